// How far the surface of a posed model lies outside its sampling spheres (ClipCoverage).
#include "spt/deforming_model.hpp"
#include "anim/keyframes.hpp"
#include "base/parallel.hpp"
#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <utility>

namespace spt {
namespace {

// Barycentric weights of the points measured on each triangle: a grid of 3 per edge, corners and
// the middle included (the gaps open between samples, mid-face as well as along edges).
std::vector<Eigen::Vector3d> probe_weights() {
    std::vector<Eigen::Vector3d> w;
    const int n = 3;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) w.emplace_back(double(n - i - j) / n, double(i) / n, double(j) / n);
    return w;
}

// Per node, its parent (the root's is itself): children follow their parent in the layout.
std::vector<uint32_t> parents(const std::vector<CompactNode>& nodes) {
    std::vector<uint32_t> parent(nodes.size(), 0);
    for (uint32_t i = 0; i < nodes.size(); ++i)
        if (!nodes[i].is_active()) parent[i + 1] = i, parent[nodes[i].first] = i;
    return parent;
}

// How far local point p lies outside every sphere of `t` (0 inside one), when that is more than
// `floor` (the largest gap so far), else some value at most `floor`: a nearest-sphere walk that
// leaves a node whose ball is no nearer than the best sphere so far, and stops once a sphere is
// nearer than the floor (most points lie on a sphere: they cannot raise the largest gap).
// `hint`: an active node to try first (none: ~0u); on return, the active node of the nearest
// sphere found. The walk starts at the hint and widens: the other child of each ancestor in
// turn, up to the root. Once at the root it has searched every subtree once, and the least gap
// is the least over every sphere whichever way it went (`parent`: parents(t.nodes())).
double gap_at(const CompactTree& t, const std::vector<uint32_t>& parent, const Eigen::Vector3f& p, double floor,
              std::vector<uint32_t>& stack, uint32_t& hint) {
    const auto& nodes = t.nodes();
    double best = INFINITY;
    uint32_t nearest = hint;
    // A leaf's spheres share one radius, and a square root is monotone and correctly rounded:
    // the nearest centre's squared distance, rooted once, gives the least gap bit for bit.
    auto leaf_gap = [&](const CompactNode& n) {
        float d2 = INFINITY;
        for (uint32_t k = n.first; k < n.first + n.count; ++k) d2 = std::min(d2, (p - t.sphere_center(n, k)).squaredNorm());
        if (const double gap = double(std::sqrt(d2)) - double(n.ss_radius); gap < best) best = gap, nearest = uint32_t(&n - nodes.data());
    };
    // A ball no nearer than the best sphere holds none nearer. Told by squares, without a root a
    // node: left only when its squared distance passes the bound's square by a margin far above
    // float rounding, so that no ball is left that a comparison of roots would keep.
    auto no_nearer = [&](const CompactNode& n) {
        const double reach = best + double(n.bv_radius);
        if (!(reach > 0)) return reach <= 0; // best is minus the radius or less: nothing below is nearer
        const Eigen::Vector3f c(n.center[0], n.center[1], n.center[2]);
        return double((p - c).squaredNorm()) >= reach * reach * (1 + 1e-5);
    };
    // The subtree at `top`, nearer child first; true once a sphere is nearer than the floor.
    auto search = [&](uint32_t top) {
        stack.assign(1, top);
        while (!stack.empty()) {
            const uint32_t i = stack.back();
            stack.pop_back();
            const CompactNode& n = nodes[i];
            if (no_nearer(n)) continue;
            if (n.is_active()) {
                leaf_gap(n);
                if (best <= floor) return true;
                continue;
            }
            const CompactNode &l = nodes[i + 1], &r = nodes[n.first];
            const float dl = (p - Eigen::Vector3f(l.center[0], l.center[1], l.center[2])).norm() - l.bv_radius;
            const float dr = (p - Eigen::Vector3f(r.center[0], r.center[1], r.center[2])).norm() - r.bv_radius;
            if (dl < dr) stack.push_back(n.first), stack.push_back(i + 1);
            else stack.push_back(i + 1), stack.push_back(n.first);
        }
        return false;
    };
    if (hint >= nodes.size()) {
        search(0);
    } else {
        leaf_gap(nodes[hint]);
        for (uint32_t below = hint; best > floor && below != 0;) {
            const uint32_t up = parent[below];
            if (search(below == up + 1 ? nodes[up].first : up + 1)) break;
            below = up;
        }
    }
    hint = nearest;
    return std::max(0.0, best);
}

} // namespace

ClipCoverage DeformingModel::measure_coverage(const Clip& clip, double frames_per_second, int threads) const {
    ClipCoverage out;
    const TriangleMesh& m = mesh_->imported.mesh;
    const std::vector<Eigen::Vector3d> weights = probe_weights();
    // Surface points: each weight on each triangle, in this order, each point once: a corner is
    // its vertex's, shared by about six triangles, and a point on an edge is its two triangles'.
    struct Point {
        Triangle t;
        Eigen::Vector3d w;
    };
    std::vector<Point> points;
    {
        std::vector<uint8_t> corner_seen(m.positions.size(), 0);
        std::unordered_set<uint64_t> edge_seen; // (lesser vertex, greater, the lesser's weight in thirds)
        for (size_t t = 0; t < m.triangles.size(); ++t) {
            if (m.copies_earlier_face(t)) continue;
            const Triangle& tri = m.triangles[t];
            for (const Eigen::Vector3d& w : weights) {
                int on[3], n = 0;
                for (int k = 0; k < 3; ++k)
                    if (w[k] > 0) on[n++] = k;
                if (n == 1) {
                    if (std::exchange(corner_seen[tri[on[0]]], 1)) continue;
                } else if (n == 2) {
                    const int lo = tri[on[0]] < tri[on[1]] ? on[0] : on[1], hi = on[0] + on[1] - lo;
                    const uint64_t key = (uint64_t(tri[lo]) << 34) | (uint64_t(tri[hi]) << 2) | uint64_t(std::lround(3 * w[lo]));
                    if (!edge_seen.insert(key).second) continue;
                }
                points.push_back({tri, w});
            }
        }
    }
    auto for_each_point = [&](auto&& f) {
        for (size_t k = 0; k < points.size(); ++k) f(k, points[k].t, points[k].w);
    };
    // Every point's gap at the bind pose, measured whole: a pose's gaps are compared with these.
    DeformingModel bind = *this;
    bind.pose(nullptr, 0);
    std::vector<double> bind_gap;
    std::vector<uint32_t> bind_nearest; // per point, the active node of its nearest sphere at bind
    const std::vector<uint32_t> parent = parents(bind.model_.tree().nodes()); // every pose's tree is this one
    std::vector<uint32_t> stack;
    uint32_t hint = ~0u;
    for_each_point([&](size_t, const Triangle& t, const Eigen::Vector3d& w) {
        const Eigen::Vector3d p = w[0] * m.positions[t[0]] + w[1] * m.positions[t[1]] + w[2] * m.positions[t[2]];
        bind_gap.push_back(gap_at(bind.model_.tree(), parent, (p - bind.model_.origin()).cast<float>(), -INFINITY, stack, hint));
        bind_nearest.push_back(hint);
        out.bind_gap = std::max(out.bind_gap, bind_gap.back());
    });
    const detail::ClipPoses poses(clip, frames_per_second, 30);
    const int frames = poses.count;
    // Per pose: the largest gap, and the largest growth of a point's gap over its bind gap; a
    // point is measured only as far as it could raise either.
    struct Result {
        double gap = 0, growth = 0;
        Eigen::Vector3d gap_at = Eigen::Vector3d::Zero(), growth_at = Eigen::Vector3d::Zero();
    };
    std::vector<Result> results(size_t(frames) + 1);
    const int jobs = std::max(1, std::min(threads, frames + 1));
    detail::parallel_for(size_t(jobs), jobs, [&](size_t job, int) {
        DeformingModel local = *this; // each job poses its own copy
        std::vector<uint32_t> walk;
        for (size_t k = job; k < results.size(); k += size_t(jobs)) {
            local.pose(&clip, poses.time(int(k)));
            Result& r = results[k];
            const Eigen::Vector3d& o = local.model_.origin();
            for_each_point([&](size_t i, const Triangle& t, const Eigen::Vector3d& w) {
                const std::vector<Eigen::Vector3d>& v = local.vertices_;
                const Eigen::Vector3d p = w[0] * v[t[0]] + w[1] * v[t[1]] + w[2] * v[t[2]];
                const double floor = std::min(r.gap, bind_gap[i] + r.growth);
                // The point's nearest sphere at bind is most often still near it.
                uint32_t hint = bind_nearest[i];
                const double g = gap_at(local.model_.tree(), parent, (p - o).cast<float>(), floor, walk, hint);
                if (g <= floor) return;
                const Eigen::Vector3d at = w[0] * m.positions[t[0]] + w[1] * m.positions[t[1]] + w[2] * m.positions[t[2]];
                if (g > r.gap) r.gap = g, r.gap_at = at;
                if (g - bind_gap[i] > r.growth) r.growth = g - bind_gap[i], r.growth_at = at;
            });
        }
    });
    for (size_t k = 0; k < results.size(); ++k) {
        const double t = poses.time(int(k));
        ++out.poses;
        if (k == 0 || results[k].gap > out.largest_gap)
            out.largest_gap = results[k].gap, out.time = t, out.where = results[k].gap_at;
        if (k == 0 || results[k].growth > out.largest_growth)
            out.largest_growth = results[k].growth, out.growth_time = t, out.growth_where = results[k].growth_at;
    }
    return out;
}

} // namespace spt
