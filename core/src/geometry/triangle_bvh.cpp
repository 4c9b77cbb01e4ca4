// Box tree over triangles: nearest-surface and segment queries for radius limiting.
#include "geometry/triangle_bvh.hpp"
#include <algorithm>
#include <array>
#include <utility>

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

namespace {

// Spreads the low 21 bits of v to every third bit.
uint64_t spread_bits(uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffull;
    v = (v | v << 16) & 0x1f0000ff0000ffull;
    v = (v | v << 8) & 0x100f00f00f00f00full;
    v = (v | v << 4) & 0x10c30c30c30c30c3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
}

// Index of the highest set bit, -1 for 0.
int highest_bit(uint64_t v) { return v ? 63 - __builtin_clzll(v) : -1; }

// Slab test: true if the segment from a along d (fraction 0 to 1) misses the box.
bool segment_misses(const Eigen::AlignedBox3d& box, const Eigen::AlignedBox3d& seg, const Eigen::Vector3d& a,
                    const Eigen::Vector3d& d) {
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
}

} // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh) : mesh_(mesh) {
    const auto n = uint32_t(mesh.triangles.size());
    if (n == 0) return;
    // Triangles in the Morton order of their centroids (a stable radix sort: deterministic),
    // then split near the middle where that order jumps furthest: one pass over the triangles
    // per level, in memory order, instead of a selection per node through an index.
    auto centroid = [&](uint32_t i) {
        const auto& t = mesh.triangles[i];
        return Eigen::Vector3d((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3);
    };
    Eigen::AlignedBox3d cbox;
    for (uint32_t i = 0; i < n; ++i) cbox.extend(centroid(i));
    const Eigen::Vector3d lo = cbox.min(), size = cbox.sizes();
    constexpr double kCells = double((1 << 21) - 1);
    std::vector<Keyed> keyed(n), spare(n);
    for (uint32_t i = 0; i < n; ++i) {
        const Eigen::Vector3d c = centroid(i);
        uint64_t key = 0;
        for (int k = 0; k < 3; ++k) {
            const double f = size[k] > 0 ? (c[k] - lo[k]) / size[k] : 0.0;
            key |= spread_bits(uint64_t(std::clamp(f, 0.0, 1.0) * kCells)) << (2 - k);
        }
        keyed[i] = {key, i};
    }
    for (int shift = 0; shift < 64; shift += 16) {
        std::vector<uint32_t> count(1 << 16, 0);
        for (const Keyed& k : keyed) ++count[(k.key >> shift) & 0xffff];
        if (count[(keyed[0].key >> shift) & 0xffff] == n) continue; // every key has this digit
        uint32_t sum = 0;
        for (uint32_t& c : count) sum += std::exchange(c, sum);
        for (const Keyed& k : keyed) spare[count[(k.key >> shift) & 0xffff]++] = k;
        keyed.swap(spare);
    }
    spare = {};
    order_.resize(n);
    for (uint32_t i = 0; i < n; ++i) order_[i] = keyed[i].triangle;
    nodes_.reserve(n / 2 + 1);
    nodes_.push_back({});
    build(0, 0, n, keyed);
}

void TriangleBvh::build(uint32_t node, uint32_t b, uint32_t e, const std::vector<Keyed>& keyed) {
    if (e - b <= 4) {
        Eigen::AlignedBox3d box;
        for (uint32_t i = b; i < e; ++i)
            for (uint32_t v : mesh_.triangles[order_[i]]) box.extend(mesh_.positions[v]);
        nodes_[node] = {box, b, e - b};
        return;
    }
    // Among the middle half of the range, the place where the Morton code changes in its
    // highest bit (nearest the middle on a tie): children stay compact and the depth stays
    // below log_{4/3} of the triangle count (find_triangle's stack).
    const uint32_t len = e - b, mid0 = b + len / 2;
    uint32_t mid = mid0;
    int best = highest_bit(keyed[mid - 1].key ^ keyed[mid].key);
    for (uint32_t i = std::max(b + 1, b + len / 4); i <= std::min(e - 1, e - len / 4); ++i) {
        const int bit = highest_bit(keyed[i - 1].key ^ keyed[i].key);
        const uint32_t dist = i > mid0 ? i - mid0 : mid0 - i, best_dist = mid > mid0 ? mid - mid0 : mid0 - mid;
        if (bit > best || (bit == best && dist < best_dist)) best = bit, mid = i;
    }
    const auto left = uint32_t(nodes_.size());
    nodes_.push_back({});
    build(left, b, mid, keyed);
    const auto right = uint32_t(nodes_.size());
    nodes_.push_back({});
    build(right, mid, e, keyed);
    nodes_[node] = {nodes_[left].box.merged(nodes_[right].box), right, 0};
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
                if (hit(order_[i])) return true;
            continue;
        }
        if (top + 2 > 128) continue; // cannot happen: the depth is below log_{4/3} of 2^32
        stack[top++] = n.first;
        stack[top++] = self + 1;
    }
    return false;
}

bool TriangleBvh::triangle_within(uint32_t triangle, const Eigen::Vector3d& p, double d2) const {
    const Triangle& t = mesh_.triangles[triangle];
    const Eigen::Vector3d q = closest_on_triangle(p, mesh_.positions[t[0]], mesh_.positions[t[1]], mesh_.positions[t[2]]);
    return (q - p).squaredNorm() < d2;
}

bool TriangleBvh::triangle_crossed(uint32_t triangle, const Eigen::Vector3d& a, const Eigen::Vector3d& d,
                                   double skip) const {
    const Triangle& t = mesh_.triangles[triangle];
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
}

bool TriangleBvh::any_within(const Eigen::Vector3d& p, double d2) const {
    return find_triangle([&](const Eigen::AlignedBox3d& box) { return box.squaredExteriorDistance(p) >= d2; },
                         [&](uint32_t t) { return triangle_within(t, p, d2); });
}

bool TriangleBvh::segment_hits(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double skip) const {
    const Eigen::Vector3d d = b - a;
    // Slab test of the segment against each box: long segments (rays out of the mesh)
    // would overlap most boxes if only the segment's own box were compared.
    const Eigen::AlignedBox3d seg(a.cwiseMin(b), a.cwiseMax(b));
    return find_triangle([&](const Eigen::AlignedBox3d& box) { return segment_misses(box, seg, a, d); },
                         [&](uint32_t t) { return triangle_crossed(t, a, d, skip); });
}

} // namespace spt::detail
