#pragma once
/// How far apart two objects are (motion planners ask this more than "collide?"): the smallest
/// gap between the sampling spheres of A and B, or, when they overlap, the negative of the
/// deepest overlap. B's pose in A's frame; model units.
#include "spt/query.hpp"
#include <limits>

namespace spt {

/// Options of a distance query.
struct DistanceOptions {
    /// Spheres (the sampling spheres), Bounds (the leaf bounding spheres) or Exact (the triangles:
    /// both models need their meshes).
    QueryLevel level = QueryLevel::Spheres;
    /// Gaps beyond this are not looked for: a pair farther apart answers `beyond` (model units, > 0).
    double max_distance = std::numeric_limits<double>::infinity();
    /// The search stops when no unvisited pair can be closer than (1 - this) x the best gap found:
    /// 0 gives the smallest gap, 0.05 one within 5% of it.
    double relative_error = 0;
    /// The search also stops when no unvisited pair can be nearer than the best gap minus this
    /// (model units, >= 0; FCL's abs_err): the answer is then at most this above the smallest gap.
    /// Both allowances together: no pair left below (1 - relative_error) x best - absolute_error.
    double absolute_error = 0;
    /// False: overlapping objects are only told apart from the rest (an `any` query, as FCL's
    /// distance answers 0 for meshes that meet): distance 0, collide, points NaN. A planner that
    /// needs the clearance of free poses skips the deepest overlap's walk on the others.
    bool depth = true;
};

/// Answer of a distance query.
struct DistanceResult {
    bool collide = false;  ///< the spheres overlap (distance <= 0)
    bool beyond = false;   ///< farther apart than max_distance: distance is +infinity and the points unset
    /// Apart: the gap between the nearest two spheres' surfaces (at Exact: triangles). Overlapping:
    /// minus the deepest overlap (the depth of collide_relative's mode deepest). Model units.
    double distance = std::numeric_limits<double>::infinity();
    /// On A's sphere, A's frame: nearest (apart) or deepest inside B; NaN when overlapping without depth.
    Eigen::Vector3d point_a = Eigen::Vector3d::Zero();
    Eigen::Vector3d point_b = Eigen::Vector3d::Zero(); ///< on B's sphere, A's frame
    QueryCounters counters; ///< node pairs and sphere tests walked
};

/// Distance of B at `b_in_a` from A (A at the identity). Const and thread-safe given one scratch a
/// thread. Error(Usage) for bad options, or level Exact without both meshes.
DistanceResult distance_relative(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                                 const DistanceOptions& options, QueryScratch& scratch);

} // namespace spt
