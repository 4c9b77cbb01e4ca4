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

    /// The model at the current pose.
    const CollisionModel& model() const { return model_; }
    /// The mesh's welded vertices at the current pose (object frame, model units).
    const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
    /// Unit vertex normals at the current pose (angle-weighted, as import computes them; zero where
    /// a vertex has none), before the first pose the mesh's own.
    const std::vector<Eigen::Vector3d>& vertex_normals() const { return vertex_normals_; }
    /// The animated mesh.
    const AnimatedMesh& mesh() const { return *mesh_; }
    /// Each sample's surface point at the current pose (SampleSet order, the samples' local frame:
    /// add the document's origin for the object frame), model units.
    const std::vector<Eigen::Vector3f>& sample_points() const { return points_; }

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
    std::vector<Eigen::Vector3d> vertices_, vertex_normals_;
    std::vector<uint8_t> normal_valid_;
    std::vector<Eigen::Vector3f> points_, normals_;
    std::vector<uint8_t> face_sampled_;      // per triangle: some face sample lies on it
    std::vector<Eigen::Vector3f> snapped_;   // per vertex, then per triangle: its normal as stored
    std::vector<uint8_t> snapped_ok_;
    // Per bone slot: the ball of the mesh-space vertices it moves (radius < 0: none); the most a
    // morph target moves a vertex; the largest sampling sphere.
    std::vector<std::pair<Eigen::Vector3d, double>> slot_balls_;
    std::vector<double> morph_reach_;
    double sphere_reach_ = 0;
    // Samples, layout and triangles to vertices_.
    void follow();
    // slot_balls_, morph_reach_ and sphere_reach_ (bound_at's), once.
    void measure_joints();
};

} // namespace spt
