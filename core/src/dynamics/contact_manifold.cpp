// Contact manifolds of sampling spheres (contact_manifold.hpp).
#include "dynamics/contact_manifold.hpp"
#include "query/query_run.hpp"
#include "query/scratch.hpp"
#include "query/world_sphere.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {
namespace {

// Below this, a pair's two surfaces do not face each other (-n_a . n_b).
constexpr double kFacing = 0.1;
// Above this, two surfaces face each other squarely (within 11 degrees).
constexpr double kSquarely = 0.98;

// -n_a . n_b of a sphere pair's surface normals (world), each turned to face the other sphere
// where its sphere is two-sided (its normal is an axis); also the pair's centres, radii and normals.
double facing(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb, const SpherePair& p,
              PairFrame* f = nullptr, Eigen::Vector3d* na_out = nullptr, Eigen::Vector3d* nb_out = nullptr) {
    const Eigen::Vector3d ca = world_sphere_centre(a, pa, p.node_a, p.a), cb = world_sphere_centre(b, pb, p.node_b, p.b);
    const Eigen::Vector3d ab = cb - ca;
    Eigen::Vector3d na = pa.rotate(sphere_normal(a.tree(), p.a)), nb = pb.rotate(sphere_normal(b.tree(), p.b));
    const uint8_t *two_a = a.tree().two_sided(), *two_b = b.tree().two_sided();
    if (two_a && two_a[p.a] && na.dot(ab) < 0) na = -na;
    if (two_b && two_b[p.b] && nb.dot(ab) > 0) nb = -nb;
    if (f) {
        f->ca = ca, f->cb = cb;
        f->ra = a.tree().nodes()[p.node_a].ss_radius, f->rb = b.tree().nodes()[p.node_b].ss_radius;
    }
    if (na_out) *na_out = na, *nb_out = nb;
    return -na.dot(nb);
}

// Whether a pair's two spheres lie side by side on faces in one plane: parallel normals (within 11
// degrees), the centres' offset across them.
bool side_by_side(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb, const SpherePair& p) {
    PairFrame f;
    Eigen::Vector3d na, nb;
    facing(a, pa, b, pb, p, &f, &na, &nb);
    const Eigen::Vector3d ab = f.cb - f.ca;
    const double d = ab.norm();
    return na.dot(nb) > kSquarely && (d == 0 || std::abs(na.dot(ab)) < 0.2 * d);
}

// Index of the largest score (the first of equals), or -1 when none is above `floor`.
template <class Score>
int best(const std::vector<ManifoldContact>& c, double floor, Score score) {
    int k = -1;
    double top = floor;
    for (size_t i = 0; i < c.size(); ++i) {
        const double s = score(c[i]);
        if (s > top) top = s, k = int(i);
    }
    return k;
}

} // namespace

std::vector<ManifoldContact> reduce_manifold(const std::vector<ManifoldContact>& c, double depth_tolerance) {
    if (c.size() <= 4) return c;
    const Eigen::Vector3d n = c[0].normal;
    auto across = [&](const Eigen::Vector3d& d) { return Eigen::Vector3d(d - d.dot(n) * n); };
    Eigen::Vector3d middle = Eigen::Vector3d::Zero();
    for (const ManifoldContact& m : c) middle += m.on_b;
    middle /= double(c.size());
    // The first point is the one farthest from the contact's middle, not the deepest: on faces
    // pressed flat together every depth is the same to within the spheres' ripple, and the deepest
    // would jump from step to step, while a corner stays (and the solver warm-starts it).
    std::vector<ManifoldContact> out;
    const int i0 = best(c, -1.0, [&](const ManifoldContact& m) { return across(m.on_b - middle).squaredNorm(); });
    const ManifoldContact p0 = c[size_t(i0)];
    out.push_back(p0);
    double span2 = 0;
    for (const ManifoldContact& m : c) span2 = std::max(span2, across(m.on_b - p0.on_b).squaredNorm());
    const double tiny2 = 1e-6 * span2;
    const int i1 = best(c, tiny2, [&](const ManifoldContact& m) { return across(m.on_b - p0.on_b).squaredNorm(); });
    if (i1 >= 0) {
        const ManifoldContact p1 = c[size_t(i1)];
        out.push_back(p1);
        const Eigen::Vector3d base = p1.on_b - p0.on_b;
        auto side = [&](const ManifoldContact& m) { return base.cross(m.on_b - p0.on_b).dot(n); }; // twice the signed area
        const double tiny_area = 1e-3 * span2;
        const int i2 = best(c, tiny_area, [&](const ManifoldContact& m) { return std::abs(side(m)); });
        if (i2 >= 0) {
            out.push_back(c[size_t(i2)]);
            const double sign = side(c[size_t(i2)]) > 0 ? -1.0 : 1.0; // the fourth from the other side of the base
            const int i3 = best(c, tiny_area, [&](const ManifoldContact& m) { return sign * side(m); });
            if (i3 >= 0) out.push_back(c[size_t(i3)]);
        }
    }
    // A point clearly deeper than every chosen one (a corner dug in) takes the place of the
    // chosen point nearest to it: the solver must push where the overlap is.
    const int deepest = best(c, -HUGE_VAL, [](const ManifoldContact& m) { return m.depth; });
    double chosen_depth = -HUGE_VAL;
    for (const ManifoldContact& m : out) chosen_depth = std::max(chosen_depth, m.depth);
    if (c[size_t(deepest)].depth > chosen_depth + depth_tolerance) {
        size_t nearest = 0;
        for (size_t k = 1; k < out.size(); ++k)
            if ((out[k].on_b - c[size_t(deepest)].on_b).squaredNorm() < (out[nearest].on_b - c[size_t(deepest)].on_b).squaredNorm())
                nearest = k;
        out[nearest] = c[size_t(deepest)];
    }
    return out;
}

void contact_manifold(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb, double margin,
                      bool a_moves, bool b_moves, bool keep_pairs, QueryScratch& scratch, ManifoldWork& work,
                      Manifold& out) {
    out.points.clear();
    out.pairs.clear();
    out.counters = {};
    QueryOptions q;
    q.level = QueryLevel::Spheres;
    q.inflate = float(margin);
    q.solids = false; // a body wholly inside another has no surface to be pushed out along
    // Spheres facing away from the other node cannot face the other surface: not tested.
    q.normal_culling = true;
    bool deep = false;
    const QueryResult r = collide_all_unless_deep(a, pa, b, pb, q, scratch, deep);
    out.counters = r.counters;
    // The walk calls a pair deep by its spheres grown by the margin, which small spheres at a
    // corner can be while still apart: then a walk of the spheres as they are tells. And where two
    // faces lie in one plane (stacked boxes' sides) their spheres along the shared edge overlap
    // deeply, side by side with parallel normals: no crossing of surfaces either. Unless a pair is
    // deep by its own radii and not such a pair, every pair within the margin after all.
    auto crossing = [&] {
        return std::any_of(scratch.pairs().begin(), scratch.pairs().end(),
                           [&](const SpherePair& p) { return is_deep_pair(p) && !side_by_side(a, pa, b, pb, p); });
    };
    if (deep) {
        QueryOptions own = q;
        own.inflate = 0;
        const QueryResult r0 = collide_all_unless_deep(a, pa, b, pb, own, scratch, deep);
        add_counters(out.counters, r0.counters);
        if (!deep || !crossing()) {
            q.mode = QueryMode::All;
            const QueryResult all = collide(a, pa, b, pb, q, scratch);
            add_counters(out.counters, all.counters);
            deep = false;
        }
    }
    // Surfaces crossing (a start inside another, or a blow the margin did not see coming): the
    // pairs the walk found up to its first deep pair, not every pair the shared volume holds, nor
    // the deepest by branch and bound (docs/scenes.md, "Deep overlaps"), pushed apart along the
    // line between the two models' centres; the next step finds the rest.
    const std::vector<SpherePair>& pairs = scratch.pairs();
    if (pairs.empty()) return; // apart; or one inside the other with no sphere near: no surface to push on
    // Each pair's two surface normals, each turned to face the other sphere where its sphere is
    // two-sided (its normal is an axis). A pair counts by its depth times how squarely its two
    // surfaces face each other: where two stacked boxes' side faces lie in one plane, the spheres
    // along the shared edges overlap, but their normals are parallel, not opposed, and they are no
    // contact: counted, they would tilt the normal sideways.
    std::vector<ManifoldContact>& all = work.candidates;
    all.clear();
    std::vector<PairFrame>& frames = work.frames;
    frames.clear();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero(), square = Eigen::Vector3d::Zero();
    const bool use_a = !a_moves || b_moves, use_b = !b_moves || a_moves; // what is struck gives the normal
    for (const SpherePair& p : pairs) {
        PairFrame f;
        Eigen::Vector3d na, nb;
        f.facing = facing(a, pa, b, pb, p, &f, &na, &nb);
        if (f.facing <= kFacing) continue;
        const double w = double(p.depth) * f.facing;
        Eigen::Vector3d& to = f.facing > kSquarely ? square : sum;
        if (use_a) to += w * na;
        if (use_b) to -= w * nb;
        frames.push_back(f);
    }
    // Faces pressed flat together give the normal alone where there are some: an edge's or a
    // corner's sphere, whose normal leans, would tilt it, and the solver's push out of the overlap
    // along a tilted normal walks a resting stack sideways.
    if (square.squaredNorm() > 0) sum = square;
    if (frames.empty()) { // no two surfaces face each other: every pair, along their centres
        for (const SpherePair& p : pairs) {
            PairFrame f;
            f.ca = world_sphere_centre(a, pa, p.node_a, p.a), f.cb = world_sphere_centre(b, pb, p.node_b, p.b);
            f.ra = a.tree().nodes()[p.node_a].ss_radius, f.rb = b.tree().nodes()[p.node_b].ss_radius;
            sum += double(p.depth) * (f.cb - f.ca).normalized();
            frames.push_back(f);
        }
    }
    if (deep) {
        auto centre_of = [](const CollisionModel& m, const Pose& p) {
            const CompactNode& root = m.tree().nodes()[0];
            return p.apply(m.origin() + Eigen::Vector3f(root.center[0], root.center[1], root.center[2]).cast<double>());
        };
        const Eigen::Vector3d line = centre_of(b, pb) - centre_of(a, pa);
        if (line.norm() > 0) sum = line;
    }
    const Eigen::Vector3d n = sum.norm() > 1e-12 ? Eigen::Vector3d(sum.normalized()) : Eigen::Vector3d::UnitX();
    for (const PairFrame& f : frames) {
        ManifoldContact m;
        m.normal = n;
        // Each sphere's support plane along the shared normal: exact for faces pressed flat together.
        m.depth = f.ra + f.rb - (f.cb - f.ca).dot(n);
        if (!(m.depth > -margin)) continue;
        // Across the normal the point is the smaller sphere's: a small part's corner on a large
        // face stays at the corner, not under the face's larger sphere beside it.
        const Eigen::Vector3d across = f.ra <= f.rb ? f.ca : f.cb;
        const Eigen::Vector3d support_b = f.cb - f.rb * n;
        m.on_b = across + (support_b - across).dot(n) * n;
        m.on_a = m.on_b + m.depth * n;
        all.push_back(m);
    }
    if (keep_pairs) { // the pairs that overlap, as the pairs effect lists them: without the margin
        const float grown = deep ? 0.0f : q.inflate; // a deep overlap's pairs came from the walk of the spheres as they are
        for (SpherePair p : pairs)
            if (p.depth > grown) p.depth -= grown, p.reach -= grown, out.pairs.push_back(p);
    }
    out.points = reduce_manifold(all, 0.25 * margin);
}

} // namespace spt::detail
