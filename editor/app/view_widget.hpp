#pragma once
// One of the four views: a QOpenGLWidget that draws the scene through render/ (the same
// Renderer as `spt render`, loaded through the widget's context, drawing into its
// framebuffer object), navigates its camera, and turns a dragged rectangle into a
// selection through core (spt/selection.hpp).
#include "editor_document.hpp"
#include "scene.hpp"
#include "spt/render/renderer.hpp"
#include <QOpenGLWidget>
#include <QPoint>
#include <memory>

class QRubberBand;

namespace spt::editor {

/// Makes OpenGL 3.3 core with a 24-bit depth buffer the default surface format, as render/
/// needs; call before the QApplication is made.
void use_render_gl_format();

/// Settings the views share, owned by the main window.
struct ViewOptions {
    bool visible_only = false;   ///< rectangle selects only samples the mesh does not hide (key X)
    bool swap_modifiers = false; ///< Ctrl adds and Shift subtracts (MeshLab's habit)
};

/// A view of the scene through one camera.
class ViewWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    /// A view of `view` kind over `scene`; selections go to `doc`. All must outlive the widget.
    ViewWidget(render::View view, EditorDocument& doc, Scene& scene, const ViewOptions& options,
               QWidget* parent = nullptr);
    ~ViewWidget() override;

    /// Which view this is.
    render::View view() const { return camera_.view; }
    /// The camera (world frame = object frame).
    const render::Camera& camera() const { return camera_; }
    /// Framebuffer size in physical pixels (logical size times the device pixel ratio).
    QSize framebuffer_size() const;
    /// The projection selection uses: this camera over the framebuffer.
    ViewProjection view_projection() const;
    /// Frames everything on the next draw (Home).
    void frame_all();
    /// Frames the selected samples (F); everything if nothing is selected.
    void frame_selection();
    /// True once the view has drawn with its camera fitted.
    bool has_drawn() const { return drawn_; }
    /// Draw time of the last frame, milliseconds (benchmarks).
    double last_draw_ms() const { return last_draw_ms_; }

signals:
    /// A one-line message for the status bar.
    void message(const QString& text);

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    enum class Drag { None, Select, Pan, Orbit };
    void upload();
    void release_gl();
    void finish_selection(const QPoint& end);
    EditorDocument& doc_;
    Scene& scene_;
    const ViewOptions& options_;
    render::Camera camera_;
    std::unique_ptr<render::Renderer> renderer_;
    render::MeshHandle mesh_;
    render::SphereSetHandle spheres_, selected_;
    uint64_t mesh_rev_ = 0, spheres_rev_ = 0, selected_rev_ = 0;
    bool fit_pending_ = true, drawn_ = false;
    double last_draw_ms_ = 0;
    Drag drag_ = Drag::None;
    SelectionMode mode_ = SelectionMode::Replace;
    QPoint press_, last_;
    QRubberBand* band_ = nullptr;
};

} // namespace spt::editor
