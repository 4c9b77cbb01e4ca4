#pragma once
/// Exact geometric predicates on double coordinates: a floating-point filter
/// answers almost every call; when it cannot certify the sign, expansion
/// arithmetic (Shewchuk's method, written for this project) gives the exact sign.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace spt {

/// Sign (-1, 0, +1) of ((b - a) x (c - a)) . (d - a), exact for the given doubles.
/// Positive when d lies on the side of plane (a, b, c) that its normal (right-hand rule) points to.
int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, const Eigen::Vector3d& d);

/// Sign (-1, 0, +1) of (b - a) x (c - a) in 2D, exact: positive when a, b, c turn counter-clockwise.
int orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

/// The exact sign of orient3d computed without the filter (for tests of the filter).
int orient3d_exact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, const Eigen::Vector3d& d);

} // namespace spt
