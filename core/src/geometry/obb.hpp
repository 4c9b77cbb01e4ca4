#pragma once
/// Oriented bounding boxes of a node's triangles for the exact level. A bounding sphere
/// cannot tell a flat patch or a thin rod from a ball; near contact only a box along the
/// part's principal axes can prune such pairs, as FCL's OBB trees do (docs/queries.md).
#include <Eigen/Core>
#include <vector>

namespace spt {

/// Centre, three unit axes and half extents (model units, object frame); rounded outwards
/// so the float box still holds every double point it was fitted to.
struct Obb {
    float center[3] = {0, 0, 0};
    float axis[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; ///< axis[k]: unit vector of the box's k-th side
    float half[3] = {-1, -1, -1};                         ///< half extents; negative: empty, bounds nothing
};

/// Box along the principal axes of `points`, holding every point after float rounding. Its
/// third axis is third_axis(axis[0], axis[1]), so a box can be stored with two axes.
Obb fit_obb(const std::vector<Eigen::Vector3d>& points);
/// The box of `points` along given float axes (the first two; the third is third_axis of
/// them): what fit_obb does once it has chosen its axes. A refit keeps a node's axes.
Obb fit_obb_along(const std::vector<Eigen::Vector3d>& points, const float axes[2][3]);

/// u x v in float: a box's third axis from its first two (unit, up to float rounding).
inline Eigen::Vector3f third_axis(const float u[3], const float v[3]) {
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

/// Box `b` moved by x -> R x + t (centre and axes; the half extents stay).
Obb placed(const Obb& b, const Eigen::Matrix3f& R, const Eigen::Vector3f& t);

/// True if boxes `a` and `b` (one frame) are disjoint even with every extent grown by
/// `margin`, told by a separating axis among the six face normals of the two boxes
/// (conservative: a pair only an edge-edge axis separates is reported as overlapping).
/// An empty box is disjoint from everything.
bool obbs_disjoint(const Obb& a, const Obb& b, float margin);

/// Same with `b` given in B's frame, placed in A's by x -> R x + t.
bool obbs_disjoint(const Obb& a, const Obb& b, const Eigen::Matrix3f& R, const Eigen::Vector3f& t, float margin);

} // namespace spt
