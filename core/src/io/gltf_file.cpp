// Reading a glTF 2.0 file's JSON, buffers and accessors with every bound checked (gltf_file.hpp).
#include "io/gltf_file.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace spt::detail {
namespace {

using json = nlohmann::json;

constexpr uint32_t kGlbMagic = 0x46546C67; // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A, kChunkBin = 0x004E4942;

uint32_t le32(const std::string& b, size_t at) {
    uint32_t v;
    std::memcpy(&v, b.data() + at, 4); // glTF is little-endian, as every target of this build
    return v;
}

std::string lowercase(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool read_whole_file(const std::string& path, std::string& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return !in.bad();
}

// %XX escapes of a relative URI; nullopt for a broken escape.
std::optional<std::string> percent_decode(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') {
            out += uri[i];
            continue;
        }
        if (i + 2 >= uri.size() || !std::isxdigit(static_cast<unsigned char>(uri[i + 1])) ||
            !std::isxdigit(static_cast<unsigned char>(uri[i + 2])))
            return std::nullopt;
        out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
        i += 2;
    }
    return out;
}

// "scheme:" at the start of a URI (RFC 3986), which no relative file name has.
bool has_scheme(const std::string& uri) {
    const size_t colon = uri.find(':');
    if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
    return std::all_of(uri.begin(), uri.begin() + std::ptrdiff_t(colon), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
    });
}

struct ComponentType {
    size_t size = 0;
    bool is_float = false, is_signed = false;
};

ComponentType component_type(uint64_t code) {
    switch (code) {
    case 5120: return {1, false, true};   // BYTE
    case 5121: return {1, false, false};  // UNSIGNED_BYTE
    case 5122: return {2, false, true};   // SHORT
    case 5123: return {2, false, false};  // UNSIGNED_SHORT
    case 5126: return {4, true, false};   // FLOAT
    default: return {};                   // UNSIGNED_INT and unknown codes: nothing read here takes them
    }
}

// One component at `p` as glTF 2.0 (3.11) maps it: floats as they are, normalized integers to
// [0, 1] or, signed, to [-1, 1].
double component(const char* p, const ComponentType& t) {
    if (t.is_float) {
        float f;
        std::memcpy(&f, p, 4);
        return double(f);
    }
    if (t.size == 1) {
        if (t.is_signed) return std::max(double(int8_t(*p)) / 127.0, -1.0);
        return double(uint8_t(*p)) / 255.0;
    }
    if (t.is_signed) {
        int16_t s;
        std::memcpy(&s, p, 2);
        return std::max(double(s) / 32767.0, -1.0);
    }
    uint16_t u;
    std::memcpy(&u, p, 2);
    return double(u) / 65535.0;
}

const char* type_name(int components) {
    static const char* const names[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
    return components >= 1 && components <= 4 ? names[components] : "";
}

} // namespace

bool is_gltf_path(const std::string& path) {
    const std::string ext = lowercase(std::filesystem::path(path).extension().string());
    return ext == ".gltf" || ext == ".glb";
}

std::optional<std::string> decode_base64(const std::string& text, size_t begin) {
    auto sextet = [](char c) -> int {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        if (c == '+') return 62;
        if (c == '/') return 63;
        return -1;
    };
    size_t end = text.size();
    for (int pad = 0; pad < 2 && end > begin && text[end - 1] == '='; ++pad) --end;
    if ((end - begin) % 4 == 1) return std::nullopt; // 6 bits cannot end a byte
    std::string out;
    out.reserve((end - begin) / 4 * 3 + 2);
    uint32_t bits = 0;
    int held = 0;
    for (size_t i = begin; i < end; ++i) {
        const int v = sextet(text[i]);
        if (v < 0) return std::nullopt;
        bits = (bits << 6) | uint32_t(v);
        held += 6;
        if (held >= 8) {
            held -= 8;
            out += char((bits >> held) & 0xFF);
        }
    }
    return out;
}

GltfFile::GltfFile(std::string path) : path_(std::move(path)) {
    std::string bytes;
    if (!read_whole_file(path_, bytes)) fail("cannot be read");
    if (bytes.size() >= 4 && le32(bytes, 0) == kGlbMagic) {
        if (!read_glb(bytes)) return;
    } else if (lowercase(std::filesystem::path(path_).extension().string()) == ".glb") {
        fail("is not a GLB file: it does not begin with 'glTF'");
    } else {
        json_ = parse_json(bytes, "is not valid JSON");
    }
    if (!json_.is_object()) fail("is not a glTF file: its JSON is not an object");
    const json* asset = member(json_, "asset");
    const json* version = asset ? member(*asset, "version") : nullptr;
    version_2_ = version && version->is_string() && version->get<std::string>().rfind("2.", 0) == 0;
}

json GltfFile::parse_json(const std::string& text, const std::string& problem) const {
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        const std::string why = e.what(); // "[json.exception.parse_error.101] parse error at ..."
        const size_t start = why.find("] ");
        fail(problem + ": " + (start == std::string::npos ? why : why.substr(start + 2)));
    }
}

// 12-byte header ('glTF', version, total length), then chunks of (length, type, data): JSON
// first, BIN next if any; chunks of other types are skipped, as the format says.
bool GltfFile::read_glb(const std::string& bytes) {
    if (bytes.size() < 12) fail("is cut short: " + std::to_string(bytes.size()) + " bytes, fewer than a GLB header's 12");
    if (le32(bytes, 4) == 1) return false; // glTF 1.0's binary form
    if (le32(bytes, 4) != 2) fail("has GLB version " + std::to_string(le32(bytes, 4)) + ", not 2");
    const uint64_t length = le32(bytes, 8);
    if (length > bytes.size())
        fail("is cut short: its GLB header says " + std::to_string(length) + " bytes, the file has " +
             std::to_string(bytes.size()));
    uint64_t at = 12;
    for (int chunk = 0; at < length; ++chunk) {
        if (length - at < 8) fail("is cut short inside the header of GLB chunk " + std::to_string(chunk));
        const uint64_t size = le32(bytes, size_t(at)), type = le32(bytes, size_t(at) + 4);
        at += 8;
        if (size > length - at)
            fail("is cut short: GLB chunk " + std::to_string(chunk) + " has " + std::to_string(size) + " bytes, " +
                 std::to_string(length - at) + " remain");
        if (chunk == 0 && type != kChunkJson) fail("GLB chunk 0 is not JSON");
        if (chunk == 0) {
            std::string text = bytes.substr(size_t(at), size_t(size));
            while (!text.empty() && text.back() == '\0') text.pop_back(); // padding some writers use for spaces
            json_ = parse_json(text, "its GLB JSON chunk is not valid JSON");
        }
        if (chunk > 0 && type == kChunkBin && !glb_bin_) glb_bin_ = bytes.substr(size_t(at), size_t(size));
        at += size;
    }
    if (at == 12) fail("has no GLB JSON chunk");
    return true;
}

void GltfFile::fail(const std::string& what) const { throw_bad_input(path_, what); }

const json* GltfFile::member(const json& object, const char* key) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

uint64_t GltfFile::unsigned_value(const json& value, const std::string& what) const {
    if (value.is_number_unsigned()) return value.get<uint64_t>();
    if (value.is_number_integer() && value.get<int64_t>() >= 0) return uint64_t(value.get<int64_t>());
    fail(what + " is " + value.dump() + ", not a non-negative integer");
}

const json& GltfFile::element(const char* array, const json& index, const std::string& what) const {
    const uint64_t i = unsigned_value(index, what);
    const json* a = member(json_, array);
    const size_t n = a && a->is_array() ? a->size() : 0;
    if (i >= n) fail(what + " is " + std::to_string(i) + ", but the file has " + std::to_string(n) + " " + array);
    if (!(*a)[i].is_object()) fail(std::string(array) + "[" + std::to_string(i) + "] is not an object");
    return (*a)[i];
}

const std::string& GltfFile::buffer(uint64_t index) {
    const json& b = element("buffers", json(index), "a bufferView's buffer");
    if (buffers_.size() <= index) buffers_.resize(size_t(index) + 1);
    std::optional<std::string>& data = buffers_[size_t(index)];
    if (data) return *data;
    const std::string name = "buffer " + std::to_string(index);
    const json* length_value = member(b, "byteLength");
    if (!length_value) fail(name + " has no byteLength");
    const uint64_t length = unsigned_value(*length_value, name + "'s byteLength");
    const json* uri = member(b, "uri");
    if (!uri) {
        if (index != 0 || !glb_bin_) fail(name + " has no uri and is not a GLB file's binary chunk");
        data = *glb_bin_;
    } else if (!uri->is_string()) {
        fail(name + "'s uri is not a string");
    } else if (const std::string u = uri->get<std::string>(); u.rfind("data:", 0) == 0) {
        const size_t comma = u.find(',');
        const std::string head = u.substr(0, std::min(comma, u.size()));
        if (comma == std::string::npos ||
            (head != "data:application/octet-stream;base64" && head != "data:application/gltf-buffer;base64"))
            fail(name + " is a data URI of a kind not read here ('" + head.substr(0, 60) +
                 "'): only application/octet-stream and application/gltf-buffer in base64");
        data = decode_base64(u, comma + 1);
        if (!data) fail(name + "'s data URI is not valid base64");
    } else {
        const std::optional<std::string> relative = percent_decode(u);
        if (!relative || relative->empty() || has_scheme(*relative) || std::filesystem::path(*relative).is_absolute() ||
            relative->front() == '/')
            fail(name + "'s uri '" + u + "' is not a file name relative to the glTF file");
        const std::filesystem::path file = std::filesystem::path(path_).parent_path() / *relative;
        data.emplace();
        if (!read_whole_file(file.string(), *data)) fail(name + "'s file '" + file.string() + "' cannot be read");
    }
    if (data->size() < length)
        fail("is cut short: " + name + " has " + std::to_string(data->size()) + " bytes, its byteLength says " +
             std::to_string(length));
    data->resize(size_t(length));
    return *data;
}

std::vector<double> GltfFile::read_accessor(const json& index, int components, bool normalized_ok, const std::string& what) {
    const json& a = element("accessors", index, what);
    const std::string name = "accessor " + std::to_string(index.get<uint64_t>()) + " (" + what + ")";
    if (member(a, "sparse")) fail(name + " is sparse, which is not read here");
    const json* type = member(a, "type");
    if (!type || *type != type_name(components))
        fail(name + " has type " + (type ? type->dump() : std::string("(none)")) + ", not \"" + type_name(components) + "\"");
    const json* code = member(a, "componentType");
    const ComponentType ct = code ? component_type(unsigned_value(*code, name + "'s componentType")) : ComponentType{};
    const json* normalized = member(a, "normalized");
    const bool is_normalized = normalized && normalized->is_boolean() && normalized->get<bool>();
    if (ct.size == 0 || (!ct.is_float && !(normalized_ok && is_normalized)))
        fail(name + " has componentType " + (code ? code->dump() : std::string("(none)")) + (normalized_ok ? ", not float or a normalized integer" : ", not float"));
    const json* count_value = member(a, "count");
    if (!count_value) fail(name + " has no count");
    const uint64_t count = unsigned_value(*count_value, name + "'s count");
    const json* view_index = member(a, "bufferView");
    if (!view_index) fail(name + " has no bufferView");
    const json& view = element("bufferViews", *view_index, name + "'s bufferView");
    const std::string view_name = "bufferView " + std::to_string(view_index->get<uint64_t>());
    const json* buffer_index = member(view, "buffer");
    const json* view_length_value = member(view, "byteLength");
    if (!buffer_index || !view_length_value) fail(view_name + " lacks its buffer or byteLength");
    const uint64_t view_length = unsigned_value(*view_length_value, view_name + "'s byteLength");
    const json* view_offset_value = member(view, "byteOffset");
    const uint64_t view_offset = view_offset_value ? unsigned_value(*view_offset_value, view_name + "'s byteOffset") : 0;
    const std::string& data = buffer(unsigned_value(*buffer_index, view_name + "'s buffer"));
    if (view_length > data.size() || view_offset > data.size() - view_length)
        fail(view_name + " reaches past its buffer (" + std::to_string(view_offset) + " + " + std::to_string(view_length) +
             " bytes of " + std::to_string(data.size()) + ")");
    const uint64_t element_size = uint64_t(components) * ct.size;
    const json* stride_value = member(view, "byteStride");
    const uint64_t stride = stride_value ? unsigned_value(*stride_value, view_name + "'s byteStride") : element_size;
    if (stride < element_size)
        fail(view_name + "'s byteStride " + std::to_string(stride) + " is less than " + name + "'s element of " +
             std::to_string(element_size) + " bytes");
    const json* offset_value = member(a, "byteOffset");
    const uint64_t offset = offset_value ? unsigned_value(*offset_value, name + "'s byteOffset") : 0;
    // offset + (count - 1) * stride + element_size <= view_length, without overflow.
    if (count > 0 && (offset > view_length || element_size > view_length - offset ||
                      count - 1 > (view_length - offset - element_size) / stride))
        fail(name + " reaches past the end of " + view_name + " (" + std::to_string(count) + " elements of " +
             std::to_string(element_size) + " bytes, " + std::to_string(stride) + " apart, from byte " +
             std::to_string(offset) + " of " + std::to_string(view_length) + ")");
    std::vector<double> out(size_t(count) * size_t(components));
    const char* base = data.data() + view_offset + offset;
    for (size_t e = 0; e < count; ++e)
        for (int c = 0; c < components; ++c)
            out[e * size_t(components) + size_t(c)] = component(base + e * stride + size_t(c) * ct.size, ct);
    return out;
}

} // namespace spt::detail
