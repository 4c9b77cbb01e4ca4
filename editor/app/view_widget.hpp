#pragma once
// One of the editor's four views: a RenderView that draws the document's scene (mesh,
// sampling spheres, current node, selection) and turns a dragged rectangle into a
// selection through core (spt/selection.hpp).
#include "editor_document.hpp"
#include "render_view.hpp"
#include "scene.hpp"
#include <QPoint>

class QRubberBand;

class QLabel;

namespace spt::editor {

/// Settings the views share, owned by the main window.
struct ViewOptions {
    bool visible_only = false;   ///< rectangle selects only samples the mesh does not hide (key X)
    bool swap_modifiers = false; ///< Ctrl adds and Shift subtracts (MeshLab's habit)
};

/// A view of the editor's scene through one camera.
class ViewWidget : public RenderView {
    Q_OBJECT
public:
    /// A view of `view` kind over `scene`; selections go to `doc`. All must outlive the widget.
    ViewWidget(render::View view, EditorDocument& doc, Scene& scene, const ViewOptions& options,
               QWidget* parent = nullptr);

    /// The projection selection uses: this camera over the framebuffer.
    ViewProjection view_projection() const;
    /// Frames the selected samples (F); everything if nothing is selected.
    void frame_selection();

protected:
    void upload(render::Renderer& renderer) override;
    void forget_uploads() override;
    render::Frame frame() const override;
    bool left_press(QMouseEvent* event) override;
    void left_move(const QPoint& p) override;
    void left_release(const QPoint& p) override;
    void keyPressEvent(QKeyEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

public:
    /// The heat map's legend (shown while the spheres are coloured by contacts; tests read it).
    QLabel* legend() const { return legend_; }

private:
    void update_legend();
    QLabel* legend_ = nullptr;
    EditorDocument& doc_;
    Scene& scene_;
    const ViewOptions& options_;
    render::MeshHandle mesh_;
    render::SphereSetHandle spheres_;
    uint64_t mesh_rev_ = 0, spheres_rev_ = 0, selected_rev_ = 0, pose_rev_ = 0;
    bool selecting_ = false;
    SelectionMode mode_ = SelectionMode::Replace;
    QPoint press_;
    QRubberBand* band_ = nullptr;
};

} // namespace spt::editor
