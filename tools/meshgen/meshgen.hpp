#pragma once
/// Procedural meshes the project makes itself: test subjects, bundled resources and
/// benchmark inputs. Every generator is deterministic, closed, outward-wound.
#include "spt/mesh.hpp"
#include <string>

namespace spt::meshgen {

/// Raw triangles before spt's import pipeline.
struct RawMesh {
    std::vector<Eigen::Vector3d> positions;
    std::vector<Triangle> triangles;
    /// Appends another mesh, moved by `offset`.
    void append(const RawMesh& other, const Eigen::Vector3d& offset = Eigen::Vector3d::Zero());
};

/// Torus around +z: ring radius R, tube radius r, nu segments around the ring, nv around the tube
/// (spt::make_torus, welded).
RawMesh torus(double R, double r, int nu, int nv);
/// Axis-aligned box centred at the origin with sides (sx, sy, sz), each face an n x n grid
/// (spt::make_box, welded).
RawMesh box(double sx, double sy, double sz, int n = 1);
/// Sphere of radius r from an icosahedron subdivided `level` times.
RawMesh icosphere(double r, int level);
/// Sphere of radius r by longitude and latitude: `slices` around +z, `stacks` from pole to pole,
/// 2 * slices * (stacks - 1) triangles (16 x 16: the 480-triangle ball of issue 37's scenes).
RawMesh uv_sphere(double r, int slices, int stacks);
/// Cylinder along +z from z=0 to z=h, radius r, `seg` sides, flat caps (sharp edges).
RawMesh cylinder(double r, double h, int seg);
/// A standing figure built from primitives (body, head, arms, legs, feet); y-up, height ~1.74, feet at y=0.
RawMesh figure();
/// A CAD-like part, y-up: a plate with two bosses and a rib; large flat faces and sharp edges.
RawMesh cad_part();

/// Writes Wavefront OBJ (text, 1-based indices, %.9g coordinates).
void write_obj(const RawMesh& m, const std::string& path);
/// Writes binary STL (unindexed float32 triangles, like most CAD exports).
void write_stl(const RawMesh& m, const std::string& path);
/// Writes binary little-endian PLY.
void write_ply(const RawMesh& m, const std::string& path);

/// Runs spt's preparation (weld, orientation, normals) on a raw mesh.
ImportedMesh prepare(const RawMesh& m, const std::string& name);

} // namespace spt::meshgen
