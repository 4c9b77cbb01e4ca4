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

} // namespace spt::detail
