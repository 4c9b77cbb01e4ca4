#pragma once
// A glTF 2.0 file read directly (.gltf with data-URI or external buffers, .glb), for what
// assimp 5.2.5 loses of it (gltf_animation.hpp). Every index, offset, length and stride is
// checked against what it points into, so a corrupt or truncated file is Error(BadInput) naming
// it and the problem, never a read out of bounds.
#include <nlohmann/json.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace spt::detail {

// True when `path` ends in .gltf or .glb, in any case.
bool is_gltf_path(const std::string& path);

// Decodes standard base64 (padding optional); nullopt at the first character that is not base64.
std::optional<std::string> decode_base64(const std::string& text, size_t begin = 0);

class GltfFile {
public:
    // Reads the JSON (and a GLB's binary chunk); buffers are read when an accessor first needs
    // them, so buffers nothing here reads (images, say) are never opened.
    explicit GltfFile(std::string path);

    // False for glTF 1.0, which is left to assimp.
    bool is_version_2() const { return version_2_; }
    const nlohmann::json& root() const { return json_; }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& what) const;

    // Member `key` of `object`, or null when `object` is not an object or lacks it.
    static const nlohmann::json* member(const nlohmann::json& object, const char* key);
    // `value` as an index or count: a non-negative integer, else fails naming `what`.
    uint64_t unsigned_value(const nlohmann::json& value, const std::string& what) const;
    // Object number `index` of the top-level array `array` ("meshes", say).
    const nlohmann::json& element(const char* array, const nlohmann::json& index, const std::string& what) const;

    // Accessor `index` as doubles, `components` per element (1 SCALAR, 2 VEC2, 3 VEC3, 4 VEC4), the
    // element count times that many. Floats always; normalized (unsigned) bytes and shorts too
    // when `normalized_ok` (rotations and weights may be stored so); sparse accessors are refused.
    std::vector<double> read_accessor(const nlohmann::json& index, int components, bool normalized_ok,
                                      const std::string& what);

private:
    const std::string& buffer(uint64_t index);
    // The JSON and BIN chunks of a GLB file; false for glTF 1.0's binary form.
    bool read_glb(const std::string& bytes);
    nlohmann::json parse_json(const std::string& text, const std::string& problem) const;

    std::string path_;
    nlohmann::json json_;
    bool version_2_ = false;
    std::optional<std::string> glb_bin_;                // a GLB's BIN chunk: buffer 0 when it has no uri
    std::vector<std::optional<std::string>> buffers_;  // each cut to its byteLength once read
};

} // namespace spt::detail

namespace spt::detail {

// Before assimp reads a glTF 2.0 file: every index the file's objects give (scene nodes, node
// children, meshes and skins, skin joints, primitive accessors, animation channels' nodes and
// samplers, sampler accessors, buffer views, textures and images) is present where assimp needs
// it and within its array; else Error(BadInput) naming the file and the JSON path. assimp 5.2.5
// dereferences some of these unchecked (an animation channel with no node crashed it).
// Files that are not glTF 2.0 pass unread.
void check_gltf_references(const std::string& path);

} // namespace spt::detail
