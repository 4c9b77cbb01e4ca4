#pragma once
// The exact level's data of one object: its triangles and a tree of them bounded by spheres and boxes.
#include "spt/mesh.hpp"
#include "geometry/obb.hpp"
#include <vector>

namespace spt {

/// One node of the exact level's triangle tree (local frame, model units), in one 64-byte
/// cache line: a bounding sphere and an oriented box sharing one centre. A compact node is
/// pruned by its sphere and its slab along box axis 0 (least spread), an elongated one (`boxed`: a
/// rod, a sliver) by its whole box (docs/queries.md). The box's third axis is rebuilt from
/// the first two (third_axis), as it was fitted.
struct alignas(64) TriangleNode {
    float center[3] = {0, 0, 0};               ///< centre of the box and of the bounding sphere
    float radius = 0;                          ///< bounding-sphere radius
    float axis[2][3] = {{1, 0, 0}, {0, 1, 0}}; ///< the box's first two unit axes; axis 0 of least spread
    float half[3] = {-1, -1, -1};              ///< the box's half extents; negative: empty
    uint32_t first = 0;          ///< inner node: index of the right child; leaf: first slot in tri_order
    uint32_t count = 0;          ///< leaf: number of triangles (1, or up to 4 compact ones); inner node: 0
    uint32_t boxed = 0;          ///< 1: elongated, pruned by its box; 0: by its sphere and slab
    /// True for a leaf.
    bool is_leaf() const { return count != 0; }
    /// The node's box with all three axes.
    Obb box() const {
        Obb b;
        const Eigen::Vector3f w = third_axis(axis[0], axis[1]);
        for (int k = 0; k < 3; ++k) {
            b.center[k] = center[k], b.half[k] = half[k];
            b.axis[0][k] = axis[0][k], b.axis[1][k] = axis[1][k], b.axis[2][k] = w[k];
        }
        return b;
    }
};
static_assert(sizeof(TriangleNode) == 64, "one cache line a node");

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
    /// Per triangle: its plane, unit normal xyz and offset d (n . x = d), in float; a zero normal
    /// for a triangle without area. Empty at a deformed pose (the distance walk then goes without).
    std::vector<float> tri_plane;
    float plane_pad = 0;                      ///< the farthest any corner lies off its float plane
    size_t degenerate_triangles = 0;
    // The sphere level's patches of two-sided samples (query/sample_piece.cpp); empty when no
    // sphere is two-sided.
    std::vector<uint32_t> sphere_source;      ///< per CompactTree sphere: its sample's SampleSet::sources entry
    std::vector<uint32_t> vertex_face_start;  ///< faces around vertex v: vertex_faces[start[v], start[v + 1])
    std::vector<uint32_t> vertex_faces;          ///< zero-area triangles left out (their edges belong to neighbours)
};

} // namespace spt
