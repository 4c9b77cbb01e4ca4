// Four-wide box tree over triangles: the radius limiter's ball-and-segment probe.
#include "geometry/triangle_bvh.hpp"
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <utility>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace spt::detail {

Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c) {
    // In scalars, not Eigen expressions: the same operations in the same order (so the same
    // bits), but no vector temporaries and element calls for -O1 builds with the sanitizers
    // to give stack slots and checks (this function was half of a sanitized conversion).
    const double px = p[0], py = p[1], pz = p[2], ax = a[0], ay = a[1], az = a[2];
    const double bx = b[0], by = b[1], bz = b[2], cx = c[0], cy = c[1], cz = c[2];
    const double abx = bx - ax, aby = by - ay, abz = bz - az;
    const double acx = cx - ax, acy = cy - ay, acz = cz - az;
    const double apx = px - ax, apy = py - ay, apz = pz - az;
    const double d1 = abx * apx + aby * apy + abz * apz, d2 = acx * apx + acy * apy + acz * apz;
    if (d1 <= 0 && d2 <= 0) return a;
    const double bpx = px - bx, bpy = py - by, bpz = pz - bz;
    const double d3 = abx * bpx + aby * bpy + abz * bpz, d4 = acx * bpx + acy * bpy + acz * bpz;
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        return {ax + abx * v, ay + aby * v, az + abz * v};
    }
    const double cpx = px - cx, cpy = py - cy, cpz = pz - cz;
    const double d5 = abx * cpx + aby * cpy + abz * cpz, d6 = acx * cpx + acy * cpy + acz * cpz;
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        return {ax + acx * w, ay + acy * w, az + acz * w};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {bx + (cx - bx) * w, by + (cy - by) * w, bz + (cz - bz) * w};
    }
    const double denom = va + vb + vc;
    if (!(std::abs(denom) > 0)) return a; // degenerate triangle
    const double v = vb / denom, w = vc / denom;
    return {ax + abx * v + acx * w, ay + aby * v + acy * w, az + abz * v + acz * w};
}

namespace {

constexpr uint32_t kLeafSize = 4; // triangles a leaf holds at most
// The walk's stack: a node pushes at most four children and the depth stays below about 80
// (every lane holds at most three quarters of its node's triangles, plus a few near leaves).
constexpr int kStack = 512;

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

// f moved to the next float towards -inf (`towards_negative`) or +inf if `step`, else f; not for
// +0 towards -inf or -0 towards +inf. Without a branch: whether the nearest float lies past a
// value is a coin toss, and the tree's build rounds 24 values a node.
float step_if(float f, bool step, bool towards_negative) {
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    const uint32_t away = (bits >> 31) == uint32_t(towards_negative); // |f| grows, or it shrinks
    bits += uint32_t(step) * (away ? 1u : ~0u);
    std::memcpy(&f, &bits, 4);
    return f;
}

// The float at or below v (at or above for the next one), clamped to the float range without
// overflow: a float box rounded outwards contains the double one. (Exact, unlike
// detail::round_up of base/float_round.hpp, which grows a positive radius by 1e-6 relative.)
// A tiny v rounds to a zero of its own sign, which steps to the smallest float of that sign
// (the zeros step_if does not take never arise: +0 is never above a v, nor -0 below one).
float float_at_or_below(double v) {
    if (!(v > -double(FLT_MAX))) return -INFINITY; // NaN too: a box that contains everything
    if (v > double(FLT_MAX)) return FLT_MAX;
    const float f = float(v);
    return step_if(f, double(f) > v, true);
}
float float_at_or_above(double v) {
    if (!(v < double(FLT_MAX))) return INFINITY;
    if (v < -double(FLT_MAX)) return -FLT_MAX;
    const float f = float(v);
    return step_if(f, double(f) < v, false);
}

// Where a range [b, e) of sorted records (more than a leaf) is cut: within its middle half,
// where the record changes in its highest bit (the Morton code's, or the index's where the
// codes are equal). The records there share every bit above that one and are sorted, so it
// turns on exactly once: a binary search finds it. Both parts are non-empty and the depth
// stays logarithmic.
uint32_t split_point(const std::vector<uint64_t>& key, uint32_t b, uint32_t e) {
    const uint32_t len = e - b;
    const uint32_t first = std::max(b + 1, b + len / 4), last = std::min(e - 1, e - len / 4);
    const uint64_t diff = key[first - 1] ^ key[last];
    if (!diff) return b + len / 2;
    const uint64_t bit = uint64_t(1) << (63 - __builtin_clzll(diff));
    // Branch-free halving (the bit's value at the middle is a coin toss): the first record in
    // [first, last] with the bit set, which `last` has.
    const uint64_t* base = key.data() + first;
    uint32_t n = last - first + 1;
    while (n > 1) {
        const uint32_t half = n / 2;
        base = (base[half - 1] & bit) ? base : base + half;
        n -= half;
    }
    return uint32_t(base - key.data());
}

bool has_vertex(const Triangle& t, uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

} // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh) : mesh_(mesh) {
    const auto n = uint32_t(mesh.triangles.size());
    if (n == 0) return;
    const auto [lo, hi] = mesh.bounds(); // every vertex: a box around the triangles, in one pass
    const Eigen::AlignedBox3d vbox(lo, hi);
    origin_ = vbox.center();
    if (!origin_.allFinite()) origin_.setZero();
    extent_ = std::max((vbox.max() - origin_).cwiseAbs().maxCoeff(), (vbox.min() - origin_).cwiseAbs().maxCoeff());
    // Triangles in the Morton order of their centroids, then cut where that order jumps
    // furthest near the middle. A record is the code's top 32 bits over the triangle's index:
    // two radix passes of 16 bits over eight-byte records sort them (a stable sort, so the
    // records end fully sorted and equal codes keep the mesh's order).
    std::vector<uint64_t> record(n), spare(n);
    {
        // Cells of a 2^21 grid over the box, from the sum of the three corners.
        constexpr double kCells = double((1 << 21) - 1);
        const Eigen::Vector3d size = vbox.sizes(), low = 3 * vbox.min();
        Eigen::Vector3d scale;
        for (int k = 0; k < 3; ++k) scale[k] = size[k] > 0 ? kCells / (3 * size[k]) : 0.0;
        for (uint32_t i = 0; i < n; ++i) {
            const auto& t = mesh.triangles[i];
            const Eigen::Vector3d sum = mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]];
            uint64_t code = 0;
            for (int k = 0; k < 3; ++k) {
                const double cell = (sum[k] - low[k]) * scale[k];
                code |= spread_bits(uint64_t(cell > 0 ? std::min(cell, kCells) : 0.0)) << (2 - k); // NaN: 0
            }
            record[i] = (code >> 31) << 32 | i; // the code has 63 bits
        }
    }
    std::vector<uint32_t> count(65536);
    for (int shift = 32; shift < 64; shift += 16) {
        std::fill(count.begin(), count.end(), 0u);
        for (uint64_t r : record) ++count[(r >> shift) & 65535];
        if (count[(record[0] >> shift) & 65535] == n) continue; // every record has this digit
        uint32_t sum = 0;
        for (uint32_t& c : count) sum += std::exchange(c, sum);
        for (uint64_t r : record) spare[count[(r >> shift) & 65535]++] = r;
        record.swap(spare);
    }
    spare = {};
    order_.resize(n);
    for (uint32_t i = 0; i < n; ++i) order_[i] = uint32_t(record[i]);
    nodes_.reserve(n / 8 + 1);
    Eigen::AlignedBox3d box;
    build(0, n, record, box);
}

Eigen::AlignedBox3d TriangleBvh::leaf_box(uint32_t b, uint32_t e) const {
    Eigen::AlignedBox3d box;
    for (uint32_t i = b; i < e; ++i)
        for (uint32_t v : mesh_.triangles[order_[i]]) box.extend(mesh_.positions[v] - origin_);
    return box;
}

uint32_t TriangleBvh::build(uint32_t b, uint32_t e, const std::vector<uint64_t>& key, Eigen::AlignedBox3d& box) {
    const auto self = uint32_t(nodes_.size());
    nodes_.emplace_back();
    // Up to four lanes: the range, then its largest part cut again while one exceeds a leaf.
    std::array<std::pair<uint32_t, uint32_t>, 4> lane{};
    lane[0] = {b, e};
    int lanes = 1;
    while (lanes < 4) {
        int widest = -1;
        for (int k = 0; k < lanes; ++k)
            if (lane[k].second - lane[k].first > kLeafSize &&
                (widest < 0 || lane[k].second - lane[k].first > lane[widest].second - lane[widest].first))
                widest = k;
        if (widest < 0) break;
        const uint32_t cut = split_point(key, lane[widest].first, lane[widest].second);
        lane[lanes++] = {cut, lane[widest].second};
        lane[widest].second = cut;
    }
    Node node{};
    for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 4; ++k) node.lo[a][k] = INFINITY, node.hi[a][k] = -INFINITY;
    node.lanes = uint8_t(lanes);
    box.setEmpty();
    for (int k = 0; k < lanes; ++k) {
        const auto [first, last] = lane[k];
        Eigen::AlignedBox3d child;
        if (last - first <= kLeafSize) {
            child = leaf_box(first, last);
            node.child[k] = first, node.count[k] = uint8_t(last - first);
        } else {
            node.child[k] = build(first, last, key, child);
        }
        for (int a = 0; a < 3; ++a) {
            node.lo[a][k] = float_at_or_below(child.min()[a]);
            node.hi[a][k] = float_at_or_above(child.max()[a]);
        }
        box.extend(child);
    }
    nodes_[self] = node;
    return self;
}

// Which lanes of a node the probe's ball (bit k of *ball) and segment's box (*seg) meet.
// (A slab test of the segment itself culled 9% of the triangle tests and cost more than that.)
void TriangleBvh::lanes_met(const Node& n, const FloatProbe& q, int* ball, int* seg) {
#if defined(__SSE2__)
    const __m128 zero = _mm_setzero_ps();
    __m128 dist2 = zero, in_seg = _mm_castsi128_ps(_mm_set1_epi32(-1));
    for (int a = 0; a < 3; ++a) {
        const __m128 lo = _mm_loadu_ps(n.lo[a]), hi = _mm_loadu_ps(n.hi[a]), c = _mm_set1_ps(q.centre[a]);
        const __m128 d = _mm_max_ps(_mm_max_ps(_mm_sub_ps(lo, c), _mm_sub_ps(c, hi)), zero);
        dist2 = _mm_add_ps(dist2, _mm_mul_ps(d, d));
        in_seg = _mm_and_ps(in_seg, _mm_and_ps(_mm_cmple_ps(lo, _mm_set1_ps(q.seg_hi[a])),
                                               _mm_cmpge_ps(hi, _mm_set1_ps(q.seg_lo[a]))));
    }
    *ball = _mm_movemask_ps(_mm_cmple_ps(dist2, _mm_set1_ps(q.reach2)));
    *seg = _mm_movemask_ps(in_seg);
#else
    *ball = *seg = 0;
    for (int k = 0; k < 4; ++k) {
        float dist2 = 0;
        bool in_seg = true;
        for (int a = 0; a < 3; ++a) {
            const float d = std::max(std::max(n.lo[a][k] - q.centre[a], q.centre[a] - n.hi[a][k]), 0.0f);
            dist2 += d * d;
            in_seg = in_seg && n.lo[a][k] <= q.seg_hi[a] && n.hi[a][k] >= q.seg_lo[a];
        }
        *ball |= int(dist2 <= q.reach2) << k;
        *seg |= int(in_seg) << k;
    }
#endif
}

TriangleBvh::FloatProbe TriangleBvh::float_probe(const BallSegmentProbe& p) const {
    // Relative to origin_ the floats keep the precision of the mesh's own size. Every rounding
    // of the boxes' tests (and of these casts) is far below eta, by which the ball and the
    // segment's box are widened: the boxes prune only what the exact tests would reject.
    const Eigen::Vector3d c = p.centre - origin_, a = p.start - origin_, b = a + p.end * p.dir;
    const bool segment = p.end > p.skip;
    const double reach = std::sqrt(std::max(0.0, p.d2));
    const double scale = extent_ + c.cwiseAbs().maxCoeff() + reach +
                         (segment ? a.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff() : 0.0);
    const double eta = std::ldexp(scale, -18);
    const bool pruned = scale < 1e30; // beyond, or NaN: every box is met, the triangle tests decide
    FloatProbe q;
    for (int k = 0; k < 3; ++k) {
        q.centre[k] = pruned ? float(c[k]) : 0.0f;
        q.seg_lo[k] = !segment ? INFINITY : pruned ? float(std::min(a[k], b[k]) - 2 * eta) : -INFINITY;
        q.seg_hi[k] = !segment ? -INFINITY : pruned ? float(std::max(a[k], b[k]) + 2 * eta) : INFINITY;
    }
    q.reach2 = pruned ? float((reach + 2 * eta) * (reach + 2 * eta)) : INFINITY;
    return q;
}

bool TriangleBvh::touches(const BallSegmentProbe& p) const {
    if (nodes_.empty()) return false;
    const FloatProbe q = float_probe(p);
    uint32_t stack[kStack];
    int top = 0;
    stack[top++] = 0;
    while (top) {
        const Node& n = nodes_[stack[--top]];
        int ball, seg;
        lanes_met(n, q, &ball, &seg);
        for (int mask = (ball | seg) & ((1 << n.lanes) - 1); mask; mask &= mask - 1) {
            const int k = __builtin_ctz(unsigned(mask));
            if (!n.count[k]) {
                stack[top++] = n.child[k];
                continue;
            }
            const bool in_ball = ball >> k & 1, on_segment = seg >> k & 1;
            for (uint32_t i = n.child[k]; i < n.child[k] + n.count[k]; ++i) {
                if (in_ball && triangle_within(order_[i], p.centre, p.d2)) return true;
                if (on_segment && !has_vertex(mesh_.triangles[order_[i]], p.start_vertex) &&
                    triangle_crossed(order_[i], p.start, p.dir, p.skip, p.end))
                    return true;
            }
        }
    }
    return false;
}

bool TriangleBvh::triangle_within(uint32_t triangle, const Eigen::Vector3d& p, double d2) const {
    const Triangle& t = mesh_.triangles[triangle];
    const Eigen::Vector3d q = closest_on_triangle(p, mesh_.positions[t[0]], mesh_.positions[t[1]], mesh_.positions[t[2]]);
    const double x = q[0] - p[0], y = q[1] - p[1], z = q[2] - p[2];
    return x * x + y * y + z * z < d2;
}

bool TriangleBvh::triangle_crossed(uint32_t triangle, const Eigen::Vector3d& a, const Eigen::Vector3d& d, double skip,
                                   double end) const {
    // Moller-Trumbore in scalars, as closest_on_triangle, for the same reason.
    const Triangle& t = mesh_.triangles[triangle];
    const Eigen::Vector3d &v0 = mesh_.positions[t[0]], &v1 = mesh_.positions[t[1]], &v2 = mesh_.positions[t[2]];
    const double e1x = v1[0] - v0[0], e1y = v1[1] - v0[1], e1z = v1[2] - v0[2];
    const double e2x = v2[0] - v0[0], e2y = v2[1] - v0[1], e2z = v2[2] - v0[2];
    const double pvx = d[1] * e2z - d[2] * e2y, pvy = d[2] * e2x - d[0] * e2z, pvz = d[0] * e2y - d[1] * e2x;
    const double det = e1x * pvx + e1y * pvy + e1z * pvz;
    if (std::abs(det) < 1e-300) return false;
    const double tx = a[0] - v0[0], ty = a[1] - v0[1], tz = a[2] - v0[2];
    // A segment through the edge two triangles share can round just outside both: the
    // barycentric bounds are widened so that such a crossing counts (the test may only find
    // more crossings than exact arithmetic, so a radius it allows never pokes out further).
    constexpr double kEdge = 1e-9;
    const double u = (tx * pvx + ty * pvy + tz * pvz) / det;
    if (u < -kEdge || u > 1 + kEdge) return false;
    const double qx = ty * e1z - tz * e1y, qy = tz * e1x - tx * e1z, qz = tx * e1y - ty * e1x;
    const double v = (d[0] * qx + d[1] * qy + d[2] * qz) / det;
    if (v < -kEdge || u + v > 1 + kEdge) return false;
    const double s = (e2x * qx + e2y * qy + e2z * qz) / det;
    return s > skip && s <= end;
}

} // namespace spt::detail
