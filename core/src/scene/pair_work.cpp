// Depth, contact point and contact normal of a colliding pair, from one `all` query.
#include "scene/pair_work.hpp"
#include "query/scratch.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {
namespace {

Eigen::Vector3d surface_normal(const CompactTree& t, uint32_t sphere) {
    return Eigen::Vector3d(t.nx()[sphere], t.ny()[sphere], t.nz()[sphere]) / 127.0;
}

Eigen::Vector3d centre(const CollisionModel& m, const Pose& p, uint32_t node, uint32_t sphere) {
    const CompactTree& t = m.tree();
    return p.apply(m.origin() + t.sphere_center(t.nodes()[node], sphere).cast<double>());
}

} // namespace

Eigen::Vector3d contact_normal(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                               const std::vector<SpherePair>& pairs, const Eigen::Vector3d& fallback, bool a_moves,
                               bool b_moves, QueryScratch& scratch) {
    const bool use_a = !a_moves || b_moves, use_b = !b_moves || a_moves; // what is struck gives the normal
    // World centres and normals made once a sphere, not once a pair (a sphere is in many pairs);
    // a sphere's two side by side, found by one look-up.
    detail::ScratchBuffers& m = scratch.buffers();
    m.memo_ca.start(a.tree().sphere_count()), m.memo_cb.start(b.tree().sphere_count());
    auto frame = [](const CollisionModel& o, const Pose& p, uint32_t node, uint32_t sphere) {
        Eigen::Matrix<double, 3, 2> v;
        v.col(0) = centre(o, p, node, sphere);
        v.col(1) = p.rotate(surface_normal(o.tree(), sphere));
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

void deepest_contact(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                     QueryLevel level, double band, bool a_dynamic, bool b_dynamic, PairWork& w,
                     QueryScratch& scratch) {
    QueryOptions q;
    q.level = level;
    q.mode = QueryMode::All; // the deepest pair is among them, and the normal needs them all
    q.inflate = float(band);
    const QueryResult r = collide(a, pa, b, pb, q, scratch);
    w.qc.node_pairs += r.counters.node_pairs, w.qc.bound_tests += r.counters.bound_tests;
    w.qc.sphere_tests += r.counters.sphere_tests, w.qc.triangle_tests += r.counters.triangle_tests;
    contact_from_pairs(a, pa, b, pb, level, band, a_dynamic, b_dynamic, scratch.pairs(), r.collide, r.deepest.point, w,
                       scratch);
}

void contact_from_pairs(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                        QueryLevel level, double band, bool a_dynamic, bool b_dynamic,
                        const std::vector<SpherePair>& pairs, bool collide, const Eigen::Vector3d& point, PairWork& w,
                        QueryScratch& scratch) {
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
    const Eigen::Vector3d ca = centre(a, pa, best->node_a, best->a), cb = centre(b, pb, best->node_b, best->b);
    const Eigen::Vector3d line = (cb - ca).norm() > 0 ? Eigen::Vector3d((cb - ca).normalized()) : Eigen::Vector3d::UnitX();
    const double ra = a.tree().nodes()[best->node_a].ss_radius;
    w.point = ca + line * (ra - 0.5 * double(best->depth)); // middle of the overlap
    w.normal = contact_normal(a, pa, b, pb, pairs, line, a_dynamic, b_dynamic, scratch);
}

} // namespace spt::detail
