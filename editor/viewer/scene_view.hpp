#pragma once
// The viewer's view: a RenderView (the editor's view widget base) that draws one recorded
// state of a SceneHistory through render::SceneDrawing, the code `spt render SCENE.json`
// draws with, and fits its camera as that command does (to the initial state).
#include "render_view.hpp"
#include "scene_history.hpp"
#include "spt/render/scene_drawing.hpp"
#include <memory>

namespace spt::editor {

/// What the viewer draws over the objects.
struct ViewerOverlays {
    render::SceneOverlays scene; ///< contacts, normals, manifold, pairs, ghost, trails, spheres, bounds, broad
    bool grid = true;            ///< ground grid
    bool axes = true;            ///< axis gizmo
    /// The flag of overlay `name` as `spt render --overlay` spells it, or nullptr for another name.
    bool* flag(std::string_view name) {
        if (name == "grid") return &grid;
        if (name == "axes") return &axes;
        return render::scene_overlay_flag(scene, name);
    }
};

/// One view of a recorded scene.
class SceneView : public RenderView {
    Q_OBJECT
public:
    /// A view of `view` kind; it draws nothing until set_history().
    explicit SceneView(render::View view, QWidget* parent = nullptr);
    /// Draws states of `history` (loaded; it must outlive the view or be replaced first);
    /// `refit` fits the camera again (a new scene), otherwise the camera stays.
    void set_history(const SceneHistory* history, bool refit);
    /// Shows state `step` (clamped to what is recorded).
    void set_step(int step);
    /// The state shown.
    int step() const { return step_; }
    /// Sets what is drawn over the objects.
    void set_overlays(const ViewerOverlays& overlays);

protected:
    void upload(render::Renderer& renderer) override;
    void forget_uploads() override;
    render::Frame frame() const override;
    render::Bounds fit_bounds(const render::Renderer& renderer, const render::Frame& frame) const override;

private:
    // The drawing of a newly loaded scene (none: nothing drawn).
    void upload_scene(render::Renderer& renderer, std::shared_ptr<const Scene> scene);
    const SceneHistory* history_ = nullptr;
    std::shared_ptr<const Scene> drawn_scene_; // the scene drawing_ was made for
    std::unique_ptr<render::SceneDrawing> drawing_;
    ViewerOverlays overlays_;
    int step_ = 0;
};

} // namespace spt::editor
