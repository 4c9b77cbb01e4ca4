#pragma once
// Small meshes made in code for the render tests, so they depend on no mesh file.
#include "spt/mesh.hpp"
#include <string>

namespace spt::test {

// A torus around +Y: ring radius R, tube radius r, nu x nv vertices (2 nu nv triangles).
TriangleMesh torus(double R, double r, int nu, int nv);

// A little figure of subdivided boxes, about 2 units tall, standing on y = 0: a nose
// points to +Z and the +X arm is raised, so every view can be told apart.
TriangleMesh box_figure();

// Writes the mesh as Wavefront OBJ (positions and triangles only).
void write_obj(const TriangleMesh& mesh, const std::string& path);
// Writes the mesh as binary little-endian PLY (float positions, int triangles).
void write_ply(const TriangleMesh& mesh, const std::string& path);

} // namespace spt::test
