#pragma once
/// What a query needs of one object: the compact sampling tree and, for the
/// `exact` level, the mesh's triangles assigned to the tree's active nodes.
/// Immutable after construction; share one model between threads freely.
#include "spt/compact_tree.hpp"
#include "spt/mesh.hpp"
#include "spt/slab.hpp"
#include "spt/spt_file.hpp"
#include <string>
#include <vector>

namespace spt {

/// One node of the exact level's triangle tree (object frame, model units, 44 bytes).
struct TriangleNode {
    float center[3] = {0, 0, 0}; ///< bounding-sphere centre of the triangles below
    float radius = 0;            ///< bounding-sphere radius
    Slab slab;                   ///< thinnest slab holding the triangles below
    uint32_t first = 0;          ///< inner node: index of the right child; leaf: first slot in tri_order
    uint32_t count = 0;          ///< leaf: number of triangles (1 to 4); inner node: 0
    /// True for a leaf.
    bool is_leaf() const { return count != 0; }
};

/// The mesh of an object for the `exact` level, with its own triangle tree. The
/// sampling tree is the wrong hierarchy for triangles: a CAD face sampled to a
/// tolerance spans thousands of samples, and a bounding sphere cannot separate two
/// flat patches face to face; a tree of triangles bounded by spheres and slabs can.
struct ExactData {
    std::vector<Eigen::Vector3d> positions;   ///< mesh vertices, model units
    std::vector<Triangle> triangles;          ///< mesh triangles
    std::vector<TriangleNode> tri_nodes;      ///< root first, depth-first (the left child follows its parent)
    std::vector<uint32_t> tri_order;          ///< triangle indices; a leaf holds tri_order[first, first + count)
    std::vector<float> tri_sphere;            ///< per triangle: centre xyz and radius of a bounding sphere
    size_t degenerate_triangles = 0;          ///< zero-area triangles left out (their edges belong to neighbours)
};

/// One object ready for queries.
class CollisionModel {
public:
    CollisionModel() = default;
    /// Model of tree `tree_name` (first tree if empty) of `doc`; no `exact` level.
    explicit CollisionModel(const SptDocument& doc, const std::string& tree_name = "");
    /// As above, plus the mesh for the `exact` level. Throws Error(BadInput) if the
    /// mesh is not the one the document was made from.
    CollisionModel(const SptDocument& doc, const TriangleMesh& mesh, const std::string& tree_name = "");

    /// The query layout.
    const CompactTree& tree() const { return tree_; }
    /// True if the `exact` level is available.
    bool has_mesh() const { return !exact_.triangles.empty(); }
    /// Triangle data for the `exact` level (empty without a mesh).
    const ExactData& exact() const { return exact_; }
    /// Largest |x| over every sphere and triangle, object frame (model units): bounds motion.
    double reach() const { return reach_; }
    /// Bounding-box diagonal of the mesh the document was made from (model units).
    double diagonal() const { return diagonal_; }
    /// Per compact node: radius around its centre holding the leaf bounding spheres below it
    /// (level `bounds` prunes with it; tight bounds hold the sampling spheres, not the leaf spheres).
    const std::vector<float>& bounds_reach() const { return bounds_reach_; }
    /// Most spheres in one active node.
    uint32_t max_leaf() const { return max_leaf_; }
    /// Bytes of the query layout plus the exact-level data.
    size_t memory_bytes() const;

private:
    void init(const SptDocument& doc, const std::string& tree_name);
    CompactTree tree_;
    ExactData exact_;
    std::vector<float> bounds_reach_;
    double reach_ = 0, diagonal_ = 0;
    uint32_t max_leaf_ = 0;
};

} // namespace spt
