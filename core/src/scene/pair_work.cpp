// Depth, contact point and contact normal of a colliding pair: from one `all` query, or for a deep
// overlap from the deepest pair and its two active nodes.
#include "scene/pair_work.hpp"
#include "query/query_run.hpp"
#include "query/scratch.hpp"
#include "query/world_sphere.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {

Eigen::Vector3d contact_normal(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                               const std::vector<SpherePair>& pairs, const Eigen::Vector3d& fallback, bool a_moves,
                               bool b_moves, QueryScratch& scratch) {
    const bool use_a = !a_moves || b_moves, use_b = !b_moves || a_moves; // what is struck gives the normal
    // World centres and normals made once a sphere, not once a pair (a sphere is in many pairs);
    // a sphere's two side by side, found by one look-up.
    detail::ScratchBuffers& m = detail::buffers_of(scratch);
    m.memo_ca.start(a.tree().sphere_count()), m.memo_cb.start(b.tree().sphere_count());
    auto frame = [](const CollisionModel& o, const Pose& p, uint32_t node, uint32_t sphere) {
        Eigen::Matrix<double, 3, 2> v;
        v.col(0) = world_sphere_centre(o, p, node, sphere);
        v.col(1) = p.rotate(sphere_normal(o.tree(), sphere));
        return v;
    };
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (const SpherePair& p : pairs) {
        const Eigen::Matrix<double, 3, 2>& sa = m.memo_ca.get(p.a, [&] { return frame(a, pa, p.node_a, p.a); });
        const Eigen::Matrix<double, 3, 2>& sb = m.memo_cb.get(p.b, [&] { return frame(b, pb, p.node_b, p.b); });
        const Eigen::Vector3d ab = sb.col(0) - sa.col(0);
        const auto na = sa.col(1), nb = sb.col(1);
        // A normal gives the axis; its side is the one facing the other sphere: in a thin part the
        // spheres of the far face poke through the near one and stand for it.
        // The side is the sign of the weight, set without a branch (a coin toss a pair): adding
        // 0.0 turns a dot of -0 into +0, so the sign is that of "dot >= 0", and +-depth * n is,
        // bit for bit, depth * (+-n).
        const double d = p.depth;
        if (use_a) n += std::copysign(d, na.dot(ab) + 0.0) * na;
        if (use_b) n -= std::copysign(d, -nb.dot(ab) + 0.0) * nb;
    }
    const double len = n.norm();
    return len > 1e-12 ? Eigen::Vector3d(n / len) : fallback;
}

namespace {

// contact_from_pairs, the pairs known to hold no deep one.
void from_pairs(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb, QueryLevel level,
                double band, bool a_dynamic, bool b_dynamic, const std::vector<SpherePair>& pairs, bool collide,
                const Eigen::Vector3d& point, PairWork& w, QueryScratch& scratch) {
    if (pairs.empty()) {
        // Triangles crossing where no spheres overlap (level exact), or one object inside the
        // other (containment: the contained anchor is the point): no sphere depth.
        w.depth = 0;
        w.point = collide ? point : Eigen::Vector3d(0.5 * (pa.translation + pb.translation));
        const Eigen::Vector3d d = pb.translation - pa.translation;
        w.normal = d.norm() > 0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::UnitX();
        return;
    }
    // The first of the deepest, as mode `deepest` reports it.
    const SpherePair* best = &pairs[0];
    for (const SpherePair& p : pairs)
        if (p.depth > best->depth) best = &p;
    w.depth = std::max(0.0, double(best->depth) - double(float(band)));
    if (level == QueryLevel::Bounds) {
        const CompactNode& na = a.tree().nodes()[best->a];
        const CompactNode& nb = b.tree().nodes()[best->b];
        const Eigen::Vector3d ca = pa.apply(a.origin() + Eigen::Vector3f(na.center[0], na.center[1], na.center[2]).cast<double>());
        const Eigen::Vector3d cb = pb.apply(b.origin() + Eigen::Vector3f(nb.center[0], nb.center[1], nb.center[2]).cast<double>());
        w.normal = (cb - ca).norm() > 0 ? Eigen::Vector3d((cb - ca).normalized()) : Eigen::Vector3d::UnitX();
        w.point = ca + w.normal * (double(na.bv_radius) - 0.5 * double(best->depth));
        return;
    }
    const Eigen::Vector3d ca = world_sphere_centre(a, pa, best->node_a, best->a), cb = world_sphere_centre(b, pb, best->node_b, best->b);
    const Eigen::Vector3d line = (cb - ca).norm() > 0 ? Eigen::Vector3d((cb - ca).normalized()) : Eigen::Vector3d::UnitX();
    const double ra = a.tree().nodes()[best->node_a].ss_radius;
    w.point = ca + line * (ra - 0.5 * double(best->depth)); // middle of the overlap
    w.normal = contact_normal(a, pa, b, pb, pairs, line, a_dynamic, b_dynamic, scratch);
}

// Whether a pair of `pairs` is deep, as the walk of collide_all_unless_deep tells it.
bool holds_deep_pair(const std::vector<SpherePair>& pairs) {
    return std::any_of(pairs.begin(), pairs.end(), is_deep_pair);
}

// Into `pairs`: the overlapping sphere pairs of active nodes node_a and node_b (spheres grown by
// `inflate`), with their depths from the world centres; at most a leaf's spheres squared.
void leaf_pair(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb, uint32_t node_a,
               uint32_t node_b, float inflate, std::vector<SpherePair>& pairs) {
    const CompactNode &na = a.tree().nodes()[node_a], &nb = b.tree().nodes()[node_b];
    const float reach = na.ss_radius + nb.ss_radius + inflate;
    pairs.clear();
    for (uint32_t i = na.first; i < na.first + na.count; ++i) {
        const Eigen::Vector3d ca = world_sphere_centre(a, pa, node_a, i);
        for (uint32_t j = nb.first; j < nb.first + nb.count; ++j) {
            const double depth = double(reach) - (world_sphere_centre(b, pb, node_b, j) - ca).norm();
            if (depth > 0) pairs.push_back({i, j, node_a, node_b, float(depth), reach});
        }
    }
}

// Deep overlaps (a deep leaf pair: surfaces that cross rather than press): the deepest pair by
// branch and bound, and the normal of the overlapping pairs of its own two active nodes, instead of
// every overlapping pair, whose number grows with the volume the two shells share (docs/scenes.md,
// "Deep overlaps").
void deep_contact(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                  const QueryOptions& all, bool a_dynamic, bool b_dynamic, PairWork& w, QueryScratch& scratch) {
    QueryOptions q = all;
    q.mode = QueryMode::Deepest;
    const QueryResult r = detail::deepest_within(a, pa, b, pb, q, float(detail::deep_allowance(a, b)), scratch);
    add_counters(w.qc, r.counters);
    detail::ScratchBuffers& s = detail::buffers_of(scratch);
    const uint32_t node_a = s.deepest_node_a, node_b = s.deepest_node_b;
    w.deepest = {r.deepest.a, r.deepest.b, node_a, node_b, float(r.deepest.depth),
                 a.tree().nodes()[node_a].ss_radius + b.tree().nodes()[node_b].ss_radius + q.inflate};
    w.depth = std::max(0.0, r.deepest.depth - double(q.inflate));
    const Eigen::Vector3d ca = world_sphere_centre(a, pa, node_a, r.deepest.a), cb = world_sphere_centre(b, pb, node_b, r.deepest.b);
    const Eigen::Vector3d line = (cb - ca).norm() > 0 ? Eigen::Vector3d((cb - ca).normalized()) : Eigen::Vector3d::UnitX();
    const double ra = a.tree().nodes()[node_a].ss_radius;
    w.point = ca + line * (ra - 0.5 * r.deepest.depth); // middle of the overlap, as contact_from_pairs
    leaf_pair(a, pa, b, pb, node_a, node_b, q.inflate, s.pairs); // the scratch's list: no allocation a step
    w.normal = contact_normal(a, pa, b, pb, s.pairs, line, a_dynamic, b_dynamic, scratch);
}

} // namespace

void deepest_contact(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                     QueryLevel level, double band, bool a_dynamic, bool b_dynamic, PairWork& w,
                     QueryScratch& scratch) {
    QueryOptions q;
    q.level = level;
    q.inflate = float(band);
    // The deepest pair is among every overlapping pair, and the normal needs them all, unless the
    // overlap is deep.
    bool deep = false;
    const QueryResult r = collide_all_unless_deep(a, pa, b, pb, q, scratch, deep);
    add_counters(w.qc, r.counters);
    w.deep = deep;
    if (deep) return deep_contact(a, pa, b, pb, q, a_dynamic, b_dynamic, w, scratch);
    from_pairs(a, pa, b, pb, level, band, a_dynamic, b_dynamic, scratch.pairs(), r.collide, r.deepest.point, w, scratch);
}

void contact_from_pairs(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                        QueryLevel level, double band, bool a_dynamic, bool b_dynamic,
                        const std::vector<SpherePair>& pairs, bool collide, const Eigen::Vector3d& point, PairWork& w,
                        QueryScratch& scratch) {
    w.deep = level == QueryLevel::Spheres && holds_deep_pair(pairs);
    if (!w.deep) return from_pairs(a, pa, b, pb, level, band, a_dynamic, b_dynamic, pairs, collide, point, w, scratch);
    QueryOptions q;
    q.level = level;
    q.inflate = float(band);
    deep_contact(a, pa, b, pb, q, a_dynamic, b_dynamic, w, scratch);
}

} // namespace spt::detail
