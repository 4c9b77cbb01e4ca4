// The bottom of the sphere walk: B's leaf spheres moved into A's frame, a leaf pair's
// sphere tests, and the recording of what collides.
#include "query/lanes.hpp"
#include "geometry/sample_disc.hpp"
#include "geometry/sphere_block.hpp"
#include <algorithm>
#include <cmath>
#include <cstring>

namespace spt {

using detail::b_to_a;
using detail::movemask;
using detail::splat;
using detail::v4f;

Eigen::Vector3f QueryRun::b_node_centre(uint32_t j) const {
    const CompactNode& n = B.tree().nodes()[j];
    return f.R * Eigen::Vector3f(n.center[0], n.center[1], n.center[2]) + f.t;
}

void QueryRun::move_leaf(uint32_t j, float* x, float* y, float* z) const {
    const CompactNode& n = B.tree().nodes()[j];
    const float* c = B.tree().centers(n);
    const float *bx = c, *by = c + n.count, *bz = c + 2 * n.count;
    // Four spheres at a time; the last group reads past the block into the next one (or
    // the array's padding) and writes up to 3 floats past count, which callers allow.
    for (uint32_t k = 0; k < n.count; k += 4) {
        v4f px, py, pz;
        std::memcpy(&px, bx + k, sizeof px), std::memcpy(&py, by + k, sizeof py), std::memcpy(&pz, bz + k, sizeof pz);
        b_to_a(f, px, py, pz);
        std::memcpy(x + k, &px, sizeof px), std::memcpy(y + k, &py, sizeof py), std::memcpy(z + k, &pz, sizeof pz);
    }
}

void QueryRun::record(uint32_t node_a, uint32_t node_b, uint32_t a, uint32_t b, const Eigen::Vector3f& ca,
                      const Eigen::Vector3f& cb, float reach, float ra, float d2) {
    if (exit) {
        exit_pair(node_a, node_b, a, b, ca, cb, reach);
        return;
    }
    if (o.mode == QueryMode::All) {
        keep_pair(node_a, node_b, a, b, reach, d2);
        return;
    }
    const float dist = std::sqrt(d2);
    const float depth = reach - dist;
    if (have_best && !(depth > res.deepest.depth)) return;
    have_best = true;
    s.deepest_node_a = node_a, s.deepest_node_b = node_b;
    Contact& c = res.deepest;
    c.depth = depth;
    c.a = a, c.b = b;
    const Eigen::Vector3d d = (cb - ca).cast<double>();
    c.normal = dist > 0 ? Eigen::Vector3d(d / d.norm()) : Eigen::Vector3d::UnitX();
    c.point = A.origin() + ca.cast<double>() + c.normal * (double(ra) - 0.5 * depth);
}

void QueryRun::keep_exit_root(uint32_t node_a, uint32_t node_b, uint32_t a, uint32_t b, float reach) {
    const bool bounds = o.level == QueryLevel::Bounds;
    const Eigen::Vector3d w = f.Rd * detail::pair_centre(B.tree(), bounds, node_b, b) + f.td -
                              detail::pair_centre(A.tree(), bounds, node_a, a);
    detail::keep_exit(*exit, detail::exit_root(w, double(reach), exit->back), double(reach));
}

bool QueryRun::shapes_touch(uint32_t sa, uint32_t sb, const Eigen::Vector3f& ca, const Eigen::Vector3f& cb, float ra,
                            float rb) {
    const uint8_t *two_a = A.tree().two_sided(), *two_b = B.tree().two_sided();
    if (!(two_a && two_a[sa]) && !(two_b && two_b[sb])) return true;
    // A normal that is not a direction (a snorm8 triple of zeros; never written by conversion)
    // leaves its sphere a ball.
    auto normal = [](const CompactTree& t, uint32_t k) { return Eigen::Vector3f(t.nx()[k], t.ny()[k], t.nz()[k]); };
    const Eigen::Vector3f na = normal(A.tree(), sa), nb = normal(B.tree(), sb);
    const bool disc_a = two_a && two_a[sa] && na.squaredNorm() > 0, disc_b = two_b && two_b[sb] && nb.squaredNorm() > 0;
    const float k = detail::kDiscHalfThickness;
    const detail::LeafShape a{ca, disc_a ? na.normalized() : Eigen::Vector3f::Zero(), ra, k * ra, disc_a};
    const detail::LeafShape b{cb, disc_b ? Eigen::Vector3f(f.R * nb.normalized()) : Eigen::Vector3f::Zero(), rb,
                              k * rb, disc_b};
    if (!detail::leaf_shapes_may_touch(a, b, o.inflate)) return false;
    // Grown spheres (continuous detection, a scene's contact band) keep the discs' answer: the
    // faces are tested only for touching.
    return o.inflate > 0 || pieces_touch(sa, sb, disc_a, disc_b, ca, cb, ra, rb);
}

bool QueryRun::node_discs_touch(uint32_t i, uint32_t j, const Eigen::Vector3f& ca, const Eigen::Vector3f& cb, float ra,
                                float rb) const {
    const float *da = A.tree().node_disc(), *db = B.tree().node_disc();
    const float *pa = da ? da + 4 * size_t(i) : nullptr, *pb = db ? db + 4 * size_t(j) : nullptr;
    const bool disc_a = pa && pa[3] >= 0, disc_b = pb && pb[3] >= 0;
    if (!disc_a && !disc_b) return true;
    const detail::LeafShape a{ca, disc_a ? Eigen::Vector3f(pa[0], pa[1], pa[2]) : Eigen::Vector3f::Zero(), ra,
                              disc_a ? pa[3] : 0, disc_a};
    const detail::LeafShape b{cb, disc_b ? Eigen::Vector3f(f.R * Eigen::Vector3f(pb[0], pb[1], pb[2])) : Eigen::Vector3f::Zero(),
                              rb, disc_b ? pb[3] : 0, disc_b};
    return detail::leaf_shapes_may_touch(a, b, o.inflate + f.margin);
}

uint32_t QueryRun::sphere_leaf_pair(uint32_t i, uint32_t j, const Eigen::Vector3f& ca) {
    const CompactTree &ta = A.tree(), &tb = B.tree();
    const CompactNode &na = ta.nodes()[i], &nb = tb.nodes()[j];
    // Lazy update: B's spheres are moved only here, for the leaf the walk reached: once a query
    // into its slot when a small model's slots fit in L2, else into a buffer that stays in L1.
    const size_t lb = s.moved_b.size() / 3;
    float *bx, *by, *bz;
    if (s.leaf_slot) {
        bx = s.leaf_cache.data() + j * s.leaf_slot, by = bx + s.leaf_column, bz = by + s.leaf_column;
        if (s.leaf_stamp[j] != s.epoch) s.leaf_stamp[j] = s.epoch, move_leaf(j, bx, by, bz);
    } else {
        bx = s.moved_b.data(), by = bx + lb, bz = by + lb;
        move_leaf(j, bx, by, bz);
    }
    const float* block_a = ta.centers(na);
    const float *ax = block_a, *ay = block_a + na.count, *az = block_a + 2 * na.count;
    uint32_t count_a = na.count, count_b = nb.count;
    const bool cull = o.normal_culling;
    if (cull) {
        // u: from A's node towards B's node. A keeps n.u >= -cos; B, in its own frame, n.(-u) >= -cos.
        // A two-sided sphere faces both ways: always kept.
        Eigen::Vector3f u = b_node_centre(j) - ca;
        const float len = u.norm();
        const float limit = -o.cull_cos * 127.0f; // normals are snorm8
        const size_t la = s.ia.size();
        float *gax = s.ga.data(), *gay = gax + la, *gaz = gay + la;
        float *gbx = s.gb.data(), *gby = gbx + lb, *gbz = gby + lb;
        if (len > 0) {
            u /= len;
            const Eigen::Vector3f ub = -(f.R.transpose() * u);
            const uint8_t *two_a = ta.two_sided(), *two_b = tb.two_sided();
            count_a = 0;
            for (uint32_t p = 0, k = na.first; p < na.count; ++p, ++k)
                if ((two_a && two_a[k]) || ta.nx()[k] * u.x() + ta.ny()[k] * u.y() + ta.nz()[k] * u.z() >= limit)
                    gax[count_a] = ax[p], gay[count_a] = ay[p], gaz[count_a] = az[p], s.ia[count_a++] = k;
            count_b = 0;
            for (uint32_t q = 0, k = nb.first; q < nb.count; ++q, ++k)
                if ((two_b && two_b[k]) || tb.nx()[k] * ub.x() + tb.ny()[k] * ub.y() + tb.nz()[k] * ub.z() >= limit)
                    gbx[count_b] = bx[q], gby[count_b] = by[q], gbz[count_b] = bz[q], s.ib[count_b++] = k;
            ax = gax, ay = gay, az = gaz, bx = gbx, by = gby, bz = gbz;
        } else {
            for (uint32_t k = 0; k < na.count; ++k) s.ia[k] = na.first + k;
            for (uint32_t k = 0; k < nb.count; ++k) s.ib[k] = nb.first + k;
        }
        if (count_a == 0 || count_b == 0) return 0;
    }
    res.counters.sphere_tests += uint64_t(count_a) * count_b;
    const float reach = na.ss_radius + nb.ss_radius + o.inflate;
    const float limit2 = reach * reach;
    float* d2 = s.d2.data();
    const float best = sphere_block_d2(ax, ay, az, count_a, bx, by, bz, count_b, d2);
    if (!(best < limit2)) return 0;
    // Whether a recorded pair is deep (is_deep_pair). One centre inside the other ball would not
    // do: a tiny sphere at a sharp edge lies wholly inside a large one at a mere touch.
    leaf_deep = false;
    const uint32_t stride = sphere_block_stride(count_b);
    auto sphere_a = [&](uint32_t k) { return cull ? s.ia[k] : na.first + k; };
    auto sphere_b = [&](uint32_t k) { return cull ? s.ib[k] : nb.first + k; };
    auto centre = [](const float* x, const float* y, const float* z, uint32_t k) { return Eigen::Vector3f(x[k], y[k], z[k]); };
    // Two-sided spheres are tested as discs after their balls overlap (geometry/sample_disc.hpp).
    const bool discs = ta.two_sided() || tb.two_sided();
    auto touch = [&](uint32_t p, uint32_t q) {
        return !discs || shapes_touch(sphere_a(p), sphere_b(q), centre(ax, ay, az, p), centre(bx, by, bz, q),
                                      na.ss_radius, nb.ss_radius);
    };
    if (o.mode != QueryMode::All && !discs) { // any and deepest want only the closest pair (the first, on ties)
        for (uint32_t p = 0; p < count_a; ++p)
            for (uint32_t q = 0; q < count_b; ++q)
                if (d2[size_t(p) * stride + q] == best) {
                    record(i, j, sphere_a(p), sphere_b(q), centre(ax, ay, az, p), centre(bx, by, bz, q), reach,
                           na.ss_radius, best);
                    return 1;
                }
    }
    // Four distances a compare and the hits walked as mask bits: a branch per distance
    // mispredicts on every boundary of the overlap. Lanes past count_b hold +inf.
    uint32_t hits = 0;
    uint32_t best_p = 0, best_q = 0;
    float best_d2 = INFINITY;
    const v4f lim = splat(limit2);
    // Mode all keeps every touching pair here (keep_pair, as record() does) without a call to
    // record() a pair.
    const bool collect = o.mode == QueryMode::All && !exit;
    // A row's hits are gathered 32 lanes at a time into one mask: a branch a row, not one a
    // group of four (a leaf's rows are mostly a group or two, hit or not at random).
    for (uint32_t p = 0; p < count_a; ++p) {
        const float* row = d2 + size_t(p) * stride;
        for (uint32_t q0 = 0; q0 < stride; q0 += 32) {
            const uint32_t q1 = std::min(stride, q0 + 32);
            unsigned bits = 0;
            for (uint32_t g = q0; g < q1; g += 4) {
                v4f v;
                std::memcpy(&v, row + g, sizeof v);
                bits |= unsigned(movemask(v < lim)) << (g - q0);
            }
            for (; bits; bits &= bits - 1) {
                const uint32_t q = q0 + uint32_t(__builtin_ctz(bits));
                if (o.mode == QueryMode::Deepest && !(row[q] < best_d2)) continue; // cannot be the closest
                if (!touch(p, q)) continue;
                if (o.mode == QueryMode::Any) { // a touching pair answers; the faces tested cost more than the order
                    record(i, j, sphere_a(p), sphere_b(q), centre(ax, ay, az, p), centre(bx, by, bz, q), reach,
                           na.ss_radius, row[q]);
                    return 1;
                }
                if (o.mode == QueryMode::Deepest) { // the closest pair that touches (the first, on ties)
                    best_d2 = row[q], best_p = p, best_q = q;
                    continue;
                }
                ++hits;
                if (collect) {
                    keep_pair(i, j, sphere_a(p), sphere_b(q), reach, row[q]);
                    leaf_deep |= detail::is_deep_pair(s.pairs.back());
                }
                else if (exit) // as record() answers an exit search, without the call
                    exit_pair(i, j, sphere_a(p), sphere_b(q), centre(ax, ay, az, p), centre(bx, by, bz, q), reach);
                else
                    record(i, j, sphere_a(p), sphere_b(q), centre(ax, ay, az, p), centre(bx, by, bz, q), reach,
                           na.ss_radius, row[q]);
            }
        }
    }
    if (o.mode == QueryMode::Deepest && best_d2 < limit2) { // any returned at its first touching pair
        record(i, j, sphere_a(best_p), sphere_b(best_q), centre(ax, ay, az, best_p), centre(bx, by, bz, best_q), reach,
               na.ss_radius, best_d2);
        return 1;
    }
    return hits;
}

} // namespace spt
