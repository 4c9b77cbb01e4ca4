// Far-away positions made relative before assimp reads them in float: OBJ and PLY.
#include "mesh/recentre.hpp"
#include "base/cancel.hpp"
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace spt::detail {
namespace {

bool space(char c) { return c == ' ' || c == '\t'; }

// One number of a text file: where it is and what it says.
struct Token {
    size_t begin, end;
    double value;
};

// Parses a double at text[pos...] after spaces; a leading '+' is allowed, as C's strtod does.
bool parse_number(const std::string& text, size_t& pos, size_t line_end, Token& t) {
    while (pos < line_end && space(text[pos])) ++pos;
    t.begin = pos;
    if (pos < line_end && text[pos] == '+') ++pos;
    const auto r = std::from_chars(text.data() + pos, text.data() + line_end, t.value);
    if (r.ec != std::errc() || !std::isfinite(t.value)) return false;
    pos = t.end = size_t(r.ptr - text.data());
    return pos == line_end || space(text[pos]) || text[pos] == '\r';
}

// The file with each token replaced by its value, shortest round trip; `tokens` in file order.
std::string rewrite(const std::string& text, const std::vector<Token>& tokens) {
    std::string out;
    out.reserve(text.size() + text.size() / 4);
    size_t at = 0;
    char buf[64];
    for (const Token& t : tokens) {
        out.append(text, at, t.begin - at);
        const auto r = std::to_chars(buf, buf + sizeof buf, t.value);
        out.append(buf, r.ptr);
        at = t.end;
    }
    out.append(text, at, std::string::npos);
    return out;
}

struct Box {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = Eigen::Vector3d::Constant(-INFINITY);
    void add(const Eigen::Vector3d& p) { lo = lo.cwiseMin(p), hi = hi.cwiseMax(p); }
    Eigen::Vector3d centre() const { return 0.5 * (lo + hi); }
};

// `xyz`: each vertex's x, y and z tokens in turn. When the box is far out, the file with each
// made relative to the box's centre.
std::optional<RecentredFile> finish(const std::string& text, std::vector<Token> xyz) {
    if (xyz.empty()) return std::nullopt;
    Box box;
    for (size_t k = 0; k + 2 < xyz.size(); k += 3) box.add({xyz[k].value, xyz[k + 1].value, xyz[k + 2].value});
    if (!far_for_float(box.lo, box.hi)) return std::nullopt;
    const Eigen::Vector3d origin = box.centre();
    for (size_t k = 0; k < xyz.size(); ++k) xyz[k].value -= origin[int(k % 3)];
    // A PLY record may hold x, y and z in any order: the rewrite goes through the file in order.
    std::sort(xyz.begin(), xyz.end(), [](const Token& a, const Token& b) { return a.begin < b.begin; });
    return RecentredFile{rewrite(text, xyz), origin};
}

// OBJ: every "v x y z ..." line's first three numbers (what follows them, w or a colour, stays).
std::optional<RecentredFile> recentre_obj(const std::string& text, const std::atomic<bool>* cancel,
                                          const std::string& path) {
    std::vector<Token> xyz;
    size_t lines = 0;
    for (size_t pos = 0; pos < text.size();) {
        size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        if ((++lines & 0xffff) == 0) stop_if_cancelled(cancel, "importing", path);
        size_t p = pos;
        while (p < end && space(text[p])) ++p;
        if (p + 1 < end && text[p] == 'v' && space(text[p + 1])) {
            p += 1;
            for (int k = 0; k < 3; ++k) {
                Token t;
                if (!parse_number(text, p, end, t)) return std::nullopt; // assimp reads it as it is
                xyz.push_back(t);
            }
            size_t last = end;
            while (last > p && (space(text[last - 1]) || text[last - 1] == '\r')) --last;
            if (last > p && text[last - 1] == '\\') return std::nullopt; // a line continued: not for this reader
        }
        pos = end + 1;
    }
    return finish(text, std::move(xyz));
}

// PLY's header, as far as the vertex element goes.
struct PlyHeader {
    enum class Format { Ascii, Little, Big } format = Format::Ascii;
    size_t data_begin = 0;    // first byte after end_header's line
    size_t vertex_count = 0;
    std::vector<int> sizes;   // bytes of each vertex property (binary)
    std::array<int, 3> xyz{-1, -1, -1}; // property index of x, y, z
    bool xyz_double = true;
};

int ply_type_size(const std::string& t) {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
}

// The header, if the vertex element comes first and holds only scalar properties.
std::optional<PlyHeader> ply_header(const std::string& text) {
    PlyHeader h;
    size_t pos = 0;
    int element = -1; // 0: vertex (the first), 1: any later one
    for (int line_no = 0;; ++line_no) {
        const size_t end = text.find('\n', pos);
        if (end == std::string::npos || line_no > 100000) return std::nullopt;
        std::istringstream line(text.substr(pos, end - pos));
        pos = end + 1;
        std::string word;
        line >> word;
        if (line_no == 0) {
            if (word != "ply") return std::nullopt;
            continue;
        }
        if (word == "format") {
            std::string f;
            line >> f;
            if (f == "ascii") h.format = PlyHeader::Format::Ascii;
            else if (f == "binary_little_endian") h.format = PlyHeader::Format::Little;
            else if (f == "binary_big_endian") h.format = PlyHeader::Format::Big;
            else return std::nullopt;
        } else if (word == "element") {
            std::string name;
            size_t count = 0;
            if (!(line >> name >> count)) return std::nullopt;
            if (element == -1) {
                if (name != "vertex") return std::nullopt;
                h.vertex_count = count;
                element = 0;
            } else {
                element = 1;
            }
        } else if (word == "property" && element == 0) {
            std::string type, name;
            if (!(line >> type >> name) || type == "list") return std::nullopt;
            const int size = ply_type_size(type);
            if (size == 0) return std::nullopt;
            for (int k = 0; k < 3; ++k)
                if (name == std::string(1, char('x' + k))) h.xyz[size_t(k)] = int(h.sizes.size()), h.xyz_double &= size == 8;
            h.sizes.push_back(size);
        } else if (word == "end_header") {
            h.data_begin = pos;
            break;
        }
    }
    for (int i : h.xyz)
        if (i < 0) return std::nullopt;
    return h;
}

std::optional<RecentredFile> recentre_ply_ascii(const std::string& text, const PlyHeader& h,
                                                const std::atomic<bool>* cancel, const std::string& path) {
    std::vector<Token> xyz;
    xyz.reserve(3 * std::min<size_t>(h.vertex_count, text.size() / 6));
    size_t pos = h.data_begin;
    for (size_t v = 0; v < h.vertex_count; ++v) {
        if ((v & 0xffff) == 0xffff) stop_if_cancelled(cancel, "importing", path);
        if (pos >= text.size()) return std::nullopt;
        size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        std::array<Token, 3> t{};
        size_t p = pos;
        for (size_t i = 0; i < h.sizes.size(); ++i) {
            Token tok;
            if (!parse_number(text, p, end, tok)) return std::nullopt;
            for (int k = 0; k < 3; ++k)
                if (h.xyz[size_t(k)] == int(i)) t[size_t(k)] = tok;
        }
        while (p < end && (space(text[p]) || text[p] == '\r')) ++p;
        if (p != end) return std::nullopt; // more on the line than the header says: not for this reader
        for (int k = 0; k < 3; ++k) xyz.push_back(t[size_t(k)]);
        pos = end + 1;
    }
    return finish(text, std::move(xyz));
}

double load_double(const char* p, bool big) {
    unsigned char b[8];
    std::memcpy(b, p, 8);
    if (big) std::reverse(b, b + 8);
    double v;
    std::memcpy(&v, b, 8);
    return v;
}

void store_double(char* p, double v, bool big) {
    unsigned char b[8];
    std::memcpy(b, &v, 8);
    if (big) std::reverse(b, b + 8);
    std::memcpy(p, b, 8);
}

std::optional<RecentredFile> recentre_ply_binary(std::string text, const PlyHeader& h) {
    if (!h.xyz_double) return std::nullopt; // float in the file: nothing more to keep
    const bool big = h.format == PlyHeader::Format::Big;
    size_t record = 0;
    std::array<size_t, 3> offset{};
    for (size_t i = 0; i < h.sizes.size(); ++i) {
        for (int k = 0; k < 3; ++k)
            if (h.xyz[size_t(k)] == int(i)) offset[size_t(k)] = record;
        record += size_t(h.sizes[i]);
    }
    if (h.vertex_count == 0 || h.data_begin > text.size() ||
        h.vertex_count > (text.size() - h.data_begin) / record)
        return std::nullopt; // truncated: assimp says so
    Box box;
    for (size_t v = 0; v < h.vertex_count; ++v) {
        const char* r = text.data() + h.data_begin + v * record;
        const Eigen::Vector3d p(load_double(r + offset[0], big), load_double(r + offset[1], big),
                                load_double(r + offset[2], big));
        if (!p.allFinite()) return std::nullopt;
        box.add(p);
    }
    if (!far_for_float(box.lo, box.hi)) return std::nullopt;
    const Eigen::Vector3d origin = box.centre();
    for (size_t v = 0; v < h.vertex_count; ++v) {
        char* r = text.data() + h.data_begin + v * record;
        for (int k = 0; k < 3; ++k)
            store_double(r + offset[size_t(k)], load_double(r + offset[size_t(k)], big) - origin[k], big);
    }
    return RecentredFile{std::move(text), origin};
}

std::string lower_extension(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    std::string e = dot == std::string::npos ? std::string() : path.substr(dot + 1);
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return e;
}

} // namespace

bool far_for_float(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
    if (!lo.allFinite() || !hi.allFinite()) return false;
    const double extent = (hi - lo).maxCoeff();
    const double farthest = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
    // A float's spacing at x is x * 2^-23: coarser than extent * 2^-20 beyond 8 extents. (An
    // extent of 0 far out may be a part that float rounding collapsed to a point.)
    return farthest > 0 && farthest > 8 * extent;
}

std::optional<RecentredFile> recentre_positions(const std::string& path, const std::atomic<bool>* cancel) {
    const std::string ext = lower_extension(path);
    if (ext != "obj" && ext != "ply") return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    stop_if_cancelled(cancel, "importing", path);
    if (ext == "obj") return recentre_obj(text, cancel, path);
    const std::optional<PlyHeader> h = ply_header(text);
    if (!h) return std::nullopt;
    if (h->format == PlyHeader::Format::Ascii) return recentre_ply_ascii(text, *h, cancel, path);
    return recentre_ply_binary(std::move(text), *h);
}

} // namespace spt::detail
