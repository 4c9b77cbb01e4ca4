// Box tree over triangles: nearest-surface and segment queries for radius limiting.
#include "geometry/triangle_bvh.hpp"
#include <algorithm>

namespace spt::detail {

Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c) {
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = va + vb + vc;
    if (!(std::abs(denom) > 0)) return a; // degenerate triangle
    return a + ab * (vb / denom) + ac * (vc / denom);
}

TriangleBvh::TriangleBvh(const TriangleMesh& mesh) : mesh_(mesh) {
    const auto n = uint32_t(mesh.triangles.size());
    order_.resize(n);
    std::vector<Eigen::Vector3d> centroids(n);
    for (uint32_t i = 0; i < n; ++i) {
        order_[i] = i;
        const auto& t = mesh.triangles[i];
        centroids[i] = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3;
    }
    nodes_.reserve(2 * n / 2 + 1);
    if (n == 0) return;
    nodes_.push_back({});
    build(0, 0, n, centroids);
}

void TriangleBvh::build(uint32_t node, uint32_t b, uint32_t e, std::vector<Eigen::Vector3d>& centroids) {
    Eigen::AlignedBox3d box, cbox;
    for (uint32_t i = b; i < e; ++i) {
        const auto& t = mesh_.triangles[order_[i]];
        for (uint32_t v : t) box.extend(mesh_.positions[v]);
        cbox.extend(centroids[order_[i]]);
    }
    nodes_[node].box = box;
    if (e - b <= 4) {
        nodes_[node].first = b, nodes_[node].count = e - b;
        return;
    }
    int axis;
    cbox.sizes().maxCoeff(&axis);
    const uint32_t mid = b + (e - b) / 2;
    std::nth_element(order_.begin() + b, order_.begin() + mid, order_.begin() + e,
                     [&](uint32_t x, uint32_t y) { return centroids[x][axis] < centroids[y][axis]; });
    const auto left = uint32_t(nodes_.size());
    nodes_.push_back({});
    build(left, b, mid, centroids);
    const auto right = uint32_t(nodes_.size());
    nodes_.push_back({});
    build(right, mid, e, centroids);
    nodes_[node].first = right, nodes_[node].count = 0;
}

template <class Reject, class Hit> bool TriangleBvh::find_triangle(Reject reject, Hit hit) const {
    if (nodes_.empty()) return false;
    uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top) {
        const uint32_t self = stack[--top];
        const Node& n = nodes_[self];
        if (reject(n.box)) continue;
        if (n.count) {
            for (uint32_t i = n.first; i < n.first + n.count; ++i)
                if (hit(mesh_.triangles[order_[i]])) return true;
            continue;
        }
        if (top + 2 > 128) continue; // cannot happen for a median tree of < 2^60 triangles
        stack[top++] = n.first;
        stack[top++] = self + 1;
    }
    return false;
}

bool TriangleBvh::any_within(const Eigen::Vector3d& p, double d2) const {
    return find_triangle([&](const Eigen::AlignedBox3d& box) { return box.squaredExteriorDistance(p) >= d2; },
                         [&](const Triangle& t) {
                             const Eigen::Vector3d q = closest_on_triangle(p, mesh_.positions[t[0]], mesh_.positions[t[1]],
                                                                           mesh_.positions[t[2]]);
                             return (q - p).squaredNorm() < d2;
                         });
}

bool TriangleBvh::segment_hits(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double skip) const {
    const Eigen::Vector3d d = b - a;
    // Slab test of the segment against each box: long segments (rays out of the mesh)
    // would overlap most boxes if only the segment's own box were compared.
    const Eigen::AlignedBox3d seg(a.cwiseMin(b), a.cwiseMax(b));
    auto misses = [&](const Eigen::AlignedBox3d& box) {
        if (!box.intersects(seg)) return true; // cheap, and enough for short segments
        double lo = 0, hi = 1;
        for (int k = 0; k < 3; ++k) {
            if (d[k] == 0) {
                if (a[k] < box.min()[k] || a[k] > box.max()[k]) return true;
                continue;
            }
            double t0 = (box.min()[k] - a[k]) / d[k], t1 = (box.max()[k] - a[k]) / d[k];
            if (t0 > t1) std::swap(t0, t1);
            lo = std::max(lo, t0), hi = std::min(hi, t1);
            if (lo > hi) return true;
        }
        return false;
    };
    return find_triangle(misses,
                         [&](const Triangle& t) {
                             // Moller-Trumbore, both faces.
                             const Eigen::Vector3d& v0 = mesh_.positions[t[0]];
                             const Eigen::Vector3d e1 = mesh_.positions[t[1]] - v0, e2 = mesh_.positions[t[2]] - v0;
                             const Eigen::Vector3d pv = d.cross(e2);
                             const double det = e1.dot(pv);
                             if (std::abs(det) < 1e-300) return false;
                             const Eigen::Vector3d tv = a - v0;
                             const double u = tv.dot(pv) / det;
                             if (u < 0 || u > 1) return false;
                             const Eigen::Vector3d qv = tv.cross(e1);
                             const double v = d.dot(qv) / det;
                             if (v < 0 || u + v > 1) return false;
                             const double s = e2.dot(qv) / det;
                             return s > skip && s <= 1;
                         });
}

} // namespace spt::detail
