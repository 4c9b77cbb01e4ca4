#pragma once
// Angle-weighted vertex normals: what import computes for a mesh, and what a deformed pose of it
// computes again (anim/), so that both follow one rule.
#include "spt/mesh.hpp"
#include <vector>

namespace spt::detail {

// Twice the area at or below which a face of a mesh with this bounding-box diagonal is degenerate
// (import's rule; a pose of the mesh keeps it).
inline double degenerate_twice_area(double diagonal) { return 1e-14 * diagonal * diagonal; }

// Unit outward normal per vertex, the sum over its faces of the face's unit normal times the
// face's angle at the vertex; `valid` is 1 where that sum has a direction. Faces of twice-area
// at most `area_eps` contribute nothing; `skip` (per face, may be empty) leaves faces out.
void angle_weighted_normals(const std::vector<Eigen::Vector3d>& positions, const std::vector<Triangle>& triangles,
                            double area_eps, const std::vector<uint8_t>& skip, std::vector<Eigen::Vector3d>& normals,
                            std::vector<uint8_t>& valid);

} // namespace spt::detail
