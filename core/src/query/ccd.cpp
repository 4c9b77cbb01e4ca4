// Continuous detection by bisection of time with conservatively grown spheres.
#include "spt/ccd.hpp"
#include "query/pending_pose.hpp"
#include "query/query_run.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace spt {
namespace {

// Model units: never a float query with a larger growth (its squares stay far below
// float's largest, so none overflows into a missed contact).
constexpr double kMaxGrow = 1e18;
constexpr int kMaxQueries = 100000; // a guard: a 1e-4 object 1e6 from the origin needs over 20,000 near contact

struct Ccd {
    const CollisionModel& a;
    const CollisionModel& b;
    const Pose& p0;
    const Pose& p1;
    QueryOptions q;
    QueryScratch& scratch;
    double speed, tol;
    double max_grow;    // largest growth asked of a float query: the models' size, at most kMaxGrow
    double end0, end1;  // largest translation component at each end
    CcdResult r;

    bool may_touch(double t, double grow) {
        const Pose p = interpolate(p0, p1, t);
        // Ruled out in double first, so a growth of any size answers without a float that
        // overflows; a growth too large for float that this cannot rule out may touch.
        const Eigen::Matrix3d rot = p.rotation.toRotationMatrix();
        if (std::isnan(grow)) return true; // 0 x infinite speed: nothing can be ruled out
        // The interpolated translation is off by a few ulps of what it sums, |t0| + t |t1 - t0|
        // (bounded by |t0| + t (|t0| + |t1|), which cannot overflow), not of the far end.
        const double place_error = 8 * std::numeric_limits<double>::epsilon() * (end0 + t * (end0 + end1));
        if (cannot_meet(a, b, local_translation(a, b, rot, p.translation), grow + place_error)) return false;
        // Grown by more than the models' size, the float query would round the geometry away
        // against the growth (a contact lost at the last bit); the bound in double is as tight.
        if (grow > max_grow) return true;
        q.inflate = grow > 0 ? std::nextafter(float(grow), std::numeric_limits<float>::infinity()) : 0.0f;
        const QueryResult res = collide_relative(a, b, p, q, scratch);
        ++r.queries;
        r.counters.node_pairs += res.counters.node_pairs;
        r.counters.bound_tests += res.counters.bound_tests;
        r.counters.sphere_tests += res.counters.sphere_tests;
        return res.collide;
    }

    // Earliest time in [lo, hi] that cannot be ruled out, or -1. Also gives up at lo
    // (conservative: nothing is ruled out after it) when the interval cannot be halved in
    // double or the query budget is spent, so a huge speed cannot make it run for ever.
    double search(double lo, double hi) {
        const double half = 0.5 * (hi - lo), grow = half * speed;
        if (!may_touch(lo + half, grow)) return -1;
        if (grow <= tol || !(lo + half > lo && lo + half < hi) || r.queries >= kMaxQueries) return lo;
        const double first = search(lo, lo + half);
        return first >= 0 ? first : search(lo + half, hi);
    }
};

} // namespace

CcdResult first_contact(const CollisionModel& a, const CollisionModel& b, const Pose& b0_in_a, const Pose& b1_in_a,
                        const CcdOptions& options, QueryScratch& scratch) {
    detail::settle(a), detail::settle(b); // a lazy pose is posed in full first
    QueryOptions q;
    q.level = options.level == QueryLevel::Bounds ? QueryLevel::Bounds : QueryLevel::Spheres;
    q.mode = QueryMode::Any;
    q.normal_culling = options.normal_culling;
    q.cull_cos = options.cull_cos;
    const double diag = b.diagonal() > 0 ? b.diagonal() : 2 * b.extent();
    const double tol = options.tolerance > 0 ? options.tolerance : 1e-4 * diag;
    check_pose(b0_in_a, "start pose of B");
    check_pose(b1_in_a, "end pose of B");
    const Pose p0{unit_rotation(b0_in_a.rotation), b0_in_a.translation};
    const Pose p1{unit_rotation(b1_in_a.rotation), b1_in_a.translation};
    // stableNorm: a difference near the largest double still has a length (or infinity,
    // which the search treats as "anything may move anywhere").
    const double speed = (p1.translation - p0.translation).stableNorm() + rotation_angle(p0, p1) * b.reach();
    const double max_grow = std::min(kMaxGrow, std::max(tol, model_radius(a) + model_radius(b)));
    Ccd c{a, b, p0, p1, q, scratch, speed, tol, max_grow,
          p0.translation.cwiseAbs().maxCoeff(), p1.translation.cwiseAbs().maxCoeff(), {}};
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
