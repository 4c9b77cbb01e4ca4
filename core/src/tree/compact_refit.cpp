// A query layout following a deformed surface: spheres moved with their samples, bounds refit
// bottom up (docs/deforming.md, "Refit").
#include "spt/compact_tree.hpp"
#include "base/float_round.hpp"
#include "base/parallel.hpp"
#include <algorithm>
#include <cmath>

namespace spt {
namespace {

int8_t snorm8(float v) { return int8_t(detail::round_half_away(std::clamp(v, -1.0f, 1.0f) * 127.0f)); }

// A ball stored in float that holds the ball (c, r) computed in double: the centre rounded, the
// radius grown by how far rounding moved it and rounded up.
void store_ball(CompactNode& n, const Eigen::Vector3d& c, double r) {
    const Eigen::Vector3d f = detail::float_rounded(c);
    n.center[0] = float(f.x()), n.center[1] = float(f.y()), n.center[2] = float(f.z());
    n.bv_radius = detail::round_up(r + (f - c).norm());
}

// f(node index) for every active node, the nodes split evenly over `threads` jobs; `active`
// (the active nodes' indices) is filled on the first call.
template <class F>
void each_active(const std::vector<CompactNode>& nodes, std::vector<uint32_t>& active, int threads, TaskSystem* tasks,
                 F&& f) {
    if (active.empty())
        for (uint32_t i = 0; i < nodes.size(); ++i)
            if (nodes[i].is_active()) active.push_back(i);
    const size_t jobs = size_t(std::max(threads, 1));
    detail::parallel_for(jobs, int(jobs), [&](size_t job, int) {
        for (size_t a = active.size() * job / jobs; a < active.size() * (job + 1) / jobs; ++a) f(active[a]);
    }, tasks);
}

} // namespace

void CompactTree::place_spheres(uint32_t i, const Eigen::Vector3f* points, const Eigen::Vector3f* normals) {
    const CompactNode& n = nodes_[i];
    float* block = centers_.data() + 3 * size_t(n.first);
    for (uint32_t k = 0; k < n.count; ++k) {
        const uint32_t sphere = n.first + k, s = sample_index_[sphere];
        const bool flat = !two_sided_.empty() && two_sided_[sphere];
        const Eigen::Vector3f c = flat ? points[s] : Eigen::Vector3f(points[s] - n.ss_radius * normals[s]);
        block[k] = c.x(), block[n.count + k] = c.y(), block[2 * n.count + k] = c.z();
        nx_[sphere] = snorm8(normals[s].x()), ny_[sphere] = snorm8(normals[s].y()), nz_[sphere] = snorm8(normals[s].z());
    }
}

void CompactTree::fit_active_ball(uint32_t i) {
    CompactNode& n = nodes_[i];
    Eigen::Vector3d lo = sphere_center(n, n.first).cast<double>(), hi = lo;
    for (uint32_t k = n.first + 1; k < n.first + n.count; ++k) {
        const Eigen::Vector3d c = sphere_center(n, k).cast<double>();
        lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
    }
    const Eigen::Vector3d mid = 0.5 * (lo + hi);
    double far = 0;
    for (uint32_t k = n.first; k < n.first + n.count; ++k)
        far = std::max(far, (sphere_center(n, k).cast<double>() - mid).norm());
    store_ball(n, mid, far + double(n.ss_radius));
}

void CompactTree::fit_inner_ball(uint32_t i) {
    CompactNode& n = nodes_[i];
    const CompactNode &a = nodes_[i + 1], &b = nodes_[n.first];
    const Eigen::Vector3d ca(a.center[0], a.center[1], a.center[2]), cb(b.center[0], b.center[1], b.center[2]);
    const double ra = a.bv_radius, rb = b.bv_radius, d = (cb - ca).norm();
    if (d + rb <= ra) {
        store_ball(n, ca, ra);
    } else if (d + ra <= rb) {
        store_ball(n, cb, rb);
    } else { // the smallest ball holding both: along the line through their centres
        const double r = 0.5 * (d + ra + rb);
        store_ball(n, ca + ((r - ra) / d) * (cb - ca), r);
    }
}

void CompactTree::set_ball(uint32_t i, const Eigen::Vector3d& center, double radius) {
    store_ball(nodes_[i], center, radius);
}

void CompactTree::follow_samples(const std::vector<Eigen::Vector3f>& points, const std::vector<Eigen::Vector3f>& normals,
                                 int threads, TaskSystem* tasks) {
    each_active(nodes_, active_, threads, tasks, [&](uint32_t i) { place_spheres(i, points.data(), normals.data()); });
    refit_bounds(threads, tasks);
    if (!two_sided_.empty()) build_node_discs();
}

void CompactTree::refit_bounds(int threads, TaskSystem* tasks) {
    // Active nodes first (on the jobs), then inner nodes from the last back: children follow
    // their parent, so every child is fitted before its parent.
    each_active(nodes_, active_, threads, tasks, [&](uint32_t i) { fit_active_ball(i); });
    for (size_t i = nodes_.size(); i-- > 0;)
        if (!nodes_[i].is_active()) fit_inner_ball(uint32_t(i));
}

} // namespace spt
