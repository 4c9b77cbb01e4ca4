#pragma once
/// Meshes made in code, for tests and benchmarks: consistently wound, model units
/// as given; closed except the sheet.
#include "spt/mesh.hpp"

namespace spt {

/// π, for the angles of the shapes made in code.
inline constexpr double kPi = 3.14159265358979323846;

/// Torus around the z axis: ring radius `ring`, tube radius `tube`, 2*nu*nv triangles.
TriangleMesh make_torus(double ring, double tube, int nu, int nv);
/// Ball of radius `radius` about the origin, faceted as a globe: nu meridians, nv bands from
/// pole to pole (2 nu (nv - 1) triangles).
TriangleMesh make_ball(double radius, int nu, int nv);
/// Axis-aligned box of the given half extents, each face an n x n grid (12 n^2 triangles).
TriangleMesh make_box(const Eigen::Vector3d& half, int n);
/// Open square sheet in the plane z = 0, side `size`, facing +z, an n x n grid (2 n^2 triangles).
TriangleMesh make_sheet(double size, int n);
/// A CAD-like part: a concave bracket profile with a rounded end, extruded along z.
/// Large flat faces (long thin cap triangles), sharp 90-degree edges.
TriangleMesh make_bracket();
/// Translated and uniformly scaled copy of `mesh` whose bounding box is centred at the
/// origin with its longest half side 1, i.e. scaled into [-1, 1]^3.
TriangleMesh scale_to_unit_cube(const TriangleMesh& mesh);

} // namespace spt
