#pragma once
// The edited tree shown at a pose of the document's animated mesh (docs/deforming.md): a core
// DeformingModel bound to the tree, made again whenever the tree changes, and the mesh at that
// pose for visible-only selection. A view state: the document itself stays at the bind pose.
#include "spt/deforming_model.hpp"
#include "spt/split_recipe.hpp"
#include <memory>
#include <string>

namespace spt::editor {

/// The pose the views show: a clip of the document's animated mesh at a time, or the bind pose.
class DocumentPose {
public:
    /// Back to the bind pose, for a document animated by `animated` (null: the mesh has no clips).
    void reset(std::shared_ptr<const AnimatedMesh> animated);
    /// The mesh with its clips, or null.
    const AnimatedMesh* animation() const { return animated_.get(); }
    /// The same, shared (null when the mesh has no clips).
    const std::shared_ptr<const AnimatedMesh>& shared_animation() const { return animated_; }
    /// Index of the clip shown (into AnimatedMesh::clips), -1 for the bind pose.
    int clip() const { return clip_; }
    /// Seconds into the clip (0 at the bind pose).
    double time() const { return time_; }
    /// The pose as a recipe step records it (clip name and time; empty at the bind pose).
    RecipePose recipe_pose() const;
    /// Chooses clip `clip` (-1: the bind pose; an index out of range is the bind pose) at `time`
    /// seconds, held within the clip; false when that is the pose already.
    bool set(int clip, double time);
    /// Poses tree `tree_name` of `doc` at the chosen pose, bound to it again when `tree_changed`
    /// (an edit changes the tree's nodes, radii and sphere order); at the bind pose it drops the
    /// model. A pose core refuses (a vertex posed to no finite point) goes back to the bind pose;
    /// the returned text says why (empty when posed).
    std::string update(const SptDocument& doc, const std::string& tree_name, bool tree_changed);
    /// The tree at the pose (posed spheres, sample points, vertices), or null at the bind pose.
    const DeformingModel* model() const { return model_.get(); }
    /// The mesh at the pose (visible-only selection), or null at the bind pose.
    const TriangleMesh* mesh() const { return model_ ? &mesh_ : nullptr; }

private:
    std::shared_ptr<const AnimatedMesh> animated_;
    int clip_ = -1;
    double time_ = 0;
    std::unique_ptr<DeformingModel> model_;
    TriangleMesh mesh_;
};

} // namespace spt::editor
