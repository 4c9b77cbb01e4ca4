#pragma once
// The exact level's data of one object: its triangles and a tree of them bounded by spheres and boxes.
#include "spt/mesh.hpp"
#include "geometry/obb.hpp"
#include <vector>

namespace spt {

/// One node of the exact level's triangle tree (local frame, model units, 76 bytes).
struct TriangleNode {
    float center[3] = {0, 0, 0}; ///< bounding-sphere centre of the triangles below
    float radius = 0;            ///< bounding-sphere radius
    Obb box;                     ///< principal-axis box holding the triangles below
    uint32_t first = 0;          ///< inner node: index of the right child; leaf: first slot in tri_order
    uint32_t count = 0;          ///< leaf: number of triangles (1 to 4); inner node: 0
    /// True for a leaf.
    bool is_leaf() const { return count != 0; }
};

/// The mesh of an object for the `exact` level, with its own triangle tree. The
/// sampling tree is the wrong hierarchy for triangles: a CAD face sampled to a
/// tolerance spans thousands of samples, and a bounding sphere cannot separate two
/// flat patches face to face, nor two thin rods side by side; a tree of triangles bounded
/// by spheres and oriented boxes can.
struct ExactData {
    std::vector<Eigen::Vector3d> positions;   ///< mesh vertices, model units
    std::vector<Triangle> triangles;          ///< mesh triangles
    std::vector<uint8_t> closed;              ///< per triangle: 1 if its part is closed (bounds a solid)
    std::vector<TriangleNode> tri_nodes;      ///< root first, depth-first (the left child follows its parent)
    std::vector<uint32_t> tri_order;          ///< triangle indices; a leaf holds tri_order[first, first + count)
    std::vector<float> tri_sphere;            ///< per triangle: centre xyz and radius of a bounding sphere
    size_t degenerate_triangles = 0;          ///< zero-area triangles left out (their edges belong to neighbours)
};

} // namespace spt
