#pragma once
// Smallest enclosing sphere of a few points (Welzl), for leaves whose spheres share a radius.
#include <Eigen/Core>
#include <vector>

namespace spt::detail {

struct Ball {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    double radius = -1; // empty
};

/// Exact smallest ball containing points[0, n), which it reorders; expected linear time,
/// deterministic order.
Ball smallest_ball(Eigen::Vector3d* points, size_t n);

/// Smallest ball containing two balls.
Ball merge_balls(const Ball& a, const Ball& b);

} // namespace spt::detail
