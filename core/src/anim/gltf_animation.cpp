// A glTF 2.0 file's animation samplers turned into clips (gltf_animation.hpp).
#include "anim/gltf_animation.hpp"
#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace spt::detail {
namespace {

using json = nlohmann::json;

// One sampler's keys: `width` numbers per value (3 translation or scale, 4 rotation, the target
// count for weights); with CUBICSPLINE each key holds three values (in-tangent, value, out-tangent).
struct Keys {
    Interpolation how = Interpolation::Linear;
    std::vector<double> times;
    std::vector<double> values;
    size_t width = 0;
    size_t per_key() const { return how == Interpolation::CubicSpline ? 3 : 1; }
    const double* at(size_t key, size_t part) const { return values.data() + (key * per_key() + part) * width; }
};

template <class Value, class Make>
void fill(Track<Value>& track, const Keys& keys, Make make) {
    track = Track<Value>();
    track.interpolation = keys.how;
    track.times = keys.times;
    const bool cubic = keys.how == Interpolation::CubicSpline;
    for (size_t k = 0; k < keys.times.size(); ++k) {
        track.values.push_back(make(keys.at(k, cubic ? 1 : 0)));
        if (!cubic) continue;
        track.in_tangents.push_back(make(keys.at(k, 0)));
        track.out_tangents.push_back(make(keys.at(k, 2)));
    }
}

class ClipReader {
public:
    ClipReader(GltfFile& file, const Rig& rig, const std::vector<MorphMesh>& morphs) : file_(file), rig_(rig), morphs_(morphs) {
        for (uint32_t i = 0; i < rig.nodes.size(); ++i) node_by_name_.emplace(rig.nodes[i].name, i); // the first of each name
    }

    Clip read(const json& animation, size_t index) {
        Clip clip;
        const json* name = GltfFile::member(animation, "name");
        clip.name = name && name->is_string() && !name->get<std::string>().empty() ? name->get<std::string>()
                                                                                     : "clip " + std::to_string(index);
        const std::string where = "clip '" + clip.name + "'";
        const json* channels = GltfFile::member(animation, "channels");
        const json* samplers = GltfFile::member(animation, "samplers");
        if (!channels || !channels->is_array() || !samplers || !samplers->is_array())
            file_.fail(where + " lacks its channels or samplers");
        std::unordered_map<uint32_t, size_t> channel_of; // rig node -> index in clip.nodes
        for (const json& channel : *channels) {
            const json* target = GltfFile::member(channel, "target");
            const json* node = target ? GltfFile::member(*target, "node") : nullptr;
            const json* path = target ? GltfFile::member(*target, "path") : nullptr;
            if (!node || !path) continue; // a channel for an extension to fill in
            const std::string node_name = gltf_node_name(*node, where);
            const auto rig_node = node_by_name_.find(node_name);
            if (rig_node == node_by_name_.end()) continue; // animates nothing that is drawn
            const json* sampler_index = GltfFile::member(channel, "sampler");
            if (!sampler_index) file_.fail(where + ", node '" + node_name + "': a channel has no sampler");
            const uint64_t s = file_.unsigned_value(*sampler_index, where + "'s sampler index");
            if (s >= samplers->size())
                file_.fail(where + ", node '" + node_name + "': sampler " + std::to_string(s) + " of " +
                           std::to_string(samplers->size()));
            const json& sampler = (*samplers)[size_t(s)];
            const std::string what = where + ", node '" + node_name + "' " + (path->is_string() ? path->get<std::string>() : "");
            if (*path == "weights") {
                read_weights(clip, *node, rig_node->second, sampler, what);
                continue;
            }
            if (*path != "translation" && *path != "rotation" && *path != "scale") continue; // not glTF 2.0's
            if (!channel_of.count(rig_node->second)) {
                channel_of[rig_node->second] = clip.nodes.size();
                clip.nodes.emplace_back().node = rig_node->second;
            }
            NodeChannel& nc = clip.nodes[channel_of[rig_node->second]];
            auto vec3 = [](const double* p) { return Eigen::Vector3d(p[0], p[1], p[2]); };
            if (*path == "rotation")
                fill(nc.rotation, keys(sampler, 4, 4, true, what), [](const double* p) { return Eigen::Vector4d(p[0], p[1], p[2], p[3]); });
            else
                fill(*path == "translation" ? nc.translation : nc.scale, keys(sampler, 3, 3, false, what), vec3);
        }
        double last = 0;
        std::vector<uint8_t> counted(rig_.nodes.size(), 0);
        for (const NodeChannel& nc : clip.nodes) {
            for (const auto* t : {&nc.translation.times, &nc.rotation.times, &nc.scale.times})
                if (!t->empty()) last = std::max(last, t->back());
            if (nc.node < rig_.joint_nodes.size() && rig_.joint_nodes[nc.node] && !counted[nc.node])
                ++clip.joints_animated, counted[nc.node] = 1;
        }
        for (const MorphChannel& mc : clip.morphs)
            if (!mc.weights.empty()) last = std::max(last, mc.weights.times.back());
        clip.duration = last;
        return clip;
    }

private:
    // The name assimp gives glTF node `index`: its own, or "nodes[index]" when it has none.
    std::string gltf_node_name(const json& index, const std::string& where) const {
        const json& node = file_.element("nodes", index, where + ": a channel's node");
        const json* name = GltfFile::member(node, "name");
        if (name && name->is_string() && !name->get<std::string>().empty()) return name->get<std::string>();
        return "nodes[" + std::to_string(index.get<uint64_t>()) + "]";
    }

    // The sampler's keys, `width` numbers per value stored as elements of `components` (weights
    // are scalars), checked: times finite and never decreasing, values numbers (a rotation's
    // value not zero), as many as the keys need.
    Keys keys(const json& sampler, int components, size_t width, bool normalized_ok, const std::string& what) {
        Keys k;
        k.width = width;
        if (const json* how = GltfFile::member(sampler, "interpolation")) {
            if (*how == "STEP") k.how = Interpolation::Step;
            else if (*how == "CUBICSPLINE") k.how = Interpolation::CubicSpline;
            else if (*how != "LINEAR") file_.fail(what + ": interpolation " + how->dump() + " is not LINEAR, STEP or CUBICSPLINE");
        }
        const json* input = GltfFile::member(sampler, "input");
        const json* output = GltfFile::member(sampler, "output");
        if (!input || !output) file_.fail(what + ": its sampler lacks its input or output");
        k.times = file_.read_accessor(*input, 1, false, what + " key times");
        for (size_t i = 0; i < k.times.size(); ++i) {
            if (!std::isfinite(k.times[i])) file_.fail(what + ": key " + std::to_string(i) + " has a time that is not a number");
            if (i > 0 && k.times[i] < k.times[i - 1])
                file_.fail(what + ": keys out of order (key " + std::to_string(i) + " at " + std::to_string(k.times[i]) +
                           " s comes after one at " + std::to_string(k.times[i - 1]) + " s)");
        }
        k.values = file_.read_accessor(*output, components, normalized_ok, what + " key values");
        const size_t expected = k.times.size() * k.per_key() * width;
        if (k.values.size() != expected)
            file_.fail(what + ": " + std::to_string(k.times.size()) + " keys need " + std::to_string(expected / components) +
                       " output values, the sampler has " + std::to_string(k.values.size() / components));
        for (size_t i = 0; i < k.times.size(); ++i)
            for (size_t part = 0; part < k.per_key(); ++part) {
                const double* v = k.at(i, part);
                if (!std::all_of(v, v + width, [](double x) { return std::isfinite(x); }))
                    file_.fail(what + ": key " + std::to_string(i) + " is not a number");
                const bool value = part == (k.per_key() == 3 ? 1u : 0u);
                if (value && width == 4 && !(std::abs(v[0]) + std::abs(v[1]) + std::abs(v[2]) + std::abs(v[3]) > 0))
                    file_.fail(what + ": key " + std::to_string(i) + " is not a rotation");
            }
        return k;
    }

    // A weights channel drives the targets of every mesh its node holds: as many weights a key as
    // the node's glTF mesh has targets, those beyond a mesh's own left out.
    void read_weights(Clip& clip, const json& node_index, uint32_t rig_node, const json& sampler, const std::string& what) {
        const json& node = file_.element("nodes", node_index, what);
        const json* mesh_index = GltfFile::member(node, "mesh");
        if (!mesh_index) return;
        const json& mesh = file_.element("meshes", *mesh_index, what + ": its node's mesh");
        const json* primitives = GltfFile::member(mesh, "primitives");
        const json* targets = primitives && primitives->is_array() && !primitives->empty()
                                  ? GltfFile::member((*primitives)[0], "targets") : nullptr;
        const size_t count = targets && targets->is_array() ? targets->size() : 0;
        if (count == 0) return;
        const Keys k = keys(sampler, 1, count, true, what);
        for (const MorphMesh& m : morphs_) {
            if (m.node != rig_node || m.target_count == 0) continue;
            MorphChannel mc;
            mc.first_target = m.first_target, mc.target_count = m.target_count;
            fill(mc.weights, k, [&](const double* p) {
                std::vector<double> w(m.target_count, 0.0);
                std::copy(p, p + std::min<size_t>(count, m.target_count), w.begin());
                return w;
            });
            clip.morphs.push_back(std::move(mc));
        }
    }

    GltfFile& file_;
    const Rig& rig_;
    const std::vector<MorphMesh>& morphs_;
    std::unordered_map<std::string, uint32_t> node_by_name_;
};

// The weights of one primitive (WEIGHTS_0, WEIGHTS_1, ...) checked vertex by vertex: every
// value first, so that a NaN is named even after a vertex of zero weights.
void check_primitive_weights(GltfFile& file, const json& attributes, const std::string& mesh) {
    std::vector<double> sum;
    for (int set = 0;; ++set) {
        const std::string key = "WEIGHTS_" + std::to_string(set);
        const json* accessor = GltfFile::member(attributes, key.c_str());
        if (!accessor) break;
        const std::vector<double> w = file.read_accessor(*accessor, 4, true, mesh + " " + key);
        const size_t vertices = w.size() / 4;
        if (set == 0) sum.assign(vertices, 0.0);
        if (vertices != sum.size())
            file.fail(mesh + ": " + key + " has " + std::to_string(vertices) + " vertices, WEIGHTS_0 " + std::to_string(sum.size()));
        for (size_t v = 0; v < vertices; ++v)
            for (size_t c = 0; c < 4; ++c) {
                const double x = w[4 * v + c];
                if (!(x >= 0) || std::isinf(x))
                    file.fail("vertex " + std::to_string(v) + " of " + mesh + " has a joint weight (" + key + " component " +
                              std::to_string(c) + ") that is " +
                              (std::isnan(x) ? "not a number" : std::isinf(x) ? "infinite" : "negative: " + std::to_string(x)));
                sum[v] += x;
            }
    }
    for (size_t v = 0; v < sum.size(); ++v)
        if (!(sum[v] > 0))
            file.fail("vertex " + std::to_string(v) + " of " + mesh + " has joint weights that sum to 0 (it follows no joint)");
}

} // namespace

void check_gltf_skin_weights(GltfFile& file) {
    const json* nodes = GltfFile::member(file.root(), "nodes");
    if (!nodes || !nodes->is_array()) return;
    std::vector<uint64_t> meshes; // held by a skinned node: other meshes' weights skin nothing
    for (const json& node : *nodes)
        if (GltfFile::member(node, "skin") && GltfFile::member(node, "mesh"))
            meshes.push_back(file.unsigned_value(node["mesh"], "a node's mesh"));
    std::sort(meshes.begin(), meshes.end());
    meshes.erase(std::unique(meshes.begin(), meshes.end()), meshes.end());
    for (const uint64_t m : meshes) {
        const json& mesh = file.element("meshes", json(m), "a skinned node's mesh");
        const json* name = GltfFile::member(mesh, "name");
        const std::string mesh_name = name && name->is_string() ? "mesh '" + name->get<std::string>() + "'" : "mesh " + std::to_string(m);
        const json* primitives = GltfFile::member(mesh, "primitives");
        if (!primitives || !primitives->is_array()) continue;
        for (size_t p = 0; p < primitives->size(); ++p) {
            const json* attributes = GltfFile::member((*primitives)[p], "attributes");
            const json* extensions = GltfFile::member((*primitives)[p], "extensions");
            // Draco-compressed attributes are not in the buffers; without JOINTS_0 nothing is skinned.
            if (!attributes || !GltfFile::member(*attributes, "JOINTS_0") ||
                (extensions && GltfFile::member(*extensions, "KHR_draco_mesh_compression")))
                continue;
            const std::string where = primitives->size() > 1 ? "primitive " + std::to_string(p) + " of " + mesh_name : mesh_name;
            check_primitive_weights(file, *attributes, where);
        }
    }
}

void apply_gltf_animation(GltfFile& file, const Rig& rig, const std::vector<MorphMesh>& morphs, std::vector<Clip>& clips) {
    const json* animations = GltfFile::member(file.root(), "animations");
    std::vector<Clip> out;
    if (animations && animations->is_array()) {
        ClipReader reader(file, rig, morphs);
        for (size_t a = 0; a < animations->size(); ++a) out.push_back(reader.read((*animations)[a], a));
    }
    clips = std::move(out);
}

} // namespace spt::detail
