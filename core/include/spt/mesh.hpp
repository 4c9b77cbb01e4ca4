#pragma once
/// Triangle meshes as spt uses them: welded, indexed, consistently wound,
/// with angle-weighted vertex normals. Units are the model's own; the frame
/// is the file's root frame with every node transform applied.
#include "spt/task_system.hpp"
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace spt {

/// A triangle as three vertex indices, counter-clockwise seen from outside.
using Triangle = std::array<uint32_t, 3>;

/// An indexed triangle mesh in its own (object) frame.
struct TriangleMesh {
    std::string name;                       ///< file name the mesh came from (no directory)
    std::vector<Eigen::Vector3d> positions; ///< welded vertex positions, model units
    std::vector<Triangle> triangles;        ///< counter-clockwise seen from outside, after fixes
    std::vector<Eigen::Vector3d> normals;   ///< unit outward vertex normals; zero where !normal_valid
    std::vector<uint8_t> normal_valid;      ///< 1 where the vertex has a computable normal
    std::vector<uint32_t> welded_index;     ///< for each vertex as the file had it, its welded vertex
    std::vector<uint8_t> on_open_part;      ///< per triangle: 1 if its part (faces joined by edges) has a
                                            ///< boundary or non-manifold edge; empty: unknown, treated as open
    std::vector<uint8_t> is_copy;           ///< per triangle: 1 for a later copy of a face (the same three
                                            ///< vertices, either winding), left out of the topology, the
                                            ///< normals and the samples; empty: no copies

    /// Axis-aligned bounds of the vertex positions (min, max); zero box if empty.
    std::pair<Eigen::Vector3d, Eigen::Vector3d> bounds() const;
    /// Length of the bounding-box diagonal, model units.
    double diagonal() const;
    /// Whether float coordinates lose the mesh's detail where it lies: its farthest coordinate is
    /// beyond 8 times its largest side (then it is read, sampled and drawn relative to a point near it).
    bool far_for_float() const;
    /// Whether triangle f is a later copy of an earlier face (is_copy), to be left out.
    bool copies_earlier_face(size_t f) const { return f < is_copy.size() && is_copy[f]; }
    /// Stable 64-bit hash of positions (as float32) and triangles; identifies the mesh in .spt files.
    uint64_t content_hash() const;
};

/// Volume, centre of mass and inertia of a closed mesh at density 1 (mass_properties).
struct SolidMass {
    double volume = 0;                                 ///< model units^3
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();   ///< centre of mass, object frame
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about the centre, object axes, per unit density
};

/// Mass properties of the solid a closed mesh bounds (divergence theorem over its triangles; later
/// copies of a face left out). Throws Error(BadInput) naming the mesh if it encloses no positive volume.
SolidMass mass_properties(const TriangleMesh& mesh);

/// What import found and fixed. Counts refer to the welded mesh.
struct ImportReport {
    size_t file_vertices = 0;         ///< vertices before welding (all meshes of the file)
    size_t vertices = 0;              ///< after welding
    size_t faces = 0;                 ///< triangles kept
    size_t welded = 0;                ///< file_vertices - vertices
    size_t degenerate_faces = 0;      ///< zero-area or repeated-index faces (kept, ignored for normals)
    size_t needle_faces = 0;          ///< not degenerate, but narrower than 1e-6 of their longest edge
    size_t duplicate_faces = 0;       ///< the same three vertices as an earlier face, either winding (kept)
    size_t unreferenced_vertices = 0; ///< welded vertices used by no face (left out of sampling)
    size_t skipped_primitives = 0;    ///< points and lines dropped by import
    size_t boundary_edges = 0;        ///< edges used by one face
    size_t nonmanifold_edges = 0;     ///< edges used by three or more faces
    size_t components = 0;            ///< face-connected components
    bool closed = false;              ///< no boundary and no non-manifold edges
    size_t flipped_faces = 0;         ///< faces re-wound to agree with their neighbours
    size_t inverted_components = 0;   ///< closed components turned right side out
    size_t flat_closed_parts = 0;     ///< closed parts that enclose no volume, sampled as open sheets
    size_t vertices_without_normal = 0; ///< left out of sampling
    std::vector<std::string> fixes;   ///< one sentence per fix applied
    std::vector<std::string> warnings; ///< one sentence per problem left in place
};

/// A mesh and the report of how it was read.
struct ImportedMesh {
    TriangleMesh mesh;   ///< the prepared mesh
    ImportReport report; ///< what import found and fixed
};

/// Options for import_mesh.
struct ImportOptions {
    double weld_tolerance = 1e-6; ///< weld distance, as a fraction of the bounding-box diagonal
    bool fix_orientation = true;  ///< re-wind inconsistent faces, turn inside-out closed parts around
    int threads = 0;              ///< threads to prepare the mesh on (0: the machine's cores); the mesh is the same on any count
    TaskSystem* tasks = nullptr;  ///< a host's threads to run that work on (spt/task_system.hpp); null: the library's pool
    /// Another thread sets it to stop the import: assimp's reading of the file then ends within
    /// one buffered read (a file read whole is still parsed to its end), and preparing the mesh
    /// looks at it as it welds and after each step; throws Cancelled. Null: never stops.
    const std::atomic<bool>* cancel = nullptr;
};

/// Largest vertex coordinate prepare_mesh accepts (model units): beyond it a double keeps
/// no digit below 1, and a model's squared sizes would overflow float.
constexpr double kMaxMeshCoordinate = 1e16;
/// Smallest bounding-box diagonal prepare_mesh accepts (model units): below it squared
/// distances in float lose their digits (subnormal) or vanish.
constexpr double kMinMeshDiagonal = 1e-15;

/// Reads every mesh of a file assimp understands, applies node transforms, welds,
/// fixes orientation and computes normals. Throws Error(BadInput) naming the file.
ImportedMesh import_mesh(const std::string& path, const ImportOptions& options = {});

/// Welds, checks topology, fixes orientation and computes normals of raw triangles
/// (as import_mesh does after reading). `name` is used in messages. Throws Error(BadInput)
/// for a non-finite coordinate or one beyond kMaxMeshCoordinate, an index out of range, a
/// diagonal below kMinMeshDiagonal, or no non-degenerate face.
ImportedMesh prepare_mesh(std::string name, std::vector<Eigen::Vector3d> positions,
                          std::vector<Triangle> triangles, const ImportOptions& options = {});

} // namespace spt
