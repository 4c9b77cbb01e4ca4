#pragma once
// The exact level's distance: the triangles of A and B, nearest pair by branch and bound.
#include "spt/distance.hpp"

namespace spt::detail {

// distance_relative at level exact for models that do not collide there (the caller asked); B's
// pose in A's frame. Fills distance, points (A's frame), beyond and the counters' node pairs,
// bound tests and triangle tests (added to what `res` holds).
void exact_gap(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a, const DistanceOptions& options,
               QueryScratch& scratch, DistanceResult& res);

} // namespace spt::detail
