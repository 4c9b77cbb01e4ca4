// Continuous detection by bisection of time with conservatively grown spheres.
#include "spt/ccd.hpp"
#include <cmath>
#include <limits>

namespace spt {
namespace {

struct Ccd {
    const CollisionModel& a;
    const CollisionModel& b;
    const Pose& p0;
    const Pose& p1;
    QueryOptions q;
    QueryScratch& scratch;
    double speed, tol;
    CcdResult r;

    bool may_touch(double t, double grow) {
        q.inflate = grow > 0 ? std::nextafter(float(grow), std::numeric_limits<float>::infinity()) : 0.0f;
        const QueryResult res = collide_relative(a, b, interpolate(p0, p1, t), q, scratch);
        ++r.queries;
        r.counters.node_pairs += res.counters.node_pairs;
        r.counters.bound_tests += res.counters.bound_tests;
        r.counters.sphere_tests += res.counters.sphere_tests;
        return res.collide;
    }

    // Earliest time in [lo, hi] that cannot be ruled out, or -1.
    double search(double lo, double hi) {
        const double half = 0.5 * (hi - lo), grow = half * speed;
        if (!may_touch(lo + half, grow)) return -1;
        if (grow <= tol) return lo;
        const double first = search(lo, lo + half);
        return first >= 0 ? first : search(lo + half, hi);
    }
};

} // namespace

CcdResult first_contact(const CollisionModel& a, const CollisionModel& b, const Pose& b0_in_a, const Pose& b1_in_a,
                        const CcdOptions& options, QueryScratch& scratch) {
    QueryOptions q;
    q.level = options.level == QueryLevel::Bounds ? QueryLevel::Bounds : QueryLevel::Spheres;
    q.mode = QueryMode::Any;
    q.normal_culling = options.normal_culling;
    q.cull_cos = options.cull_cos;
    const double diag = b.diagonal() > 0 ? b.diagonal() : 2 * b.extent();
    const double tol = options.tolerance > 0 ? options.tolerance : 1e-4 * diag;
    const double speed =
        (b1_in_a.translation - b0_in_a.translation).norm() + rotation_angle(b0_in_a, b1_in_a) * b.reach();
    Ccd c{a, b, b0_in_a, b1_in_a, q, scratch, speed, tol, {}};
    if (c.may_touch(0, 0)) {
        c.r.hit = true, c.r.toi = 0;
        return c.r;
    }
    if (speed > 0) {
        const double t = c.search(0, 1);
        if (t >= 0) c.r.hit = true, c.r.toi = t;
    }
    return c.r;
}

} // namespace spt
