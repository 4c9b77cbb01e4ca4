// Index references of a glTF 2.0 file checked before assimp follows them (gltf_file.hpp).
#include "io/gltf_file.hpp"
#include "spt/error.hpp"
#include <string>

namespace spt::detail {
namespace {

using nlohmann::json;

struct Checker {
    const GltfFile& file;
    const json& root;

    size_t count(const char* array) const {
        const json* a = GltfFile::member(root, array);
        return a && a->is_array() ? a->size() : 0;
    }
    [[noreturn]] void fail(const std::string& where, const std::string& what) const { file.fail(where + ": " + what); }
    // `value` is an index into the top-level `array`.
    void index(const json& value, const char* array, const std::string& where) const {
        if (!value.is_number_integer() || value.get<int64_t>() < 0 || uint64_t(value.get<int64_t>()) >= count(array))
            fail(where, "is not an index into '" + std::string(array) + "' (" + std::to_string(count(array)) + " of them)");
    }
    // Member `key` of `object`, or null; `required`: it must be there.
    const json* member(const json& object, const char* key, const std::string& where, bool required) const {
        const json* v = GltfFile::member(object, key);
        if (!v && required) fail(where, "has no '" + std::string(key) + "'");
        return v;
    }
    // Member `key` of `object`, if present, is an index into `array`; `required`: it must be present.
    void member_index(const json& object, const char* key, const char* array, const std::string& where,
                      bool required = false) const {
        if (const json* v = member(object, key, where, required)) index(*v, array, where + "/" + key);
    }
    // Member `key` of `object`, if present, is an array of indices into `array`.
    void member_indices(const json& object, const char* key, const char* array, const std::string& where,
                        bool required = false) const {
        const json* v = member(object, key, where, required);
        if (!v) return;
        if (!v->is_array()) fail(where + "/" + key, "is not an array");
        for (size_t i = 0; i < v->size(); ++i) index((*v)[i], array, where + "/" + key + "/" + std::to_string(i));
    }
    // Every object of the top-level `array`, with its path.
    template <class F>
    void each(const char* array, F&& f) const {
        const json* a = GltfFile::member(root, array);
        if (!a) return;
        if (!a->is_array()) fail(std::string("/") + array, "is not an array");
        for (size_t i = 0; i < a->size(); ++i) {
            const std::string where = std::string("/") + array + "/" + std::to_string(i);
            if (!(*a)[i].is_object()) fail(where, "is not an object");
            f((*a)[i], where);
        }
    }
    // The values of an object of accessor indices (a primitive's attributes or a morph target).
    void accessor_map(const json& object, const std::string& where) const {
        if (!object.is_object()) fail(where, "is not an object");
        for (auto it = object.begin(); it != object.end(); ++it) index(it.value(), "accessors", where + "/" + it.key());
    }

    void run() const {
        member_index(root, "scene", "scenes", "");
        each("scenes", [&](const json& s, const std::string& w) { member_indices(s, "nodes", "nodes", w); });
        each("nodes", [&](const json& n, const std::string& w) {
            member_indices(n, "children", "nodes", w);
            member_index(n, "mesh", "meshes", w);
            member_index(n, "skin", "skins", w);
            member_index(n, "camera", "cameras", w);
        });
        each("skins", [&](const json& s, const std::string& w) {
            member_indices(s, "joints", "nodes", w, true);
            member_index(s, "inverseBindMatrices", "accessors", w);
            member_index(s, "skeleton", "nodes", w);
        });
        each("meshes", [&](const json& m, const std::string& w) {
            const json* prims = GltfFile::member(m, "primitives");
            if (!prims || !prims->is_array()) fail(w, "has no array of 'primitives'");
            for (size_t i = 0; i < prims->size(); ++i) {
                const json& p = (*prims)[i];
                const std::string pw = w + "/primitives/" + std::to_string(i);
                const json* attributes = GltfFile::member(p, "attributes");
                if (!attributes) fail(pw, "has no 'attributes'");
                accessor_map(*attributes, pw + "/attributes");
                member_index(p, "indices", "accessors", pw);
                member_index(p, "material", "materials", pw);
                if (const json* targets = GltfFile::member(p, "targets")) {
                    if (!targets->is_array()) fail(pw + "/targets", "is not an array");
                    for (size_t t = 0; t < targets->size(); ++t)
                        accessor_map((*targets)[t], pw + "/targets/" + std::to_string(t));
                }
            }
        });
        each("accessors", [&](const json& a, const std::string& w) { member_index(a, "bufferView", "bufferViews", w); });
        each("bufferViews", [&](const json& v, const std::string& w) { member_index(v, "buffer", "buffers", w, true); });
        each("images", [&](const json& i, const std::string& w) { member_index(i, "bufferView", "bufferViews", w); });
        each("textures", [&](const json& t, const std::string& w) {
            member_index(t, "source", "images", w);
            member_index(t, "sampler", "samplers", w);
        });
        each("animations", [&](const json& a, const std::string& w) {
            const json* samplers = GltfFile::member(a, "samplers");
            const size_t n = samplers && samplers->is_array() ? samplers->size() : 0;
            for (size_t i = 0; i < n; ++i) {
                const std::string sw = w + "/samplers/" + std::to_string(i);
                member_index((*samplers)[i], "input", "accessors", sw, true);
                member_index((*samplers)[i], "output", "accessors", sw, true);
            }
            const json* channels = GltfFile::member(a, "channels");
            if (!channels || !channels->is_array()) fail(w, "has no array of 'channels'");
            for (size_t i = 0; i < channels->size(); ++i) {
                const json& c = (*channels)[i];
                const std::string cw = w + "/channels/" + std::to_string(i);
                const json* s = GltfFile::member(c, "sampler");
                if (!s || !s->is_number_integer() || s->get<int64_t>() < 0 || uint64_t(s->get<int64_t>()) >= n)
                    fail(cw + "/sampler", "is not an index into the animation's " + std::to_string(n) + " samplers");
                const json* target = GltfFile::member(c, "target");
                if (!target) fail(cw, "has no 'target'");
                // The node may be left to an extension, but assimp follows it unchecked.
                member_index(*target, "node", "nodes", cw + "/target", true);
            }
        });
    }
};

} // namespace

void check_gltf_references(const std::string& path) {
    if (!is_gltf_path(path)) return;
    const GltfFile file(path);
    if (!file.is_version_2()) return;
    Checker{file, file.root()}.run();
}

} // namespace spt::detail
