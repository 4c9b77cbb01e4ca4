#pragma once
/// Exact intersection test of two closed triangles (Guigue & Devillers 2003),
/// decided only by exact orientation predicates, so touching counts and no
/// rounding can flip the answer for the given double coordinates.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace spt {

/// True if closed triangles (p1, q1, r1) and (p2, q2, r2) share at least one point.
/// A triangle whose corners are collinear (zero area) never intersects: its edges
/// belong to its non-degenerate neighbours in a mesh.
bool triangles_intersect(const Eigen::Vector3d& p1, const Eigen::Vector3d& q1, const Eigen::Vector3d& r1,
                         const Eigen::Vector3d& p2, const Eigen::Vector3d& q2, const Eigen::Vector3d& r2);

/// True if the three points are collinear (exactly).
bool is_degenerate_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

} // namespace spt
