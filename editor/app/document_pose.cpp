// DocumentPose: a DeformingModel of the edited tree at the timeline's clip and time.
#include "document_pose.hpp"
#include <algorithm>

namespace spt::editor {

void DocumentPose::reset(std::shared_ptr<const AnimatedMesh> animated) {
    animated_ = std::move(animated);
    clip_ = -1;
    time_ = 0;
    model_.reset();
    mesh_ = TriangleMesh{}; // the next pose copies the new mesh's triangles
}

RecipePose DocumentPose::recipe_pose() const {
    if (clip_ < 0) return {};
    return {animated_->clips[size_t(clip_)].name, time_};
}

bool DocumentPose::set(int clip, double time) {
    if (!animated_ || clip < 0 || size_t(clip) >= animated_->clips.size()) clip = -1;
    // Held within the clip as pose_vertices holds it, so the time shown is the time posed.
    time = clip < 0 ? 0.0 : std::clamp(time, 0.0, animated_->clips[size_t(clip)].duration);
    if (clip == clip_ && time == time_) return false;
    clip_ = clip;
    time_ = time;
    return true;
}

std::string DocumentPose::update(const SptDocument& doc, const std::string& tree_name, bool tree_changed) {
    if (clip_ < 0 || doc.trees.empty()) {
        model_.reset();
        return {};
    }
    try {
        // Without the exact level's triangles: the views draw spheres and the mesh, nothing queries it.
        if (!model_ || tree_changed) model_ = std::make_unique<DeformingModel>(doc, animated_, tree_name, false);
        model_->pose(&animated_->clips[size_t(clip_)], time_);
    } catch (const std::exception& e) {
        // Shown at the bind pose rather than not at all; a slot must not throw into Qt.
        clip_ = -1, time_ = 0;
        model_.reset();
        return e.what();
    }
    if (mesh_.triangles.empty()) mesh_ = animated_->imported.mesh;
    mesh_.positions = model_->vertices();
    mesh_.normals = model_->vertex_normals();
    return {};
}

} // namespace spt::editor
