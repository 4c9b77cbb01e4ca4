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

/// Triangles of a mesh attached to the active nodes of a compact tree (object frame).
/// Every non-degenerate triangle belongs to exactly one active node: the node of
/// the lowest-numbered sample on it (a vertex sample of one of its corners or a
/// face sample of it); a triangle with no sample goes to the nearest active node.
struct ExactData {
    std::vector<Eigen::Vector3d> positions;   ///< mesh vertices, model units
    std::vector<Triangle> triangles;          ///< mesh triangles
    std::vector<uint32_t> node_tri_begin;     ///< CSR over compact nodes: owned triangles of node i
    std::vector<uint32_t> node_tris;          ///< triangle indices, grouped by node
    std::vector<float> node_reach;            ///< radius around each node centre holding its spheres and triangles
    std::vector<float> node_tri_reach;        ///< radius around each node centre holding its triangles only; -1 if it owns none
    std::vector<Slab> node_slab;              ///< per node: thinnest slab holding the triangles below it
    std::vector<float> tri_sphere;            ///< per triangle: centre xyz and radius of a bounding sphere
    std::vector<uint32_t> vertex_tri_begin;   ///< CSR: triangles incident to each vertex
    std::vector<uint32_t> vertex_tris;
    std::vector<uint32_t> sphere_source;      ///< per compact sphere: SampleSet source (vertex or face|bit)
    uint32_t max_node_tris = 0;               ///< most triangles owned by one node
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
