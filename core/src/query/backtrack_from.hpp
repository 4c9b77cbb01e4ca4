#pragma once
// The backtrack of rule Exact when its first query has already been run by the caller.
#include "spt/response.hpp"
#include <vector>

namespace spt::detail {

/// As backtrack (rule Exact, level bounds or spheres, `pose_a` and `pose_b` in the world), but
/// the query at the start pose is not run again: `start_pairs` are the overlapping pairs an `all`
/// query of these options (inflate 0) found at exactly these poses, non-empty. The answer is
/// the same, bit for bit, as backtrack's (with the same `max_distance`).
BacktrackResult backtrack_from_pairs(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b,
                                     const Pose& pose_b, const Eigen::Vector3d& motion, const QueryOptions& options,
                                     const std::vector<SpherePair>& start_pairs, QueryScratch& scratch,
                                     double max_distance = kNoBacktrackLimit);

/// As backtrack (rule Exact, `pose_a` and `pose_b` in the world) for a deep overlap, whose spheres
/// overlap at these poses: at level spheres (no culling, no two-sided spheres, inflate 0) the
/// first jump goes to the largest exit root of every sphere pair along the motion, found by branch
/// and bound, instead of to the largest of the pairs overlapping now; the looks go on from there.
/// The same distance as backtrack's within the looks' rounding up (a millionth of a reach a look)
/// unless the models, once parted along the motion, would meet again further on (docs/queries.md,
/// "Deep overlaps"). Elsewhere backtrack's answer. With an `allowance` > 0 (model units) the
/// branch and bound skips pairs that cannot part later than the best by more, and its answer (at
/// most that much late, never early) is returned without a look; a `seed` pair (say the deepest,
/// may be null) is where it starts.
BacktrackResult deep_backtrack(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                               const Eigen::Vector3d& motion, const QueryOptions& options, QueryScratch& scratch,
                               double max_distance = kNoBacktrackLimit, double allowance = 0,
                               const SpherePair* seed = nullptr);

} // namespace spt::detail
