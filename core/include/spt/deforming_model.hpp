#pragma once
/// A collision model whose surface deforms with its animation (docs/deforming.md): every
/// sampling sphere follows its sample (a vertex sample its vertex, a face sample its triangle at
/// the same barycentric coordinates), centred at p - r*n with the deformed normal, and the tree's
/// bounding spheres are refit. Queries take model() as any CollisionModel.
#include "spt/animation.hpp"
#include "spt/collision_model.hpp"
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace spt {

namespace detail {
struct LazyLayout;
class LazyPose;
}

/// How well the sampling spheres cover the surface across a clip (docs/deforming.md, "Stretch"):
/// surface points (each triangle's corners, edge middles and a grid inside) at poses every
/// 1/frames_per_second seconds, and how far the farthest lies outside every sphere.
struct ClipCoverage {
    double bind_gap = 0;    ///< the largest gap at the bind pose, model units (0: covered)
    double largest_gap = 0; ///< the largest gap at any pose measured, model units
    double time = 0;        ///< clip seconds of that pose
    Eigen::Vector3d where = Eigen::Vector3d::Zero(); ///< that surface point at the bind pose, object frame
    double largest_growth = 0; ///< the most a point's gap grows over its bind gap at any pose (stretch)
    double growth_time = 0;    ///< clip seconds of that pose
    Eigen::Vector3d growth_where = Eigen::Vector3d::Zero(); ///< that point at the bind pose, object frame
    int poses = 0;          ///< poses measured
};

/// One deforming object: a tree of a document bound to the animated mesh it was made from.
class DeformingModel {
public:
    /// Binds tree `tree_name` (the first if empty) of `doc` to `mesh`, which must be the mesh the
    /// document was made from (Error(BadInput) otherwise). Starts at the bind pose. The mesh is
    /// shared, not copied. Without `triangles` a pose moves the sampling spheres only, and the
    /// model has no `exact` level (its triangle tree is a third of a pose's work).
    DeformingModel(const SptDocument& doc, std::shared_ptr<const AnimatedMesh> mesh, const std::string& tree_name = "",
                   bool triangles = true);

    /// Spreads each pose over `threads` jobs (default 1) on the host's `tasks` (null: the library's
    /// pool, spt/task_system.hpp); a pose is the same for any count.
    void set_threads(int threads, TaskSystem* tasks = nullptr) { threads_ = std::max(1, threads), tasks_ = tasks; }

    /// Poses the model at `time` seconds of `clip` (a null clip: the bind pose, the mesh as imported).
    void pose(const Clip* clip, double time);
    /// Poses the model on the mesh's welded vertices at `positions` (object frame, model units).
    void pose_on(const std::vector<Eigen::Vector3d>& positions);

    /// Poses the model lazily at `time` seconds of `clip` (the paper's update of only what a test
    /// visits; docs/deforming.md, "Lazy refit"): the bounding spheres near the root are fitted
    /// now from the posed vertices, and each part of the tree below is posed when a `spheres`
    /// query first descends into it; an `exact` query, and containment, refit the triangles alone.
    /// Every other query, and a copy of the model, poses the rest first, so answers are those of
    /// pose() (the pruning near the root is looser). Several threads may run `spheres` and `exact`
    /// queries on it at once; what poses the rest must run alone. Two-sided spheres (open parts):
    /// the nodes near the root are tested as balls until a settle, those of a posed part as the
    /// discs a full pose fits.
    void pose_lazily(const Clip* clip, double time);
    /// As pose_lazily, on the mesh's welded vertices at `positions` (object frame, model units).
    void pose_lazily_on(const std::vector<Eigen::Vector3d>& positions);
    /// Poses what a lazy pose left (the model is then what pose() makes); a no-op otherwise.
    void settle();
    /// The most samples in a part of the tree a lazy pose poses in one go (default 512).
    void set_lazy_region(uint32_t samples);
    /// Refits inner bounding spheres tight, by searching the spheres below each that holds at
    /// least CompactTree::kTightSearchFrom (default off): a pose costs about 1.15x as much, and a
    /// query on it walks about as many node pairs as on a tree built at the pose
    /// (docs/deforming.md, "Refit"). A lazy pose then also bounds the balls near the root by the
    /// posed face normals (which side of the surface each sphere lies on), several times its cost
    /// for a repeated query near the rigid tree's (docs/deforming.md, "Lazy refit"). Applies from
    /// the next pose.
    void set_tight_refit(bool tight);

    /// The model at the current pose.
    const CollisionModel& model() const { return model_; }
    /// The mesh's welded vertices at the current pose (object frame, model units).
    const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
    /// Unit vertex normals at the current pose (angle-weighted, as import computes them; zero where
    /// a vertex has none), before the first pose the mesh's own. Settles a lazy pose.
    const std::vector<Eigen::Vector3d>& vertex_normals() const;
    /// The animated mesh.
    const AnimatedMesh& mesh() const { return *mesh_; }
    /// Each sample's surface point at the current pose (SampleSet order, the samples' local frame:
    /// add the document's origin for the object frame), model units. Settles a lazy pose.
    const std::vector<Eigen::Vector3f>& sample_points() const;

    /// A ball holding the model at `time` seconds of `clip` (a null clip: the bind pose) without
    /// posing it: each joint's ball of the vertices it moves, carried by the joint, all held by one
    /// ball grown by the sampling spheres and the morph targets (centre in the object frame, model
    /// units). Linear blend skinning keeps every surface point within its joints' balls, so this
    /// bounds what pose() would make; it costs a few microseconds, a pose a millisecond.
    std::pair<Eigen::Vector3d, double> bound_at(const Clip* clip, double time) const;

    /// Measures the coverage of the surface by the spheres across `clip` (see ClipCoverage) on
    /// `threads` copies of the model (the same answer for any count); this model keeps its pose.
    ClipCoverage measure_coverage(const Clip& clip, double frames_per_second = 30, int threads = 1) const;

private:
    friend class detail::LazyPose; // poses parts of model_ from this pose's vertices
    std::shared_ptr<const AnimatedMesh> mesh_;
    CollisionModel model_;
    bool triangles_;
    double diagonal_ = 0; // the bind pose's bounding-box diagonal, model units
    int threads_ = 1;
    TaskSystem* tasks_ = nullptr;
    std::vector<Eigen::Vector3f> bind_points_, bind_normals_; // the document's samples (local frame)
    std::vector<uint32_t> source_;                            // per sample: vertex, or triangle | kFaceSampleBit
    std::vector<Eigen::Vector3d> barycentric_;                // per face sample: weights of its triangle's corners
    std::vector<Eigen::Vector3d> bind_at_;                    // per sample: where its vertex or weights put it at bind
    // The current pose and what computing it needs, kept from pose to pose.
    std::vector<Eigen::Vector3d> vertices_;
    mutable std::vector<Eigen::Vector3d> vertex_normals_;
    mutable std::vector<uint8_t> normal_valid_;
    std::vector<Eigen::Vector3f> points_, normals_;
    std::vector<uint8_t> face_sampled_;      // per triangle: some face sample lies on it
    std::vector<Eigen::Vector3f> snapped_;   // per vertex, then per triangle: its normal as stored
    std::vector<uint8_t> snapped_ok_;
    // Per bone slot: the ball of the mesh-space vertices it moves (radius < 0: none); the most a
    // morph target moves a vertex; the largest sampling sphere.
    std::vector<std::pair<Eigen::Vector3d, double>> slot_balls_;
    std::vector<double> morph_reach_;
    double sphere_reach_ = 0;
    // Lazy posing: the tree's layout for it (made at the first lazy pose; null if the tree cannot
    // be posed lazily) and the pending pose (shared by copies until one of them poses lazily).
    uint32_t lazy_region_ = 512;
    bool lazy_checked_ = false;
    std::shared_ptr<const detail::LazyLayout> lazy_layout_;
    std::shared_ptr<detail::LazyPose> lazy_;
    std::vector<Eigen::Vector3d> next_vertices_; // a clip's pose, checked before it replaces vertices_
    // A settled lazy pose leaves the vertex normals to the first call that reads them.
    mutable bool vertex_normals_stale_ = false;
    // Samples, layout and triangles to vertices_.
    void follow();
    // The mesh's vertices at `time` seconds of `clip` (null: the bind pose), in next_vertices_.
    const std::vector<Eigen::Vector3d>& clip_vertices(const Clip* clip, double time);
    // `positions` into vertices_, after checking their count and that they are finite (Error
    // otherwise, nothing changed).
    void take_vertices(const std::vector<Eigen::Vector3d>& positions);
    // Sample i's point and normal at vertices_ into points_ and normals_; `snapped` its normal as
    // stored, or null (the bind's).
    void place_sample(size_t i, const Eigen::Vector3f* snapped);
    // slot_balls_, morph_reach_ and sphere_reach_ (bound_at's), once.
    void measure_joints();
};

} // namespace spt
