// SceneView: a recorded scene state drawn through render::SceneDrawing.
#include "scene_view.hpp"
#include <algorithm>

namespace spt::editor {

SceneView::SceneView(render::View view, QWidget* parent) : RenderView(view, parent) {}

void SceneView::set_history(const SceneHistory* history, bool refit) {
    history_ = history;
    step_ = std::clamp(step_, 0, history_ ? std::max(history_->recorded(), 0) : 0);
    if (refit) frame_all();
    update();
}

void SceneView::set_step(int step) {
    step_ = std::clamp(step, 0, history_ ? std::max(history_->recorded(), 0) : 0);
    update();
}

void SceneView::set_overlays(const ViewerOverlays& overlays) {
    overlays_ = overlays;
    update();
}

void SceneView::forget_uploads() {
    drawing_.reset();
    drawn_scene_.reset();
}

void SceneView::upload(render::Renderer& renderer) {
    // A history recorded again with other effects shares its scene: the uploads stay.
    std::shared_ptr<const Scene> scene = history_ && history_->loaded() ? history_->shared_scene() : nullptr;
    if (scene != drawn_scene_) upload_scene(renderer, scene);
    // Animated objects take the pose of the step shown (the clip's, with effect deform).
    if (drawing_ && scene)
        drawing_->show_time(renderer, double(step_) * scene->dt, history_->effects().has(Effect::Deform));
}

void SceneView::upload_scene(render::Renderer& renderer, std::shared_ptr<const Scene> scene) {
    if (drawing_) drawing_->release(renderer);
    drawing_.reset();
    drawn_scene_ = scene; // held, so the drawing's reference stays valid
    if (!scene) return;
    try {
        drawing_ = std::make_unique<render::SceneDrawing>(renderer, *scene);
    } catch (const std::exception& e) {
        // A model's mesh that cannot be read again: the scene shows nothing, the reason is said.
        emit message(QString::fromStdString(e.what()));
    }
}

render::Frame SceneView::frame() const {
    render::Frame f;
    const auto state = history_ && drawing_ ? history_->state(step_) : nullptr;
    if (state) {
        const std::vector<std::vector<Eigen::Vector3f>> trails =
            overlays_.scene.trails ? history_->trails(step_) : std::vector<std::vector<Eigen::Vector3f>>{};
        f = drawing_->frame(state->poses, state->step ? &*state->step : nullptr, state->ghost, trails, state->broad,
                            overlays_.scene);
    }
    f.grid = overlays_.grid;
    f.axes = overlays_.axes;
    return f;
}

render::Bounds SceneView::fit_bounds(const render::Renderer& renderer, const render::Frame& frame) const {
    if (drawing_) return drawing_->initial_bounds(renderer);
    return RenderView::fit_bounds(renderer, frame);
}

} // namespace spt::editor
