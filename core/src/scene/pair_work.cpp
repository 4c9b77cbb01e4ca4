// Depth and contact normal of a colliding pair.
#include "scene/pair_work.hpp"
#include <algorithm>

namespace spt::detail {
namespace {

Eigen::Vector3d surface_normal(const CompactTree& t, uint32_t sphere) {
    return Eigen::Vector3d(t.nx()[sphere], t.ny()[sphere], t.nz()[sphere]) / 127.0;
}

} // namespace

Eigen::Vector3d contact_normal(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                               const Contact& c, QueryLevel level, bool a_moves, bool b_moves) {
    if (level == QueryLevel::Bounds) return c.normal; // node indices: no surface normal to read
    const Eigen::Vector3d na = pa.rotate(surface_normal(a.tree(), c.a));
    const Eigen::Vector3d nb = pb.rotate(surface_normal(b.tree(), c.b));
    Eigen::Vector3d n = na - nb;
    if (a_moves && !b_moves) n = -nb;
    if (b_moves && !a_moves) n = na;
    const double len = n.norm();
    if (!(len > 1e-6)) return c.normal;
    n /= len;
    return n.dot(c.normal) < -0.5 ? c.normal : n; // surfaces facing away from the overlap: keep the centres' normal
}

void deepest_contact(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                     QueryLevel level, double band, bool a_dynamic, bool b_dynamic, PairWork& w,
                     QueryScratch& scratch) {
    QueryOptions q;
    q.level = level;
    q.mode = QueryMode::Deepest;
    q.inflate = float(band);
    const QueryResult r = collide(a, pa, b, pb, q, scratch);
    w.qc.node_pairs += r.counters.node_pairs, w.qc.bound_tests += r.counters.bound_tests;
    w.qc.sphere_tests += r.counters.sphere_tests, w.qc.triangle_tests += r.counters.triangle_tests;
    if (!r.collide) {
        // The exact level saw triangles cross where no spheres overlap: no sphere depth.
        w.depth = 0;
        w.point = 0.5 * (pa.translation + pb.translation);
        const Eigen::Vector3d d = pb.translation - pa.translation;
        w.normal = d.norm() > 0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::UnitX();
        return;
    }
    w.depth = std::max(0.0, r.deepest.depth - double(q.inflate));
    w.point = r.deepest.point;
    w.normal = contact_normal(a, pa, b, pb, r.deepest, level, a_dynamic, b_dynamic);
}

} // namespace spt::detail
