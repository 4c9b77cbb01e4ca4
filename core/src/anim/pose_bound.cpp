// A ball around a deforming model at a pose, from its joints alone (DeformingModel::bound_at):
// what a broad phase needs to know before anything is posed.
#include "spt/deforming_model.hpp"
#include <algorithm>
#include <cmath>

namespace spt {
namespace {

// The ball holding balls a and b.
std::pair<Eigen::Vector3d, double> enclose(const std::pair<Eigen::Vector3d, double>& a,
                                           const std::pair<Eigen::Vector3d, double>& b) {
    const double d = (b.first - a.first).norm();
    if (d + b.second <= a.second) return a;
    if (d + a.second <= b.second) return b;
    const double r = 0.5 * (d + a.second + b.second);
    return {a.first + ((r - a.second) / d) * (b.first - a.first), r};
}

} // namespace

void DeformingModel::measure_joints() {
    const Rig& rig = mesh_->rig;
    slot_balls_.assign(rig.bone_slots.size(), {Eigen::Vector3d::Zero(), -1.0});
    // Per slot, the box of its vertices first, then the ball around the box's middle.
    std::vector<Eigen::Vector3d> lo(rig.bone_slots.size(), Eigen::Vector3d::Constant(INFINITY)),
        hi(rig.bone_slots.size(), Eigen::Vector3d::Constant(-INFINITY));
    for (size_t v = 0; v < rig.influences.size(); ++v)
        for (int k = 0; k < 4; ++k)
            if (rig.influences[v].weight[k] > 0) {
                const uint32_t s = rig.influences[v].slot[k];
                lo[s] = lo[s].cwiseMin(rig.mesh_positions[v]), hi[s] = hi[s].cwiseMax(rig.mesh_positions[v]);
            }
    for (size_t s = 0; s < slot_balls_.size(); ++s) {
        if (!(lo[s].x() <= hi[s].x())) continue;
        const Eigen::Vector3d c = 0.5 * (lo[s] + hi[s]);
        double r = 0;
        for (size_t v = 0; v < rig.influences.size(); ++v)
            for (int k = 0; k < 4; ++k)
                if (rig.influences[v].weight[k] > 0 && rig.influences[v].slot[k] == s)
                    r = std::max(r, (rig.mesh_positions[v] - c).norm());
        slot_balls_[s] = {c, r};
    }
    morph_reach_.clear();
    for (const MorphTarget& m : rig.morph_targets) {
        double far = 0;
        for (const Eigen::Vector3d& d : m.delta) far = std::max(far, d.norm());
        morph_reach_.push_back(far);
    }
    sphere_reach_ = 0;
    for (const CompactNode& n : model_.tree().nodes())
        if (n.is_active()) sphere_reach_ = std::max(sphere_reach_, double(n.ss_radius));
}

std::pair<Eigen::Vector3d, double> DeformingModel::bound_at(const Clip* clip, double time) const {
    const Rig& rig = mesh_->rig;
    const TriangleMesh& m = mesh_->imported.mesh;
    // A sphere's centre lies within its radius of its surface point and the sphere a radius
    // further; rounding of the float layout is covered by a millionth of the size.
    const double grow = 2 * sphere_reach_ * (1 + 1e-6) + 1e-6 * diagonal_;
    if (rig.influences.empty() || !clip) {
        Eigen::Vector3d lo = m.positions.front(), hi = lo;
        for (const Eigen::Vector3d& p : m.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
        const Eigen::Vector3d c = 0.5 * (lo + hi);
        double r = 0;
        for (const Eigen::Vector3d& p : m.positions) r = std::max(r, (p - c).norm());
        return {c, r + grow};
    }
    // Morph targets move a vertex by at most the sum of |weight| times their reach, before the skin.
    double morph = 0;
    std::vector<double> weights(rig.morph_targets.size());
    for (size_t i = 0; i < weights.size(); ++i) weights[i] = rig.morph_targets[i].default_weight;
    for (const MorphChannel& c : clip->morphs) {
        if (c.weights.empty()) continue;
        for (uint32_t k = 0; k < c.target_count; ++k) {
            double w = 0; // the largest weight of the track: a bound at any time
            for (const std::vector<double>& key : c.weights.values) w = std::max(w, std::abs(key[k]));
            for (const auto* tangents : {&c.weights.in_tangents, &c.weights.out_tangents})
                for (const std::vector<double>& key : *tangents) w = std::max(w, std::abs(key[k]));
            weights[c.first_target + k] = w;
        }
    }
    for (size_t i = 0; i < weights.size(); ++i) morph += std::abs(weights[i]) * morph_reach_[i];
    const std::vector<Eigen::Affine3d> nodes = pose_nodes(rig, clip, time);
    std::pair<Eigen::Vector3d, double> all{Eigen::Vector3d::Zero(), -1.0};
    for (size_t s = 0; s < slot_balls_.size(); ++s) {
        if (slot_balls_[s].second < 0) continue;
        const Eigen::Affine3d t = nodes[rig.bone_slots[s].node] * Eigen::Affine3d(rig.bone_slots[s].offset);
        // The linear part stretches a ball by at most its largest singular value (<= Frobenius norm).
        const double stretch = t.linear().norm();
        const std::pair<Eigen::Vector3d, double> b{rig.scale * (t * slot_balls_[s].first),
                                                   rig.scale * stretch * (slot_balls_[s].second + morph)};
        all = all.second < 0 ? b : enclose(all, b);
    }
    if (all.second < 0) return bound_at(nullptr, 0);
    return {all.first, all.second * (1 + 1e-9) + grow};
}

} // namespace spt
