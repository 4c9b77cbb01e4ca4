#pragma once
// One of the editor's four views: a RenderView that draws the document's scene (mesh,
// sampling spheres, current node, selection) and turns a dragged rectangle, lasso or brush
// stroke into a selection through core (spt/selection.hpp), its outline composed over the
// picture while it is drawn.
#include "editor_document.hpp"
#include "render_view.hpp"
#include "scene.hpp"
#include <QPoint>

#include <QColor>
#include <QPointF>
#include <vector>

class QLabel;

namespace spt::editor {

/// What a left drag draws (Select menu: R, L, C).
enum class SelectTool {
    Rectangle, ///< a rectangle between the press and the release
    Lasso,     ///< a free polygon along the drag
    Brush,     ///< a circle painted along the drag
};

/// Settings the views share, owned by the main window.
struct ViewOptions {
    bool visible_only = false;   ///< selection takes only samples the mesh does not hide (key X)
    bool swap_modifiers = false; ///< Ctrl adds and Shift subtracts (MeshLab's habit)
    SelectTool tool = SelectTool::Rectangle; ///< what a left drag draws
    double brush_radius = 25;    ///< brush radius, logical pixels ([ and ])
};

class StrokeOverlay;

/// Colour of the outline of a stroke being drawn (rectangle, lasso, brush) over a view.
QColor stroke_outline_color();

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
    /// Where the mouse last was over this view (logical pixels).
    QPoint hover() const { return hover_; }
    /// Logical pixels from the top left to GL window pixels of the framebuffer from the bottom left.
    Eigen::Vector2f window_point(const QPointF& p) const;
    /// True while a selection stroke is being drawn.
    bool selecting() const { return selecting_; }
    /// Select linked at the last hover point (Ctrl+L): the mesh part under the cursor, in `mode`.
    void select_linked(SelectionMode mode);

signals:
    /// The mouse moved over this view (the view select linked picks in).
    void hovered(ViewWidget* view);

protected:
    void upload(render::Renderer& renderer) override;
    void forget_uploads() override;
    render::Frame frame() const override;
    bool left_press(QMouseEvent* event) override;
    void left_move(const QPoint& p) override;
    void left_release(const QPoint& p) override;
    void keyPressEvent(QKeyEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
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
    SelectTool tool_ = SelectTool::Rectangle; // fixed at the press
    QPoint press_, hover_;
    std::vector<QPointF> path_; // the drag's points, logical pixels
    StrokeOverlay* overlay_ = nullptr;
    void end_stroke();
};

} // namespace spt::editor
