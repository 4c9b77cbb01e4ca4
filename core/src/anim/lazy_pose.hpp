#pragma once
// Lazy refit, the paper's update of only what a test visits (docs/deforming.md, "Lazy refit"):
// a pose moves the bounding spheres of the few nodes near the root at once, each from the posed
// vertices its samples hang on, and leaves the parts below (regions) for the query that first
// descends into them.
#include "geometry/vertex_faces.hpp"
#include "query/pending_pose.hpp"
#include "spt/deforming_model.hpp"
#include <memory>
#include <mutex>
#include <vector>

namespace spt::detail {

constexpr uint32_t kNoSlot = 0xffffffffu; // a vertex or face that the region in hand does not read

/// What lazy posing needs to know of one tree on one mesh, made once.
struct LazyLayout {
    /// A part of the tree posed in one go: the subtree of a frontier node.
    struct Region {
        std::vector<uint32_t> active;         // active nodes of the subtree (their spheres move)
        std::vector<uint32_t> fit_active;     // active nodes whose balls are refit (not the covers)
        std::vector<uint32_t> fit_inner;      // inner nodes refit, from the last back (not the covers)
        std::vector<uint32_t> samples;        // the samples of the active nodes
        std::vector<uint32_t> sample_slot;    // per sample: its normal's slot (vertex slots, then face slots)
        std::vector<uint32_t> normal_vertices; // vertices whose normals the samples read
        std::vector<uint32_t> normal_faces;   // every face around those, ascending (as a full pose sums)
        std::vector<uint32_t> corner_slot;    // per normal face, 3: the corner's vertex slot or kNoSlot
        std::vector<uint32_t> sampled_faces;  // faces whose samples lie here (each a face slot)
        std::vector<uint32_t> sampled_corner_slot; // per sampled face, 3 vertex slots
    };
    /// A node whose ball a pose fits from the posed vertices and face normals under it: a frontier
    /// node's children, or an active frontier node.
    struct Cover {
        uint32_t node;
        // Faces and vertices with samples below, one-sided and two-sided, each with the largest
        // radius of those samples' spheres (model units).
        std::vector<uint32_t> faces, vertices, flat_faces, flat_vertices;
        std::vector<float> face_reach, vertex_reach, flat_face_reach, flat_vertex_reach;
        // Per face: each barycentric weight's least over its samples here, and how many corners
        // of its patch face_patch holds for it in turn (patch_corners; 0: the least weights'
        // triangle, which does not reach past the box of the cover's samples at bind).
        std::vector<Eigen::Vector3d> face_least, flat_face_least, face_patch, flat_face_patch;
        std::vector<uint8_t> face_patch_size, flat_face_patch_size;
        double off = 0;    // the most a stored point lies from its surface point, model units
        // Without normals (the lazy pose's default): every vertex a sample below hangs on, the
        // most sum |barycentric weight| of a sample below, and how far a sphere reaches past its
        // surface point (model units).
        std::vector<uint32_t> corners;
        double spread = 1, grow = 0;
    };
    std::vector<uint32_t> need; // per compact node: the region to pose before reading below it
    std::vector<Region> regions;
    std::vector<Cover> covers;
    size_t most_items = 0; // the most items of one cover at a pose (LazyPose::cover_items)
    std::vector<uint32_t> upper; // inner nodes above the covers, from the last back
    std::vector<std::pair<uint32_t, uint32_t>> upper_covers; // per upper node: its run of covers
    std::vector<uint8_t> loose;  // per compact node: 1 for a cover or an upper node
    VertexFaces around;          // every face around each vertex (the covers' vertex normals)
};

/// Appends to `out` the corners (barycentric weights) of the patch of a face whose weights lie
/// between `least` and `most` (each weight's least and most over some samples of it); returns how
/// many (at most six, or twelve with rounding's near twins). The samples lie in the corners' hull,
/// at any pose of the face. Appends nothing and returns 0 when that patch is the triangle of the
/// least weights (no corner of it reaches past the most weights).
uint8_t patch_corners(const Eigen::Vector3d& least, const Eigen::Vector3d& most, std::vector<Eigen::Vector3d>& out);

/// The layout for `model`'s tree (bound to `mesh` with the per-sample `source`, `barycentric`
/// and `offset` (the stored point's distance from its surface point at bind)), in regions of at
/// most `region_samples` samples; null for an empty tree.
std::shared_ptr<const LazyLayout> make_lazy_layout(const CompactTree& tree, const TriangleMesh& mesh,
                                                   const std::vector<uint32_t>& source,
                                                   const std::vector<Eigen::Vector3d>& barycentric,
                                                   const std::vector<double>& offset, uint32_t region_samples);

/// The pending pose of one DeformingModel.
class LazyPose final : public PendingPose {
public:
    LazyPose(DeformingModel* owner, std::shared_ptr<const LazyLayout> layout);
    /// The model this poses.
    const DeformingModel* owner() const { return owner_; }
    /// Starts a lazy pose at the owner's vertices: every region unposed, the covers' and upper
    /// nodes' balls fitted, the model pending.
    void begin();
    /// Poses the rest: the model becomes what a full pose makes.
    void settle() override;

protected:
    void pose_region(uint32_t r) override;
    void pose_triangles() override;

private:
    DeformingModel* owner_;
    std::shared_ptr<const LazyLayout> layout_;
    std::unique_ptr<std::atomic<uint8_t>[]> posed_flags_; // one a region
    std::mutex mutex_; // one region posed at a time (the scratch below is shared)
    std::vector<Eigen::Vector3d> normal_sum_; // per slot of the region in hand
    // Per face, what it adds to its corners' normals at this pose, made once a pose (regions
    // share faces): 3 vectors, valid when the face's stamp is the pose's; degenerate faces add none.
    std::vector<Eigen::Vector3d> corner_add_;
    std::vector<uint32_t> face_stamp_;
    std::vector<uint8_t> face_adds_;
    uint32_t pose_stamp_ = 0;
    // Per vertex and per face sampled, its normal at this pose as stored (ok: it has one), made by
    // the first region that reads it; the stamp says which pose.
    std::vector<uint32_t> vertex_stamp_, sampled_stamp_;
    std::vector<Eigen::Vector3d> vertex_unit_;
    std::vector<Eigen::Vector3f> vertex_snap_, face_snap_;
    std::vector<uint8_t> vertex_ok_, face_ok_;
    // Per face at this pose, for tight covers: its unit normal (zero without one) and whether it has
    // a share in its corners' vertex normals.
    std::vector<Eigen::Vector3d> cover_unit_;
    std::vector<uint8_t> cover_share_;
    void pose_region_locked(uint32_t r); // with mutex_ held
    std::vector<Eigen::Vector4d> items_; // the cover in hand's, at this pose: points and reaches past them
    size_t cover_items(const LazyLayout::Cover& c); // writes c's items into items_, returns how many
    std::vector<Eigen::Vector3d> cover_box_; // per cover, at this pose: its items' box (least, most), the tree's frame
    void fit_cover(size_t k, size_t items); // cover k's ball around the first `items` of items_
    void fit_tight_covers(); // the covers from the posed face normals, the nodes above from the covers
};

} // namespace spt::detail
