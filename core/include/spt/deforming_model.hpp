#pragma once
/// A collision model whose surface deforms with its animation (docs/deforming.md): every
/// sampling sphere follows its sample (a vertex sample its vertex, a face sample its triangle at
/// the same barycentric coordinates), centred at p - r*n with the deformed normal, and the tree's
/// bounding spheres are refit. Queries take model() as any CollisionModel.
#include "spt/animation.hpp"
#include "spt/collision_model.hpp"
#include <memory>
#include <string>
#include <vector>

namespace spt {

/// One deforming object: a tree of a document bound to the animated mesh it was made from.
class DeformingModel {
public:
    /// Binds tree `tree_name` (the first if empty) of `doc` to `mesh`, which must be the mesh the
    /// document was made from (Error(BadInput) otherwise). Starts at the bind pose. The mesh is
    /// shared, not copied.
    DeformingModel(const SptDocument& doc, std::shared_ptr<const AnimatedMesh> mesh, const std::string& tree_name = "");

    /// Poses the model at `time` seconds of `clip` (a null clip: the bind pose, the mesh as imported).
    void pose(const Clip* clip, double time);
    /// Poses the model on the mesh's welded vertices at `positions` (object frame, model units).
    void pose_on(const std::vector<Eigen::Vector3d>& positions);

    /// The model at the current pose.
    const CollisionModel& model() const { return model_; }
    /// The mesh's welded vertices at the current pose (object frame, model units).
    const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
    /// The animated mesh.
    const AnimatedMesh& mesh() const { return *mesh_; }

private:
    std::shared_ptr<const AnimatedMesh> mesh_;
    CollisionModel model_;
    std::vector<Eigen::Vector3f> bind_points_, bind_normals_; // the document's samples (local frame)
    std::vector<uint32_t> source_;                            // per sample: vertex, or triangle | kFaceSampleBit
    std::vector<Eigen::Vector3d> barycentric_;                // per face sample: weights of its triangle's corners
    std::vector<Eigen::Vector3d> bind_at_;                    // per sample: where its vertex or weights put it at bind
    // The current pose and what computing it needs, kept from pose to pose.
    std::vector<Eigen::Vector3d> vertices_, vertex_normals_;
    std::vector<uint8_t> normal_valid_;
    std::vector<Eigen::Vector3f> points_, normals_;
};

} // namespace spt
