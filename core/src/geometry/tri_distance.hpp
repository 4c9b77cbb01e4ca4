#pragma once
/// Closest points between two triangles, for the exact level's distance query: the same
/// answer as FCL's TriangleDistance, in double.
#include <Eigen/Core>
#include <limits>

namespace spt {

/// Closest points of two closed triangles.
struct TriangleGap {
    double distance = 0;     ///< 0 when the triangles meet (model units)
    Eigen::Vector3d p, q;    ///< a closest point on the first and on the second triangle
};

/// Distance and closest points of triangles (a0, a1, a2) and (b0, b1, b2); triangles that
/// meet (decided exactly) answer 0 and a common point. A zero-area triangle counts as its edges.
/// `may_meet` false: the caller knows they do not cross (the exact test is skipped). `limit`: only
/// a distance below it is of use; at or above it the answer is some distance >= limit.
TriangleGap triangle_gap(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1, const Eigen::Vector3d& a2,
                         const Eigen::Vector3d& b0, const Eigen::Vector3d& b1, const Eigen::Vector3d& b2,
                         bool may_meet = true, double limit = std::numeric_limits<double>::infinity());

/// Closest point of segment [p0, p1] to x is p0 + s (p1 - p0); returns s in [0, 1].
double segment_closest_parameter(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& x);

/// Closest points of segments [p0, p1] and [q0, q1]: p0 + s (p1 - p0) and q0 + t (q1 - q0).
/// Returns the squared distance; parallel and degenerate segments are handled.
double segments_closest(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& q0,
                        const Eigen::Vector3d& q1, double& s, double& t);

/// Closest point of triangle (a, b, c) to x (Ericson's Voronoi-region walk; degenerate triangles allowed).
Eigen::Vector3d triangle_closest_point(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                       const Eigen::Vector3d& x);

} // namespace spt
