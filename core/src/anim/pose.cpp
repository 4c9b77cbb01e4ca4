// Posing a rig: node transforms from a clip, then morph targets and linear blend skinning.
#include "anim/keyframes.hpp"
#include "mesh/vertex_normals.hpp"
#include "spt/animation.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace spt {

size_t AnimatedMesh::find_clip(const std::string& name) const {
    for (size_t i = 0; i < clips.size(); ++i)
        if (clips[i].name == name) return i;
    // A decimal index names a clip too (a name wins: a clip may be called "1").
    if (!name.empty() && name.size() < 10 && name.find_first_not_of("0123456789") == std::string::npos) {
        const size_t i = std::stoul(name);
        if (i < clips.size()) return i;
    }
    std::string have;
    for (size_t i = 0; i < clips.size(); ++i) have += (i ? ", " : "") + std::to_string(i) + " '" + clips[i].name + "'";
    throw Error(ErrorKind::Usage, imported.mesh.name + " has no clip '" + name + "'" +
                                      (clips.empty() ? std::string(": it has no clips") : "; its clips: " + have));
}

bool may_hold_animation(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return !(ext == ".obj" || ext == ".ply" || ext == ".stl" || ext == ".off");
}

double clip_time(const Clip& clip, double t, double speed, double offset, bool loop) {
    const double c = offset + speed * t;
    if (!(clip.duration > 0) || !std::isfinite(c)) return 0;
    if (!loop) return std::clamp(c, 0.0, clip.duration);
    const double w = std::fmod(c, clip.duration);
    return w < 0 ? w + clip.duration : w;
}

std::vector<Eigen::Affine3d> pose_nodes(const Rig& rig, const Clip* clip, double time) {
    std::vector<Eigen::Affine3d> local(rig.nodes.size());
    for (size_t i = 0; i < rig.nodes.size(); ++i) local[i].matrix() = rig.nodes[i].rest_local;
    if (clip) {
        for (const NodeChannel& c : clip->nodes) {
            const RigNode& n = rig.nodes[c.node];
            const Eigen::Vector3d t = c.translation.empty() ? n.rest_translation : detail::sample_vector(c.translation, time);
            const Eigen::Quaterniond r = c.rotation.empty() ? n.rest_rotation : detail::sample_rotation(c.rotation, time);
            const Eigen::Vector3d s = c.scale.empty() ? n.rest_scale : detail::sample_vector(c.scale, time);
            Eigen::Affine3d m = Eigen::Affine3d::Identity();
            m.translate(t).rotate(r).scale(s);
            local[c.node] = m;
        }
    }
    std::vector<Eigen::Affine3d> global(rig.nodes.size());
    for (size_t i = 0; i < rig.nodes.size(); ++i) {
        const int32_t p = rig.nodes[i].parent;
        global[i] = p < 0 ? local[i] : global[size_t(p)] * local[i]; // parents come first
    }
    return global;
}

TriangleMesh posed_mesh(const AnimatedMesh& mesh, const Clip* clip, double time) {
    TriangleMesh m = mesh.imported.mesh;
    pose_vertices(mesh, clip, time, m.positions);
    const double area_eps = detail::degenerate_twice_area(mesh.imported.mesh.diagonal());
    detail::angle_weighted_normals(m.positions, m.triangles, area_eps, m.is_copy, m.normals, m.normal_valid);
    return m;
}

std::vector<TriangleMesh> clip_poses(const AnimatedMesh& mesh, double step, size_t max_per_clip, size_t max_bytes) {
    if (!(step > 0) || !std::isfinite(step)) throw Error(ErrorKind::Usage, "the step between poses must be positive");
    std::vector<TriangleMesh> poses;
    if (mesh.clips.empty()) return poses;
    // A pose's mesh, and the limiter's box tree and vertex fans over it, take about this much.
    const TriangleMesh& bind = mesh.imported.mesh;
    const size_t pose_bytes = 64 * bind.positions.size() + 48 * bind.triangles.size() + 1;
    max_per_clip = std::min(max_per_clip, max_bytes / pose_bytes / mesh.clips.size());
    for (const Clip& clip : mesh.clips) {
        // A hair under whole steps does not add a pose a rounding away from the end.
        const double whole = std::ceil(clip.duration / step - 1e-9);
        const size_t most = std::max<size_t>(max_per_clip, 2) - 1; // steps, at most
        const bool capped = !(whole <= double(most));
        const size_t steps = capped ? most : size_t(whole);
        const double dt = capped ? clip.duration / double(most) : step;
        for (size_t k = 0; k <= steps; ++k)
            poses.push_back(posed_mesh(mesh, &clip, std::min(clip.duration, double(k) * dt)));
    }
    return poses;
}

void pose_vertices(const AnimatedMesh& mesh, const Clip* clip, double time, std::vector<Eigen::Vector3d>& positions) {
    const Rig& rig = mesh.rig;
    if (rig.influences.empty()) { // nothing animates it
        positions = mesh.imported.mesh.positions;
        return;
    }
    // In place, vertex by vertex: first each mesh's own space with its morph targets (glTF:
    // targets, then the skin), then the skin. `positions` keeps its capacity from pose to pose.
    positions.assign(rig.mesh_positions.begin(), rig.mesh_positions.end());
    if (!rig.morph_targets.empty()) {
        std::vector<double> weights(rig.morph_targets.size()), sampled;
        for (size_t i = 0; i < weights.size(); ++i) weights[i] = rig.morph_targets[i].default_weight;
        if (clip)
            for (const MorphChannel& c : clip->morphs) { // each channel sampled once
                if (c.weights.empty()) continue;
                detail::sample_weights(c.weights, time, c.target_count, sampled);
                for (uint32_t k = 0; k < c.target_count; ++k) weights[c.first_target + k] = sampled[k];
            }
        for (size_t i = 0; i < weights.size(); ++i) {
            if (weights[i] == 0) continue;
            const MorphTarget& m = rig.morph_targets[i];
            for (size_t k = 0; k < m.vertices.size(); ++k) positions[m.vertices[k]] += weights[i] * m.delta[k];
        }
    }
    const std::vector<Eigen::Affine3d> nodes = pose_nodes(rig, clip, time);
    std::vector<Eigen::Affine3d> slot(rig.bone_slots.size());
    for (size_t i = 0; i < slot.size(); ++i)
        slot[i] = nodes[rig.bone_slots[i].node] * Eigen::Affine3d(rig.bone_slots[i].offset);
    for (size_t v = 0; v < positions.size(); ++v) {
        const VertexInfluences& in = rig.influences[v];
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        for (int k = 0; k < 4; ++k)
            if (in.weight[k] != 0) p += in.weight[k] * (slot[in.slot[k]] * positions[v]);
        positions[v] = rig.scale * p;
    }
}

} // namespace spt
