// Reading a file's skins, morph targets and animations through assimp (spt/animation.hpp).
// The mesh itself comes from import_mesh; the rig is read from the same assimp scene in the same
// vertex order (nodes depth first, each node's meshes in turn), so welded_index maps it. For
// glTF 2.0 files the clips and skin weights are then read from the file too (gltf_animation.hpp).
#include "anim/gltf_animation.hpp"
#include "anim/rig_import.hpp"
#include "spt/error.hpp"
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>

namespace spt {
namespace {

// assimp's ticks-per-second when a file does not say (its viewers assume this too).
constexpr double kDefaultTicksPerSecond = 25;

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
    Eigen::Matrix4d e;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) e(r, c) = double(m[r][c]);
    return e;
}

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The vertices of one mesh as one node holds it: where the raw vertices begin, and the morph
// targets made for it (a mesh held by two nodes is two instances, as import_mesh reads it).
struct MeshInstance {
    uint32_t node = 0, mesh = 0;
    uint32_t first_raw = 0;
    uint32_t first_target = 0, target_count = 0;
};

struct Reader {
    const aiScene* scene;
    const std::string& path;
    Rig rig;
    std::vector<std::string> warnings;
    std::unordered_map<std::string, uint32_t> node_by_name; // the first node of each name
    std::unordered_map<const aiNode*, uint32_t> node_by_pointer; // every node read so far
    std::vector<MeshInstance> instances;
    std::vector<Eigen::Vector3d> raw_local;     // per raw vertex, its mesh's space
    std::vector<VertexInfluences> raw_influence; // per raw vertex
    std::vector<std::vector<std::pair<uint32_t, Eigen::Vector3d>>> raw_deltas; // per target: raw vertex, offset
    size_t trimmed = 0; // vertices that had more than 4 joints

    [[noreturn]] void fail(const std::string& what) const { throw_bad_input(path, what); }

    std::string mesh_name(uint32_t m) const {
        const aiString& n = scene->mMeshes[m]->mName;
        return n.length ? "'" + std::string(n.C_Str()) + "'" : "number " + std::to_string(m);
    }

    // assimp 5.2.5's Half-Life MDL reader lists every bone as a child of one `<MDL_bones>` node
    // but sets each bone's mParent to its parent bone, whose transform its own is relative to
    // (the vertices are bound with the chained transforms). So a node whose mParent is a node
    // read before it hangs from that one, which keeps parents before their children.
    void read_nodes(const aiNode* n, int32_t parent, int depth) {
        if (depth > 1000) return; // a cyclic or absurd node graph, as import_mesh stops too
        const uint32_t index = uint32_t(rig.nodes.size());
        RigNode r;
        r.name = n->mName.C_Str();
        const auto declared = n->mParent ? node_by_pointer.find(n->mParent) : node_by_pointer.end();
        r.parent = declared != node_by_pointer.end() ? int32_t(declared->second) : parent;
        r.rest_local = to_eigen(n->mTransformation);
        const Eigen::Affine3d a(r.rest_local);
        Eigen::Matrix3d rotation, scaling;
        a.computeRotationScaling(&rotation, &scaling);
        r.rest_translation = a.translation();
        r.rest_rotation = Eigen::Quaterniond(rotation).normalized();
        r.rest_scale = scaling.diagonal();
        rig.nodes.push_back(std::move(r));
        node_by_name.emplace(rig.nodes.back().name, index);
        node_by_pointer.emplace(n, index);
        for (unsigned i = 0; i < n->mNumMeshes; ++i)
            if (n->mMeshes[i] < scene->mNumMeshes) instances.push_back({index, n->mMeshes[i], 0, 0, 0});
        for (unsigned c = 0; c < n->mNumChildren; ++c) read_nodes(n->mChildren[c], int32_t(index), depth + 1);
    }

    // The rig's nodes are in depth-first order, but import_mesh visits meshes depth first too, so
    // instances collected on the way down are already in its vertex order.
    void read_instance(MeshInstance& in) {
        const aiMesh* m = scene->mMeshes[in.mesh];
        in.first_raw = uint32_t(raw_local.size());
        std::vector<std::vector<std::pair<uint32_t, double>>> joints(m->mNumVertices);
        if (m->HasBones()) {
            rig.skinned = true;
            for (unsigned b = 0; b < m->mNumBones; ++b) {
                const aiBone* bone = m->mBones[b];
                const auto it = node_by_name.find(bone->mName.C_Str());
                if (it == node_by_name.end())
                    fail("joint '" + std::string(bone->mName.C_Str()) + "' of mesh " + mesh_name(in.mesh) +
                         " names no node of the file");
                const Eigen::Matrix4d offset = to_eigen(bone->mOffsetMatrix);
                if (!offset.allFinite())
                    fail("the inverse bind matrix of joint '" + std::string(bone->mName.C_Str()) + "' is not finite");
                const uint32_t slot = uint32_t(rig.bone_slots.size());
                rig.bone_slots.push_back({it->second, offset});
                for (unsigned k = 0; k < bone->mNumWeights; ++k) {
                    const aiVertexWeight& w = bone->mWeights[k];
                    if (w.mVertexId >= m->mNumVertices) continue;
                    if (!std::isfinite(w.mWeight) || w.mWeight < 0)
                        fail("vertex " + std::to_string(w.mVertexId) + " of mesh " + mesh_name(in.mesh) +
                             " has a joint weight that is " + (std::isfinite(w.mWeight) ? "negative" : "not a number"));
                    if (w.mWeight > 0) joints[w.mVertexId].push_back({slot, double(w.mWeight)});
                }
            }
        } else {
            const uint32_t slot = uint32_t(rig.bone_slots.size());
            rig.bone_slots.push_back({in.node, Eigen::Matrix4d::Identity()}); // hangs rigidly from its node
            for (auto& j : joints) j.push_back({slot, 1.0});
        }
        for (unsigned v = 0; v < m->mNumVertices; ++v) {
            auto& j = joints[v];
            if (j.size() > 4) {
                ++trimmed;
                std::partial_sort(j.begin(), j.begin() + 4, j.end(),
                                  [](const auto& x, const auto& y) { return x.second > y.second; });
                j.resize(4);
            }
            double sum = 0;
            for (const auto& [slot, w] : j) sum += w;
            if (!(sum > 0))
                fail("vertex " + std::to_string(v) + " of mesh " + mesh_name(in.mesh) +
                     " has joint weights that sum to 0 (it follows no joint)");
            VertexInfluences influence;
            for (size_t k = 0; k < j.size(); ++k) influence.slot[k] = j[k].first, influence.weight[k] = j[k].second / sum;
            raw_influence.push_back(influence);
            raw_local.emplace_back(double(m->mVertices[v].x), double(m->mVertices[v].y), double(m->mVertices[v].z));
        }
        in.first_target = uint32_t(rig.morph_targets.size());
        for (unsigned t = 0; t < m->mNumAnimMeshes; ++t) {
            const aiAnimMesh* am = m->mAnimMeshes[t];
            MorphTarget target;
            target.name = am->mName.length ? am->mName.C_Str() : "target " + std::to_string(t);
            target.default_weight = std::isfinite(am->mWeight) ? double(am->mWeight) : 0.0;
            std::vector<std::pair<uint32_t, Eigen::Vector3d>> deltas;
            if (am->mVertices && am->mNumVertices == m->mNumVertices) {
                for (unsigned v = 0; v < m->mNumVertices; ++v) {
                    if (!finite(am->mVertices[v]))
                        fail("morph target " + std::to_string(t) + " of mesh " + mesh_name(in.mesh) +
                             " has a position that is not a number");
                    const aiVector3D d = am->mVertices[v] - m->mVertices[v]; // assimp keeps whole positions
                    if (d.x != 0 || d.y != 0 || d.z != 0)
                        deltas.push_back({in.first_raw + v, Eigen::Vector3d(double(d.x), double(d.y), double(d.z))});
                }
            }
            rig.morph_targets.push_back(std::move(target));
            raw_deltas.push_back(std::move(deltas));
        }
        in.target_count = uint32_t(rig.morph_targets.size()) - in.first_target;
    }

    // Seconds of each key; false unless finite and never decreasing.
    template <class Key>
    void key_times(const Key* keys, unsigned n, double tps, std::vector<double>& out, const std::string& what) const {
        out.resize(n);
        for (unsigned k = 0; k < n; ++k) {
            out[k] = keys[k].mTime / tps;
            if (!std::isfinite(out[k])) fail(what + ": key " + std::to_string(k) + " has a time that is not a number");
            if (k > 0 && out[k] < out[k - 1])
                fail(what + ": keys out of order (key " + std::to_string(k) + " at " + std::to_string(out[k]) +
                     " s comes after one at " + std::to_string(out[k - 1]) + " s)");
        }
    }

    Clip read_clip(const aiAnimation* a, size_t index) const {
        Clip clip;
        clip.name = a->mName.length ? a->mName.C_Str() : "clip " + std::to_string(index);
        const double tps = a->mTicksPerSecond > 0 ? a->mTicksPerSecond : kDefaultTicksPerSecond;
        const std::string where = "clip '" + clip.name + "'";
        double last = 0;
        std::vector<uint8_t> counted(rig.nodes.size(), 0);
        for (unsigned c = 0; c < a->mNumChannels; ++c) {
            const aiNodeAnim* ch = a->mChannels[c];
            const auto it = node_by_name.find(ch->mNodeName.C_Str());
            if (it == node_by_name.end()) continue; // animates nothing that is drawn
            NodeChannel nc;
            nc.node = it->second;
            const std::string what = where + ", node '" + std::string(ch->mNodeName.C_Str()) + "'";
            key_times(ch->mPositionKeys, ch->mNumPositionKeys, tps, nc.translation.times, what + " translation");
            for (unsigned k = 0; k < ch->mNumPositionKeys; ++k) {
                const aiVector3D& v = ch->mPositionKeys[k].mValue;
                if (!finite(v)) fail(what + " translation: key " + std::to_string(k) + " is not a number");
                nc.translation.values.emplace_back(double(v.x), double(v.y), double(v.z));
            }
            key_times(ch->mScalingKeys, ch->mNumScalingKeys, tps, nc.scale.times, what + " scale");
            for (unsigned k = 0; k < ch->mNumScalingKeys; ++k) {
                const aiVector3D& v = ch->mScalingKeys[k].mValue;
                if (!finite(v)) fail(what + " scale: key " + std::to_string(k) + " is not a number");
                nc.scale.values.emplace_back(double(v.x), double(v.y), double(v.z));
            }
            key_times(ch->mRotationKeys, ch->mNumRotationKeys, tps, nc.rotation.times, what + " rotation");
            for (unsigned k = 0; k < ch->mNumRotationKeys; ++k) {
                const aiQuaternion& q = ch->mRotationKeys[k].mValue;
                const Eigen::Vector4d v(double(q.x), double(q.y), double(q.z), double(q.w));
                if (!v.allFinite() || !(v.norm() > 0))
                    fail(what + " rotation: key " + std::to_string(k) + " is not a rotation");
                nc.rotation.values.push_back(v);
            }
            for (const auto* t : {&nc.translation.times, &nc.rotation.times, &nc.scale.times})
                if (!t->empty()) last = std::max(last, t->back());
            if (rig.joint_nodes[nc.node] && !counted[nc.node]) ++clip.joints_animated, counted[nc.node] = 1;
            clip.nodes.push_back(std::move(nc));
        }
        for (unsigned c = 0; c < a->mNumMorphMeshChannels; ++c) {
            const aiMeshMorphAnim* ch = a->mMorphMeshChannels[c];
            const std::string name = ch->mName.C_Str();
            // glTF names the channel after the node holding the mesh; other formats after the mesh.
            const MeshInstance* in = nullptr;
            for (const MeshInstance& i : instances)
                if (i.target_count && (rig.nodes[i.node].name == name || scene->mMeshes[i.mesh]->mName.C_Str() == name)) {
                    in = &i;
                    break;
                }
            if (!in) continue;
            MorphChannel mc;
            mc.first_target = in->first_target, mc.target_count = in->target_count;
            const std::string what = where + ", morph weights of '" + name + "'";
            key_times(ch->mKeys, ch->mNumKeys, tps, mc.weights.times, what);
            for (unsigned k = 0; k < ch->mNumKeys; ++k) {
                const aiMeshMorphKey& key = ch->mKeys[k];
                std::vector<double> w(in->target_count, 0.0);
                for (unsigned i = 0; i < key.mNumValuesAndWeights; ++i) {
                    if (!std::isfinite(key.mWeights[i]))
                        fail(what + ": key " + std::to_string(k) + " has a weight that is not a number");
                    if (key.mValues[i] < in->target_count) w[key.mValues[i]] = key.mWeights[i];
                }
                mc.weights.values.push_back(std::move(w));
            }
            if (!mc.weights.times.empty()) last = std::max(last, mc.weights.times.back());
            clip.morphs.push_back(std::move(mc));
        }
        clip.duration = last;
        return clip;
    }
};

} // namespace

} // namespace spt

namespace spt::detail {

void read_assimp_rig(const std::string& path, AnimatedMesh& out, std::vector<MorphMesh>& morphs) {
    Assimp::Importer importer;
    // The flags import_mesh reads with, so that vertices come in the same order.
    const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_ValidateDataStructure);
    if (!scene || !scene->mRootNode) throw_bad_input(path, "cannot be read again for its animation");
    Reader r{scene, path, {}, {}, {}, {}, {}, {}, {}, {}, 0};
    r.read_nodes(scene->mRootNode, -1, 0);
    for (MeshInstance& in : r.instances) r.read_instance(in);
    const std::vector<uint32_t>& welded = out.imported.mesh.welded_index;
    if (welded.size() != r.raw_local.size())
        throw_bad_input(path, "its animation does not match its mesh (" + std::to_string(r.raw_local.size()) +
                                  " vertices against " + std::to_string(welded.size()) + ")");
    Rig& rig = r.rig;
    rig.joint_nodes.assign(rig.nodes.size(), 0);
    if (rig.skinned)
        for (const MeshInstance& in : r.instances)
            if (scene->mMeshes[in.mesh]->HasBones())
                for (size_t v = in.first_raw; v < in.first_raw + scene->mMeshes[in.mesh]->mNumVertices; ++v)
                    for (int k = 0; k < 4; ++k)
                        if (r.raw_influence[v].weight[k] > 0) rig.joint_nodes[rig.bone_slots[r.raw_influence[v].slot[k]].node] = 1;
    rig.joint_count = size_t(std::count(rig.joint_nodes.begin(), rig.joint_nodes.end(), 1));
    const bool animated = rig.skinned || scene->mNumAnimations > 0 || !rig.morph_targets.empty();
    if (animated) {
        // Each welded vertex follows the first file vertex welded into it.
        const size_t n = out.imported.mesh.positions.size();
        std::vector<int64_t> first(n, -1);
        for (size_t v = 0; v < welded.size(); ++v)
            if (first[welded[v]] < 0) first[welded[v]] = int64_t(v);
        rig.mesh_positions.resize(n, Eigen::Vector3d::Zero());
        rig.influences.resize(n);
        for (size_t w = 0; w < n; ++w) {
            if (first[w] < 0) continue;
            rig.mesh_positions[w] = r.raw_local[size_t(first[w])];
            rig.influences[w] = r.raw_influence[size_t(first[w])];
        }
        for (size_t t = 0; t < rig.morph_targets.size(); ++t)
            for (const auto& [raw, d] : r.raw_deltas[t])
                if (first[welded[raw]] == int64_t(raw)) {
                    rig.morph_targets[t].vertices.push_back(welded[raw]);
                    rig.morph_targets[t].delta.push_back(d);
                }
        for (unsigned a = 0; a < scene->mNumAnimations; ++a) out.clips.push_back(r.read_clip(scene->mAnimations[a], a));
    }
    if (r.trimmed)
        out.imported.report.warnings.push_back(std::to_string(r.trimmed) +
                                               " file vertices had more than 4 joints: each keeps its 4 heaviest, renormalised");
    out.rig = std::move(rig);
    morphs.clear();
    for (const MeshInstance& in : r.instances)
        if (in.target_count) morphs.push_back({in.node, in.first_target, in.target_count});
}

} // namespace spt::detail

namespace spt {

AnimatedMesh import_animated_mesh(const std::string& path, const ImportOptions& options) {
    AnimatedMesh out;
    out.imported = import_mesh(path, options); // the checks of a mesh file, and the welded mesh
    std::optional<detail::GltfFile> gltf;
    if (detail::is_gltf_path(path)) gltf.emplace(path);
    if (gltf && !gltf->is_version_2()) gltf.reset(); // glTF 1.0: assimp's reading only
    // Before assimp's reading of the weights, which has lost the 0s and NaNs.
    if (gltf) detail::check_gltf_skin_weights(*gltf);
    std::vector<detail::MorphMesh> morphs;
    detail::read_assimp_rig(path, out, morphs);
    if (gltf && !out.rig.influences.empty()) detail::apply_gltf_animation(*gltf, out.rig, morphs, out.clips);
    return out;
}

} // namespace spt
