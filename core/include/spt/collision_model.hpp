#pragma once
/// What a query needs of one object: the compact sampling tree and, for the
/// `exact` level, the mesh's triangles assigned to the tree's active nodes.
/// Immutable after construction (a DeformingModel poses its own); share one model between threads
/// freely. A lazily posed one (DeformingModel::pose_lazily) takes `spheres` queries from several
/// threads at once (see there), and anything that poses the rest of it only alone.
#include "spt/compact_tree.hpp"
#include "spt/mesh.hpp"
#include "spt/spt_file.hpp"
#include <memory>
#include <string>
#include <vector>

namespace spt {

struct ExactData; // the exact level's triangles and triangle tree (private layout)
struct SolidData; // where the model is solid, for containment (private layout)
class DeformingModel;
namespace detail {
struct ModelAccess;
class PendingPose;
/// The pose a lazily posed model still owes (query/pending_pose.hpp): a copy or a move of the
/// model poses the rest of the source first, and the copy is posed throughout.
struct PendingHandle {
    PendingPose* pose = nullptr;
    PendingHandle() = default;
    PendingHandle(const PendingHandle& other);
    PendingHandle& operator=(const PendingHandle& other);
};
}

/// One object ready for queries.
class CollisionModel {
public:
    /// An empty model: collides with nothing.
    CollisionModel() = default;
    /// Model of tree `tree_name` (first tree if empty) of `doc`; no `exact` level.
    explicit CollisionModel(const SptDocument& doc, const std::string& tree_name = "");
    /// As above, plus the mesh for the `exact` level. Throws Error(BadInput) if the
    /// mesh is not the one the document was made from.
    CollisionModel(const SptDocument& doc, const TriangleMesh& mesh, const std::string& tree_name = "");

    /// The query layout.
    const CompactTree& tree() const { return tree_; }
    /// True if the `exact` level is available.
    bool has_mesh() const;
    /// Object-frame point the model's geometry is stored relative to (SampleSet::origin), model units.
    const Eigen::Vector3d& origin() const { return tree_.origin(); }
    /// Largest |x - origin()| over every sphere and triangle (model units): the model's size.
    double extent() const { return extent_; }
    /// Largest |x| over every sphere and triangle in the object frame (model units): how far a
    /// point of the model can be from the centre of the object's rotations; bounds motion.
    double reach() const { return reach_; }
    /// Bounding-box diagonal of the mesh the document was made from (model units).
    double diagonal() const { return diagonal_; }
    /// Per compact node: radius around its centre holding the leaf bounding spheres below it
    /// (level `bounds` prunes with it; tight bounds hold the sampling spheres, not the leaf spheres).
    const std::vector<float>& bounds_reach() const { return bounds_reach_; }
    /// Most spheres in one active node.
    uint32_t max_leaf() const { return max_leaf_; }
    /// Bytes of the query layout, the exact-level data and the solid grids.
    size_t memory_bytes() const;

private:
    friend struct detail::ModelAccess; // the query code's view of exact_ and solid_ (query/model_access.hpp)
    friend class DeformingModel;       // poses the layout and the triangles in place
    friend class detail::LazyPose;     // ... or part by part, as queries need it
    void init(const SptDocument& doc, const std::string& tree_name);
    // extent_, reach_ and bounds_reach_ from the layout (and the triangles, when there are some);
    // `by_leaves`: from the active nodes' balls instead of every sphere (a bound, cheaper).
    void measure(bool by_leaves = false);
    // The model on a deformed surface: the spheres follow `points` and `normals` (per sample,
    // local frame), with `triangles` the exact level's triangles `positions` (per mesh vertex,
    // object frame), else the exact level is dropped; bounds refit. Containment asks the posed
    // triangles (the solid grids were made for the bind pose); none without them.
    void follow_surface(const std::vector<Eigen::Vector3d>& positions, const std::vector<Eigen::Vector3f>& points,
                        const std::vector<Eigen::Vector3f>& normals, bool triangles, int threads, TaskSystem* tasks);
    // follow_surface's part after the spheres: the triangles (or none), containment, measure.
    void follow_triangles(const std::vector<Eigen::Vector3d>& positions, bool triangles);
    // follow_triangles' first step, and a lazy pose's (run alone): exact_ made this model's own,
    // its corners at `positions` (object frame), containment's anchors there; the triangles'
    // balls and tree are left for fit_triangle_tree.
    void place_triangle_corners(const std::vector<Eigen::Vector3d>& positions);
    // extent_ and reach_ grown to hold the triangles' corners (a lazy pose's bound until measure).
    void grow_to_hold_triangles();
    // The triangles' balls and tree refit in place around the corners placed (exact_ this model's own).
    void fit_triangle_tree();
    detail::PendingHandle pending_; // first: copied (so the source is posed) before the rest
    CompactTree tree_;
    std::shared_ptr<const ExactData> exact_; // null without a mesh; immutable, so copies share it
    std::shared_ptr<const SolidData> solid_;
    std::vector<float> bounds_reach_;
    // Per node, the slab of query/node_slab.hpp (the distance query's bound); empty once the
    // spheres have moved from where it was fitted (a deformed pose), where the balls bound alone.
    std::vector<float> node_slab_;
    std::vector<float> node_max_radius_; // per node, the largest sampling-sphere radius below it
    double extent_ = 0, reach_ = 0, diagonal_ = 0;
    uint32_t max_leaf_ = 0;
};

} // namespace spt
