// The .spt codec. Layout and rules: docs/spt-format.md.
#include "spt/spt_file.hpp"
#include "io/binary_io.hpp"
#include "io/recipe_codec.hpp"
#include "io/motion_codec.hpp"
#include "base/parallel.hpp"
#include "sampling/encoding.hpp"
#include <algorithm>
#include <zlib.h>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <set>
#include <unistd.h>

namespace spt {
namespace {

constexpr char kMagic[8] = {'S', 'P', 'T', 'R', 'E', 'E', 0x1A, 0x0A};
constexpr size_t kHeaderSize = 32;
constexpr size_t kSampleBytes = 24;
constexpr size_t kNodeBytes = 32;
constexpr uint32_t kActiveBit = 0x80000000u;
constexpr uint32_t kMaxName = 4096;

uint32_t crc(const uint8_t* p, size_t n) {
    uLong c = crc32(0L, Z_NULL, 0);
    while (n > 0) { // zlib takes uInt lengths
        const uInt chunk = uInt(std::min<size_t>(n, 1u << 30));
        c = crc32(c, p, chunk);
        p += chunk, n -= chunk;
    }
    return uint32_t(c);
}

} // namespace

const SamplingTree* SptDocument::tree(const std::string& name) const {
    for (const auto& t : trees)
        if (t.name() == name) return &t;
    return nullptr;
}

std::string SptDocument::validate() const {
    std::set<std::string> names;
    for (const auto& t : trees) {
        if (t.name().empty()) return "a tree has an empty name";
        if (!names.insert(t.name()).second) return "two trees are named '" + t.name() + "'";
        const std::string why = t.validate(uint32_t(samples.size()));
        if (!why.empty()) return "tree '" + t.name() + "': " + why;
    }
    return {};
}

uint32_t spt_version_for(const SptDocument& doc) {
    uint32_t version = doc.samples.origin.isZero(0) ? 1 : 2;
    for (const auto& t : doc.trees) {
        version = std::max(version, detail::recipe_version(t.recipe()));
        if (!t.motion_builds().empty()) version = std::max(version, detail::kMotionBuildsVersion);
    }
    return version;
}

std::vector<uint8_t> encode_spt(const SptDocument& doc) {
    const uint32_t version = spt_version_for(doc);
    detail::Writer w;
    // The whole file but recipes and strings' slack, reserved: no copies of a growing buffer.
    constexpr size_t kSampleBytes = 3 * 4 + 4 + 4 + 2 + 2, kNodeBytes = 8 + 3 * 4 + 4 + 4 + 4;
    size_t expected = kHeaderSize + 256 + doc.mesh.name.size() + doc.samples.size() * kSampleBytes;
    for (const auto& t : doc.trees)
        expected += 64 + t.name().size() + t.node_count() * kNodeBytes + doc.samples.size() * 4;
    w.reserve(expected);
    const uint8_t header[kHeaderSize] = {}; // filled in below
    w.put_bytes(header, kHeaderSize);
    w.put_string(doc.mesh.name);
    w.put(doc.mesh.vertex_count);
    w.put(doc.mesh.triangle_count);
    w.put(doc.mesh.hash);
    w.put(doc.mesh.diagonal);
    const SampleSet& s = doc.samples;
    if (version >= 2) w.put(s.origin.x()), w.put(s.origin.y()), w.put(s.origin.z());
    w.put(uint32_t(s.size()));
    for (size_t i = 0; i < s.size(); ++i) {
        w.put(s.points[i].x()), w.put(s.points[i].y()), w.put(s.points[i].z());
        w.put(encode_normal(s.normals[i]));
        w.put(s.sources[i]);
        w.put(encode_length(s.spacing[i], false));
        w.put(encode_length(s.max_radius[i], true));
    }
    w.put(uint32_t(doc.trees.size()));
    for (const auto& tree : doc.trees) {
        w.put_string(tree.name());
        const auto nodes = tree.nodes();
        w.put(uint32_t(nodes.size()));
        uint32_t total = 0;
        for (const TreeNode* n : nodes) {
            w.put(n->id);
            w.put(n->center.x()), w.put(n->center.y()), w.put(n->center.z());
            w.put(n->bv_radius), w.put(n->ss_radius);
            w.put(uint32_t(n->samples.size()) | (n->active ? kActiveBit : 0));
            total += uint32_t(n->samples.size());
        }
        w.put(total);
        for (const TreeNode* n : nodes)
            for (uint32_t idx : n->samples) w.put(idx);
        if (version >= 3) detail::put_recipe(w, tree.recipe(), version);
        if (version >= detail::kMotionBuildsVersion) detail::put_motion_builds(w, tree.motion_builds());
    }
    std::vector<uint8_t> b = w.take();
    std::memcpy(b.data(), kMagic, 8);
    const uint32_t flags = 0;
    const uint64_t length = b.size();
    const uint32_t body_crc = crc(b.data() + kHeaderSize, b.size() - kHeaderSize);
    std::memcpy(b.data() + 8, &version, 4);
    std::memcpy(b.data() + 12, &flags, 4);
    std::memcpy(b.data() + 16, &length, 8);
    std::memcpy(b.data() + 24, &body_crc, 4);
    const uint32_t header_crc = crc(b.data(), 28);
    std::memcpy(b.data() + 28, &header_crc, 4);
    return b;
}

SptDocument decode_spt(const std::vector<uint8_t>& bytes, const std::string& path) {
    detail::Reader r(bytes, path);
    if (bytes.size() < kHeaderSize)
        r.fail(0, "file is " + std::to_string(bytes.size()) + " bytes, shorter than the 32-byte header (not an .spt file?)");
    if (std::memcmp(bytes.data(), kMagic, 8) != 0) r.fail(0, "not an .spt file (bad magic)");
    uint32_t version, flags, body_crc, header_crc;
    uint64_t length;
    std::memcpy(&version, bytes.data() + 8, 4);
    std::memcpy(&flags, bytes.data() + 12, 4);
    std::memcpy(&length, bytes.data() + 16, 8);
    std::memcpy(&body_crc, bytes.data() + 24, 4);
    std::memcpy(&header_crc, bytes.data() + 28, 4);
    if (crc(bytes.data(), 28) != header_crc) r.fail(28, "header checksum mismatch (corrupt header)");
    if (version < 1 || version > kSptVersion)
        r.fail(8, "format version " + std::to_string(version) + " is not supported (this build reads versions 1 to " +
                      std::to_string(kSptVersion) + ")");
    if (flags != 0) r.fail(12, "unknown flags " + std::to_string(flags));
    if (length != bytes.size())
        r.fail(16, "header says " + std::to_string(length) + " bytes but the file has " + std::to_string(bytes.size()) +
                       (length > bytes.size() ? " (truncated)" : " (trailing data)"));
    if (crc(bytes.data() + kHeaderSize, bytes.size() - kHeaderSize) != body_crc)
        r.fail(24, "checksum mismatch: the file is corrupt");
    r.get<std::array<uint8_t, kHeaderSize>>("header");

    // The checksum guards against accidents; everything below is still checked, so a
    // hand-made hostile file cannot make the loader misbehave.
    SptDocument doc;
    doc.mesh.name = r.get_string("mesh name", kMaxName);
    doc.mesh.vertex_count = r.get<uint32_t>("vertex count");
    doc.mesh.triangle_count = r.get<uint32_t>("triangle count");
    doc.mesh.hash = r.get<uint64_t>("mesh hash");
    size_t at = r.offset();
    doc.mesh.diagonal = r.get<double>("mesh diagonal");
    if (!std::isfinite(doc.mesh.diagonal) || doc.mesh.diagonal < 0) r.fail(at, "mesh diagonal is not a finite length");
    SampleSet& s = doc.samples;
    if (version >= 2) {
        at = r.offset();
        const double ox = r.get<double>("local origin"), oy = r.get<double>("local origin"), oz = r.get<double>("local origin");
        s.origin = {ox, oy, oz};
        if (!s.origin.allFinite()) r.fail(at, "local origin is not finite");
        if (version == 2 && s.origin.isZero(0))
            r.fail(at, "a version 2 file with a zero local origin (written as version 1)");
    }

    at = r.offset();
    const auto count = r.get<uint32_t>("sample count");
    r.need(uint64_t(count) * kSampleBytes, std::to_string(count) + " samples");
    s.points.resize(count), s.normals.resize(count), s.sources.resize(count);
    s.spacing.resize(count), s.max_radius.resize(count);
    for (uint32_t i = 0; i < count; ++i) {
        at = r.offset();
        const float x = r.get<float>("sample"), y = r.get<float>("sample"), z = r.get<float>("sample");
        s.points[i] = {x, y, z};
        if (!s.points[i].allFinite()) r.fail(at, "sample " + std::to_string(i) + " has a non-finite position");
        s.normals[i] = decode_normal(r.get<uint32_t>("sample normal"));
        at = r.offset();
        s.sources[i] = r.get<uint32_t>("sample source");
        const bool face = s.sources[i] & kFaceSampleBit;
        const uint32_t src = s.sources[i] & kMaxSourceIndex; // bit 30: two-sided (open part)
        if (src >= (face ? doc.mesh.triangle_count : doc.mesh.vertex_count))
            r.fail(at, "sample " + std::to_string(i) + " refers to " + (face ? "triangle " : "vertex ") + std::to_string(src) +
                           " beyond the mesh");
        at = r.offset();
        s.spacing[i] = decode_length(r.get<uint16_t>("sample spacing"));
        s.max_radius[i] = decode_length(r.get<uint16_t>("sample radius limit"));
        if (!std::isfinite(s.spacing[i]) || s.spacing[i] < 0 || std::isnan(s.max_radius[i]) || s.max_radius[i] < 0)
            r.fail(at, "sample " + std::to_string(i) + " has an invalid spacing or radius limit");
    }

    const auto tree_count = r.get<uint32_t>("tree count");
    // Each tree takes at least 12 bytes: a bound that stops absurd counts before any allocation.
    r.need(uint64_t(tree_count) * 12, std::to_string(tree_count) + " trees");
    for (uint32_t t = 0; t < tree_count; ++t) {
        at = r.offset();
        std::string name = r.get_string("tree name", kMaxName);
        if (name.empty()) r.fail(at, "tree " + std::to_string(t) + " has an empty name");
        if (doc.tree(name)) r.fail(at, "two trees are named '" + name + "'");
        const size_t tree_at = at;
        const auto node_count = r.get<uint32_t>("node count");
        r.need(uint64_t(node_count) * kNodeBytes, std::to_string(node_count) + " nodes");
        std::vector<TreeNode> nodes(node_count);
        uint64_t expected = 0;
        NodeId last = 0;
        for (uint32_t k = 0; k < node_count; ++k) {
            at = r.offset();
            TreeNode& n = nodes[k];
            n.id = r.get<uint64_t>("node id");
            if (n.id <= last) r.fail(at, "node ids must be increasing and non-zero (id " + std::to_string(n.id) + ")");
            last = n.id;
            const float cx = r.get<float>("node"), cy = r.get<float>("node"), cz = r.get<float>("node");
            n.center = {cx, cy, cz};
            n.bv_radius = r.get<float>("node");
            n.ss_radius = r.get<float>("node");
            const auto packed = r.get<uint32_t>("node");
            n.active = packed & kActiveBit;
            const uint32_t members = packed & ~kActiveBit;
            if (!n.active && members) r.fail(at, "inactive node " + std::to_string(n.id) + " claims samples");
            expected += members;
            // Indices follow the nodes: a claim larger than what is left of the file is a lie.
            if (expected * 4 > r.remaining())
                r.fail(at, "node " + std::to_string(n.id) + " claims more samples than the file holds");
            nodes[k].samples.resize(members);
        }
        at = r.offset();
        const auto total = r.get<uint32_t>("index count");
        if (total != expected)
            r.fail(at, "index count " + std::to_string(total) + " differs from the nodes' sum " + std::to_string(expected));
        r.need(uint64_t(total) * 4, std::to_string(total) + " sample indices");
        for (auto& n : nodes)
            for (auto& idx : n.samples) idx = r.get<uint32_t>("sample index");
        SamplingTree tree(std::move(name), std::move(nodes));
        const std::string why = tree.validate(count);
        if (!why.empty()) r.fail(tree_at, "tree '" + tree.name() + "': " + why);
        if (version >= 3) tree.set_recipe(detail::get_recipe(r, tree, version));
        if (version >= detail::kMotionBuildsVersion) tree.set_motion_builds(detail::get_motion_builds(r, tree));
        doc.trees.push_back(std::move(tree));
    }
    // Each document has one encoding: the oldest version that holds it.
    if (version >= 3 && spt_version_for(doc) != version)
        r.fail(8, version == detail::kMotionBuildsVersion
                      ? "a version 6 file without a build from motion (written as version 5 or older)"
                      : detail::recipe_version_mismatch(version));
    if (r.remaining() != 0) r.fail(r.offset(), std::to_string(r.remaining()) + " bytes of unexpected trailing data");
    return doc;
}

void save_spt(const SptDocument& doc, const std::string& path) {
    // The check and the encoding only read the document (the encoding writes the values as
    // they are, whatever the tree's shape): on two threads they run at once.
    std::string why;
    std::vector<uint8_t> bytes;
    detail::parallel_for(2, detail::machine_threads(), [&](size_t k, int) {
        if (k == 0) why = doc.validate();
        else bytes = encode_spt(doc);
    });
    if (!why.empty()) throw Error(ErrorKind::BadInput, path + ": refusing to save an invalid document: " + why);
    auto cannot = [&](const std::string& what) {
        throw Error(ErrorKind::CannotWrite, path + ": cannot write: " + what + ": " + std::strerror(errno));
    };
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) cannot("create " + tmp);
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int e = errno;
            ::close(fd), ::unlink(tmp.c_str());
            errno = e;
            cannot("write");
        }
        done += size_t(n);
    }
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        const int e = errno;
        ::unlink(tmp.c_str());
        errno = e;
        cannot("flush");
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int e = errno;
        ::unlink(tmp.c_str());
        errno = e;
        cannot("rename into place");
    }
}

bool is_spt_file(const std::string& path) {
    // The first six bytes only: a file that starts like one but is damaged after them is an
    // .spt file that load_spt then names the damage of, not a mesh for the importer.
    char magic[6] = {};
    std::ifstream(path, std::ios::binary).read(magic, sizeof magic);
    return std::memcmp(magic, kMagic, sizeof magic) == 0;
}

SptDocument load_spt(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw_bad_input(path, "no such file");
    if (std::filesystem::is_directory(path, ec)) throw_bad_input(path, "is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw_bad_input(path, "cannot be opened for reading");
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw_bad_input(path, "cannot read its size");
    std::vector<uint8_t> bytes(size);
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size));
    if (!in) throw_bad_input(path, "read failed");
    return decode_spt(bytes, path);
}

std::string check_mesh_matches(const MeshInfo& info, const TriangleMesh& mesh) {
    if (info.vertex_count != mesh.positions.size())
        return "the tree was made from a mesh with " + std::to_string(info.vertex_count) + " vertices, this one has " +
               std::to_string(mesh.positions.size());
    if (info.triangle_count != mesh.triangles.size())
        return "the tree was made from a mesh with " + std::to_string(info.triangle_count) + " triangles, this one has " +
               std::to_string(mesh.triangles.size());
    if (info.hash != mesh.content_hash()) return "the mesh's content differs from the one the tree was made from";
    return {};
}

} // namespace spt
