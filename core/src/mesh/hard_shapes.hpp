#pragma once
/// Meshes made in code with the features that break collision models (docs/hard-cases.md):
/// thin parts, open and non-manifold surfaces, triangle soups. Model units as given.
#include "spt/mesh.hpp"
#include <cstdint>

namespace spt {

/// Closed tetrahedron with the given corners (wound outward by prepare_mesh).
TriangleMesh make_tetrahedron(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                              const Eigen::Vector3d& d);
/// Closed wedge (triangular prism): cross-section (-w, 0), (w, 0), (0, h) in x-z, ridge at
/// z = h along y from -l to l. h < 0 gives a ridge pointing down. 8 triangles.
TriangleMesh make_wedge(double w, double h, double l);
/// A 2 x 2 x 0.2 plate (z from -0.1 to 0.1) with a fin 0.02 thick, 1.6 long and about 1 tall
/// standing on it along y: two closed boxes, the fin sunk 0.05 into the plate.
TriangleMesh make_plate_with_fin();
/// A hub (a cube of half 0.15) with `blades` closed blades 1 long, 0.2 wide and `thickness` thick
/// around the y axis, from 0.1 to 1.1 out, sunk 0.05 into the hub: 1 + blades closed boxes.
TriangleMesh make_rotor(int blades, double thickness);
/// A unit cube body (half 0.5) with two ears, plates 0.02 thick sticking out 0.45 along +x and -x
/// (sunk 0.05 into the body): three closed boxes.
TriangleMesh make_body_with_ears();
/// Box of half extents `half` without the faces on its +z side (open at the top), n x n per face.
TriangleMesh make_open_box(const Eigen::Vector3d& half, int n);
/// Open tube (no end caps) around the z axis: radius r, from z = -l/2 to l/2, `segments` around.
TriangleMesh make_open_tube(double r, double l, int segments);
/// Non-manifold fan: `blades` rectangles 1 x 0.5 sharing their edge on the z axis (z from 0 to 1).
TriangleMesh make_fan(int blades);
/// Triangle soup: `count` unconnected triangles of side about `size` in the cube [-1, 1]^3.
TriangleMesh make_triangle_soup(int count, double size, uint32_t seed);
/// A closed box soup (every face its own vertices, welded by import) with one face pulled back
/// by `gap` from its edges: nearly closed, open along a slit all round that face.
TriangleMesh make_gapped_box(double half, double gap);

} // namespace spt
