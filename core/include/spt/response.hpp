#pragma once
/// Collision response (paper §3-4-3): how far B must move back against its
/// motion until the model no longer collides.
#include "spt/query.hpp"
#include <limits>

namespace spt {

/// How the backtrack distance is found.
enum class BacktrackRule {
    Exact, ///< smallest distance along -motion at which the model reports no collision
    Paper, ///< the paper's rule: the deepest sampling-sphere penetration (exact only along the contact normal)
};

/// No limit on how far a backtrack searches.
inline constexpr double kNoBacktrackLimit = std::numeric_limits<double>::infinity();

/// Result of a backtrack.
struct BacktrackResult {
    double distance = 0;   ///< model units along -motion; 0 without collision or without motion
    int queries = 0;       ///< collision queries run
    bool converged = true; ///< false if the iteration limit stopped the search
    bool beyond = false;   ///< the distance exceeds max_distance: then `distance` may be only a lower bound
};

/// Distance B must move along -motion (motion: B's movement relative to A, world
/// frame, any length) until the model at `options.level` reports no collision.
/// Levels `bounds` and `spheres`, rule Exact: solves |c1 - c2 - s*u| = r1 + r2 for every
/// overlapping pair and repeats from the largest root until no pair overlaps, so the
/// answer is exact for the sphere model (rounded up by 1e-6 of the pair's reach so a
/// float query at the answer agrees). Level `exact`: steps of 1% of B's diagonal, then
/// bisection to 1e-6 of the diagonal. A search that finds the distance is above
/// `max_distance` (model units) stops there with `beyond` set; below it, the answer is the
/// same, bit for bit, as without a limit.
BacktrackResult backtrack(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                          const Eigen::Vector3d& motion, const QueryOptions& options, BacktrackRule rule,
                          QueryScratch& scratch, double max_distance = kNoBacktrackLimit);

/// Same with B's pose and motion given in A's frame.
BacktrackResult backtrack_relative(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                                   const Eigen::Vector3d& motion_in_a, const QueryOptions& options,
                                   BacktrackRule rule, QueryScratch& scratch,
                                   double max_distance = kNoBacktrackLimit);

} // namespace spt
