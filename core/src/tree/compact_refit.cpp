// A query layout following a deformed surface: spheres moved with their samples, bounds refit
// bottom up (docs/deforming.md, "Refit").
#include "spt/compact_tree.hpp"
#include "base/float_round.hpp"
#include "base/parallel.hpp"
#include "tree/spheres_below.hpp"
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
    double far2 = 0; // one square root a node: it is monotone and correctly rounded
    for (uint32_t k = n.first; k < n.first + n.count; ++k)
        far2 = std::max(far2, (sphere_center(n, k).cast<double>() - mid).squaredNorm());
    store_ball(n, mid, std::sqrt(far2) + double(n.ss_radius));
    double* box = boxes_.data() + 6 * size_t(i);
    for (int a = 0; a < 3; ++a) box[a] = lo[a], box[3 + a] = hi[a];
}

double CompactTree::farthest_below(uint32_t i, const Eigen::Vector3d& from) const {
    // Branch and bound over the subtree: a child's ball holds its spheres, so |from - c| + r
    // bounds how far they reach; the farther child is searched first.
    double best = 0;
    uint32_t stack[128];
    int top = 0;
    stack[top++] = i;
    while (top > 0) {
        const uint32_t j = stack[--top];
        const CompactNode& n = nodes_[j];
        if (n.is_active()) {
            for (uint32_t k = n.first; k < n.first + n.count; ++k)
                best = std::max(best, (sphere_center(n, k).cast<double>() - from).norm() + double(n.ss_radius));
            continue;
        }
        const uint32_t child[2] = {j + 1, n.first};
        double reach[2];
        for (int h = 0; h < 2; ++h) {
            const CompactNode& c = nodes_[child[h]];
            reach[h] = (Eigen::Vector3d(c.center[0], c.center[1], c.center[2]) - from).norm() + double(c.bv_radius);
        }
        const int first = reach[0] < reach[1] ? 0 : 1; // pushed first, searched last
        for (int h : {first, 1 - first})
            if (reach[h] > best && top < 128) stack[top++] = child[h];
            else if (reach[h] > best) return -1; // deeper than the stack: no answer (the caller keeps its ball)
    }
    return best;
}

void CompactTree::fit_inner_ball(uint32_t i, bool search_below) {
    CompactNode& n = nodes_[i];
    const CompactNode &a = nodes_[i + 1], &b = nodes_[n.first];
    const Eigen::Vector3d ca(a.center[0], a.center[1], a.center[2]), cb(b.center[0], b.center[1], b.center[2]);
    const double ra = a.bv_radius, rb = b.bv_radius, d = (cb - ca).norm();
    // The smallest ball holding the children's balls...
    Eigen::Vector3d centre = ca;
    double radius = ra;
    if (d + ra <= rb) {
        centre = cb, radius = rb;
    } else if (!(d + rb <= ra)) { // along the line through their centres
        radius = 0.5 * (d + ra + rb);
        centre = ca + ((radius - ra) / d) * (cb - ca);
    }
    // ...or, tight, the ball around the middle of the centres' box that reaches the farthest
    // sphere below (the builder's first candidate) when it is smaller, as it is at most nodes.
    // Searched only above kTightSearchFrom spheres: lower down, the children's balls have
    // gathered little slack, and searching there was most of the tight refit's time.
    if (!tight_refit_) return store_ball(n, centre, radius);
    double* box = boxes_.data() + 6 * size_t(i);
    const double *ba = boxes_.data() + 6 * size_t(i + 1), *bb = boxes_.data() + 6 * size_t(n.first);
    for (int k = 0; k < 3; ++k) box[k] = std::min(ba[k], bb[k]), box[3 + k] = std::max(ba[3 + k], bb[3 + k]);
    if (!search_below || spheres_below_[i] < kTightSearchFrom) return store_ball(n, centre, radius);
    const Eigen::Vector3d mid(0.5 * (box[0] + box[3]), 0.5 * (box[1] + box[4]), 0.5 * (box[2] + box[5]));
    const double far = farthest_below(i, mid);
    if (far >= 0 && far < radius) centre = mid, radius = far;
    store_ball(n, centre, radius);
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

void CompactTree::ensure_boxes() {
    if (boxes_.size() != 6 * nodes_.size()) boxes_.assign(6 * nodes_.size(), 0.0);
    if (spheres_below_.size() != nodes_.size()) spheres_below_ = detail::spheres_below(nodes_);
}

void CompactTree::refit_bounds(int threads, TaskSystem* tasks) {
    ensure_boxes();
    // Active nodes first (on the jobs), then inner nodes from the last back: children follow
    // their parent, so every child is fitted before its parent.
    each_active(nodes_, active_, threads, tasks, [&](uint32_t i) { fit_active_ball(i); });
    for (size_t i = nodes_.size(); i-- > 0;)
        if (!nodes_[i].is_active()) fit_inner_ball(uint32_t(i));
}

} // namespace spt
