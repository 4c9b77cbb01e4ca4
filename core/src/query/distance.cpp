// Distance between two sampling-sphere models: best-first branch and bound over node pairs,
// ordered by the gap their bounding spheres leave; overlapping models answer the deepest overlap.
// Level exact hands the apart case to the triangles (distance_exact.cpp).
#include "spt/distance.hpp"
#include "query/best_first.hpp"
#include "query/distance_exact.hpp"
#include "query/model_access.hpp"
#include "query/node_slab.hpp"
#include "query/pending_pose.hpp"
#include "query/query_run.hpp"
#include "query/scratch.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <limits>
#include <cmath>

namespace spt {
namespace {

// B's local point in A's local frame (both relative to their models' origins), in double.
struct FrameBToA {
    Eigen::Matrix3d r;
    Eigen::Vector3d t;
    FrameBToA(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a)
        : r(b_in_a.rotation.toRotationMatrix()), t(b_in_a.apply(b.origin()) - a.origin()) {}
    Eigen::Vector3d operator()(const Eigen::Vector3f& p) const { return r * p.cast<double>() + t; }
};

Eigen::Vector3d centre(const CompactNode& n) { return {n.center[0], n.center[1], n.center[2]}; }

} // namespace

DistanceResult distance_relative(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                                 const DistanceOptions& options, QueryScratch& scratch) {
    if (!(options.max_distance > 0) || !(options.relative_error >= 0 && options.relative_error < 1) ||
        !(options.absolute_error >= 0 && std::isfinite(options.absolute_error)))
        throw Error(ErrorKind::Usage,
                    "distance: max_distance must be > 0, relative_error in [0, 1) and absolute_error finite and >= 0");
    DistanceResult res;
    // Overlapping: the deepest overlap, as mode deepest finds it (or, without depth, only that
    // they overlap, as mode any finds it).
    QueryOptions deepest;
    deepest.level = options.level;
    deepest.mode = options.depth ? QueryMode::Deepest : QueryMode::Any;
    deepest.solids = false;
    // The absolute allowance holds for an overlap's depth too: the answer may be that much above -depth.
    const QueryResult hit = options.depth && options.absolute_error > 0
                                ? detail::deepest_within(a, b, b_in_a, deepest, float(options.absolute_error), scratch)
                                : collide_relative(a, b, b_in_a, deepest, scratch);
    res.counters = hit.counters;
    if (hit.collide && !options.depth) {
        res.collide = true;
        res.distance = 0;
        res.point_a = res.point_b = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
        return res;
    }
    if (hit.collide) {
        const Contact& c = hit.deepest;
        res.collide = true;
        res.distance = -c.depth;
        res.point_a = c.point + 0.5 * c.depth * c.normal;
        res.point_b = c.point - 0.5 * c.depth * c.normal;
        return res;
    }
    detail::settle(a), detail::settle(b); // a lazy pose is posed in full first
    if (options.level == QueryLevel::Exact) { // no triangles meet: the nearest two
        detail::exact_gap(a, b, b_in_a, options, scratch, res);
        return res;
    }
    const CompactTree& ta = a.tree();
    const CompactTree& tb = b.tree();
    if (ta.nodes().empty() || tb.nodes().empty()) {
        res.beyond = true;
        return res;
    }
    const bool bounds = options.level == QueryLevel::Bounds;
    const std::vector<float>& reach_a = a.bounds_reach();
    const std::vector<float>& reach_b = b.bounds_reach();
    auto radius_a = [&](uint32_t i) { return double(bounds ? reach_a[i] : ta.nodes()[i].bv_radius); };
    auto radius_b = [&](uint32_t i) { return double(bounds ? reach_b[i] : tb.nodes()[i].bv_radius); };
    const FrameBToA to_a(a, b, b_in_a);
    // Moved as the walk reaches them (a few multiplies): a table of every node would cost a large
    // model's node count a query however little the walk visits.
    auto centre_b = [&](uint32_t j) {
        return to_a(Eigen::Vector3f(tb.nodes()[j].center[0], tb.nodes()[j].center[1], tb.nodes()[j].center[2]));
    };
    // At level spheres a node's spheres also lie in its slab (query/node_slab.hpp): across a densely
    // sampled face the slab's gap is far nearer the distance than the balls'.
    const float* slab_a = bounds ? nullptr : detail::node_slab_of(a);
    const float* slab_b = bounds ? nullptr : detail::node_slab_of(b);
    // Node i's row of its model's node_slabs table, or null where it has no disc.
    auto disc_of = [](const float* slab, uint32_t i) {
        const float* s = slab ? slab + detail::kSlabStride * i : nullptr;
        return s && s[3] >= 0 ? s : nullptr;
    };
    // How far a node's spheres reach along a unit vector at cosine a (sine b) to its disc's normal,
    // s its node_slabs row: the angle is the one both discs of a pair share, found once.
    auto support = [](const float* s, double radius, double a, double b) {
        return detail::disc_support<double>(radius, s[3], s[4], s[5], s[6], a, b);
    };
    auto lower_bound = [&](uint32_t i, uint32_t j) {
        const Eigen::Vector3d ca = centre(ta.nodes()[i]), cb = centre_b(j), d = cb - ca;
        const double ra = radius_a(i), rb = radius_b(j);
        double gap = d.norm() - ra - rb;
        const float *sa = disc_of(slab_a, i), *sb = disc_of(slab_b, j);
        if (!sa && !sb) return gap;
        // The gap beyond a disc's face towards the other node's centre (its reach along its normal,
        // or against it), then beyond the other's reach back along that normal: its ball's, or
        // with a disc too, its disc's at the angle between the two normals.
        const Eigen::Vector3d na = sa ? Eigen::Vector3d(sa[0], sa[1], sa[2]) : Eigen::Vector3d::Zero();
        const Eigen::Vector3d nb = sb ? Eigen::Vector3d(to_a.r * Eigen::Vector3d(sb[0], sb[1], sb[2])) : Eigen::Vector3d::Zero();
        const double cosine = std::clamp(na.dot(nb), -1.0, 1.0), sine = sa && sb ? std::sqrt(1 - cosine * cosine) : 0;
        if (sa) {
            const double along = na.dot(d);
            const double beyond = std::abs(along) - (along >= 0 ? sa[3] : sa[4]);
            gap = std::max(gap, beyond - (sb ? support(sb, rb, along >= 0 ? -cosine : cosine, sine) : rb));
        }
        if (sb) {
            const double along = -nb.dot(d);
            const double beyond = std::abs(along) - (along >= 0 ? sb[3] : sb[4]);
            gap = std::max(gap, beyond - (sa ? support(sa, ra, along >= 0 ? -cosine : cosine, sine) : ra));
        }
        return gap;
    };
    double best = options.max_distance;
    // A pair is worth a visit while it could beat the best by more than the allowances.
    const double keep = 1 - options.relative_error;
    auto worth = [&](double gap) { return gap < best * keep - options.absolute_error; };
    Eigen::Vector3d best_a, best_b; // nearest sphere centres, A's local frame
    double best_ra = 0, best_rb = 0;
    bool found = false;
    // Node pairs by the least gap below them (a lower bound, model units), kept in the scratch so
    // that a query allocates nothing once it has grown.
    using Bound = detail::ScratchBuffers::SphereGapBound;
    detail::BestFirst<double> open(detail::buffers_of(scratch).sphere_gap_heap);
    std::vector<Eigen::Vector3d>& moved = detail::buffers_of(scratch).distance_leaf_b; // B's leaf spheres
    if (const double g = lower_bound(0, 0); g < best) open.push(g, 0, 0);
    auto children = [](const CompactTree& t, uint32_t i) { return std::array<uint32_t, 2>{i + 1, t.nodes()[i].first}; };
    for (Bound top; open.take(top);) {
        if (!worth(top.gap) && !(top.gap < 0)) break;
        ++res.counters.node_pairs;
        const CompactNode& na = ta.nodes()[top.a];
        const CompactNode& nb = tb.nodes()[top.b];
        if (na.is_active() && nb.is_active()) {
            if (bounds) { // the leaf bounding spheres are the model
                const double g = (centre(na) - centre_b(top.b)).norm() - na.bv_radius - nb.bv_radius;
                ++res.counters.bound_tests;
                if (g < best) best = g, best_a = centre(na), best_b = centre_b(top.b), best_ra = na.bv_radius, best_rb = nb.bv_radius, found = true;
                continue;
            }
            // B's spheres moved once a leaf pair, not once an A sphere; a pair's root taken only
            // where its squared distance may beat the best (widened: the root decides as before).
            if (moved.size() < nb.count) moved.resize(nb.count);
            for (uint32_t l = 0; l < nb.count; ++l) moved[l] = to_a(tb.sphere_center(nb, nb.first + l));
            const double reach = double(na.ss_radius) + double(nb.ss_radius);
            res.counters.sphere_tests += uint64_t(na.count) * nb.count;
            for (uint32_t k = na.first; k < na.first + na.count; ++k) {
                const Eigen::Vector3d ca = ta.sphere_center(na, k).cast<double>();
                for (uint32_t l = 0; l < nb.count; ++l) {
                    const double limit = best + reach, d2 = (ca - moved[l]).squaredNorm();
                    if (!(limit > 0 && d2 <= limit * limit * (1 + 1e-9))) continue;
                    const double g = std::sqrt(d2) - na.ss_radius - nb.ss_radius;
                    if (g < best) best = g, best_a = ca, best_b = moved[l], best_ra = na.ss_radius, best_rb = nb.ss_radius, found = true;
                }
            }
            continue;
        }
        // Descend the larger (a leaf never): both children of that side.
        const bool side_a = nb.is_active() || (!na.is_active() && radius_a(top.a) >= radius_b(top.b));
        Bound kids[2];
        int n = 0;
        for (uint32_t c : side_a ? children(ta, top.a) : children(tb, top.b)) {
            const uint32_t i = side_a ? c : top.a, j = side_a ? top.b : c;
            ++res.counters.bound_tests;
            if (const double g = lower_bound(i, j); worth(g) || g < 0) kids[n++] = {g, i, j};
        }
        open.push_children(kids, n);
    }
    if (!found) {
        res.beyond = true;
        return res;
    }
    res.distance = std::max(best, 0.0); // spheres that do not overlap are at least touching apart
    const Eigen::Vector3d u = (best_b - best_a).normalized();
    res.point_a = best_a + best_ra * u + a.origin();
    res.point_b = best_b - best_rb * u + a.origin();
    return res;
}

} // namespace spt
