// Backtrack along the motion (paper §3-4-3, made exact for the sphere model).
#include "spt/response.hpp"
#include "query/backtrack_from.hpp"
#include "query/query_run.hpp"
#include <algorithm>
#include <cmath>

namespace spt {
namespace {

// Steps of 1% of the diagonal taken before giving up (100 diagonals plus the two extents).
constexpr int kMaxSteps = 10200;

// Steps of 1% of the larger diagonal from `start` (where the model collides), then bisection
// to 1e-6 of it: for the exact level, and for a sphere model held by containment alone.
// A step that starts past `max_distance` ends the search: the answer lies beyond it.
BacktrackResult by_bisection(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                             const Eigen::Vector3d& back, const QueryOptions& options, QueryScratch& scratch,
                             double max_distance, double start = 0, int queries = 0) {
    BacktrackResult r;
    r.queries = queries;
    QueryOptions q = options;
    q.mode = QueryMode::Any;
    auto collides = [&](double s) {
        Pose p = b_in_a;
        p.translation += s * back;
        ++r.queries;
        return collide_relative(a, b, p, q, scratch).collide;
    };
    if (start == 0 && !collides(0)) return r;
    double diag = std::max({a.diagonal(), b.diagonal(), 2 * a.extent(), 2 * b.extent()});
    if (!(diag > 0)) diag = std::max(1.0, start); // no size to step by (a point model): any length serves
    const double step = 0.01 * diag;
    // Bounded counts, not only lengths: far from s = 0 a step or a halving can be below
    // the rounding of s, and a loop on lengths alone would never end.
    double lo = start, hi = start + step;
    for (int k = 0; collides(hi); ++k) {
        lo = hi, hi += step;
        if (lo > max_distance) { // collides at lo: the answer is past it
            r.distance = lo;
            r.beyond = true;
            return r;
        }
        if (k >= kMaxSteps || !(hi > lo)) {
            r.converged = false;
            break;
        }
    }
    for (int k = 0; r.converged && hi - lo > 1e-6 * diag && k < 64; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break; // no double between them: as close as it gets
        (collides(mid) ? lo : hi) = mid;
    }
    r.distance = hi;
    r.beyond = hi > max_distance;
    return r;
}

// Rule Exact at levels bounds and spheres. Every pair overlapping at s keeps overlapping until
// its own exit root, so the model collides on [s, largest root): jump there (and a millionth
// of that pair's reach past it) and look again. Each look asks only for the largest root
// (collide_exit), not for every overlapping pair.
// `start_pairs`: the pairs at s = 0 when the caller has them (then that query is not run).
// A jump past `max_distance` ends the search: the answer is at least that jump.
BacktrackResult by_exit_roots(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                              const Eigen::Vector3d& back, const QueryOptions& options,
                              const std::vector<SpherePair>* start_pairs, QueryScratch& scratch,
                              double max_distance) {
    BacktrackResult r;
    const bool bounds = options.level == QueryLevel::Bounds;
    double s = 0;
    for (int it = 0; it < 100000; ++it) {
        Pose p = b_in_a;
        p.translation += s * back;
        detail::ExitSearch exit;
        exit.back = back;
        if (it == 0 && start_pairs) {
            // As collide_exit would answer from these pairs: B's centres moved as the walk's
            // exit roots move them, once a sphere (a sphere is in many pairs).
            const Eigen::Matrix3d rot = unit_rotation(p.rotation).toRotationMatrix();
            const Eigen::Vector3d t = local_translation(a, b, rot, p.translation); // the centres are local
            detail::SphereMemo<Eigen::Vector3d>& moved = detail::buffers_of(scratch).memo_b;
            moved.start(std::max(b.tree().nodes().size(), b.tree().sphere_count()));
            for (const SpherePair& pair : *start_pairs) {
                const Eigen::Vector3d ca = detail::pair_centre(a.tree(), bounds, pair.node_a, pair.a);
                const Eigen::Vector3d& cb = moved.get(pair.b, [&] {
                    return Eigen::Vector3d(rot * detail::pair_centre(b.tree(), bounds, pair.node_b, pair.b) + t);
                });
                const Eigen::Vector3d w = cb - ca;
                const double reach = pair.reach;
                // A pair that parts before the best root so far is skipped without its square root.
                if (exit.found && !detail::exit_may_reach(w, reach, back, exit.root)) continue;
                detail::keep_exit(exit, detail::exit_root(w, reach, back), reach);
            }
        } else {
            ++r.queries;
            if (!collide_exit(a, b, p, options, exit, scratch).collide) {
                r.distance = s;
                return r;
            }
            // Held by containment alone (no sphere pairs to solve): step out instead.
            if (!exit.found) return by_bisection(a, b, b_in_a, back, options, scratch, max_distance, s, r.queries);
        }
        const double next = s + std::max(0.0, exit.root) + 1e-6 * exit.reach;
        if (!(next > s) || !std::isfinite(next)) break; // s no longer moves: report unconverged
        if (next > max_distance) {
            r.distance = next;
            r.beyond = true;
            return r;
        }
        s = next;
    }
    r.converged = false;
    r.distance = s;
    return r;
}

// Any finite non-zero motion gives a direction: scaled by its largest component before
// normalising, so 1e-300 and 1e300 are directions like 1. Zero without one.
Eigen::Vector3d back_direction(const Eigen::Vector3d& motion) {
    const double big = motion.cwiseAbs().maxCoeff();
    if (!(big > 0) || !std::isfinite(big)) return Eigen::Vector3d::Zero();
    return -(motion / big).normalized();
}

// backtrack_relative; `start_pairs` (may be null) as for backtrack_from_pairs.
BacktrackResult relative(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                         const Eigen::Vector3d& motion_in_a, const QueryOptions& options, BacktrackRule rule,
                         const std::vector<SpherePair>* start_pairs, QueryScratch& scratch, double max_distance) {
    BacktrackResult r;
    const Eigen::Vector3d back = back_direction(motion_in_a);
    if (back.isZero()) return r; // no motion: no direction to move back along
    QueryOptions q = options;
    if (rule == BacktrackRule::Paper) {
        q.mode = QueryMode::Deepest;
        const QueryResult res = collide_relative(a, b, b_in_a, q, scratch);
        r.queries = 1;
        r.distance = res.collide ? std::max(0.0, res.deepest.depth) : 0;
        r.beyond = r.distance > max_distance;
        return r;
    }
    if (options.level == QueryLevel::Exact) return by_bisection(a, b, b_in_a, back, options, scratch, max_distance);
    return by_exit_roots(a, b, b_in_a, back, options, start_pairs, scratch, max_distance);
}

// backtrack; `start_pairs` (may be null) as for backtrack_from_pairs.
BacktrackResult in_world(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                         const Eigen::Vector3d& motion, const QueryOptions& options, BacktrackRule rule,
                         const std::vector<SpherePair>* start_pairs, QueryScratch& scratch, double max_distance) {
    check_pose(pose_a, "pose of A");
    check_pose(pose_b, "pose of B");
    const Pose ua{unit_rotation(pose_a.rotation), pose_a.translation};
    const Pose ub{unit_rotation(pose_b.rotation), pose_b.translation};
    return relative(a, b, relative_pose(ua, ub), ua.rotation.conjugate() * motion, options, rule, start_pairs, scratch,
                    max_distance);
}

} // namespace

BacktrackResult backtrack_relative(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                                   const Eigen::Vector3d& motion_in_a, const QueryOptions& options,
                                   BacktrackRule rule, QueryScratch& scratch, double max_distance) {
    return relative(a, b, b_in_a, motion_in_a, options, rule, nullptr, scratch, max_distance);
}

BacktrackResult backtrack(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                          const Eigen::Vector3d& motion, const QueryOptions& options, BacktrackRule rule,
                          QueryScratch& scratch, double max_distance) {
    return in_world(a, pose_a, b, pose_b, motion, options, rule, nullptr, scratch, max_distance);
}

} // namespace spt

namespace spt::detail {

BacktrackResult backtrack_from_pairs(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b,
                                     const Pose& pose_b, const Eigen::Vector3d& motion, const QueryOptions& options,
                                     const std::vector<SpherePair>& start_pairs, QueryScratch& scratch,
                                     double max_distance) {
    return in_world(a, pose_a, b, pose_b, motion, options, BacktrackRule::Exact, &start_pairs, scratch, max_distance);
}

} // namespace spt::detail
