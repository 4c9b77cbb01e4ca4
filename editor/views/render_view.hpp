#pragma once
// A QOpenGLWidget that draws a render::Frame through render/ (the same Renderer as
// `spt render`, loaded through the widget's context, drawing into its framebuffer object)
// and navigates its camera. The editor's and the viewer's views are subclasses that say
// what to upload and draw.
#include "spt/render/renderer.hpp"
#include <QOpenGLWidget>
#include <QPoint>
#include <memory>

class QLabel;

namespace spt::editor {

/// The name a view's corner shows: "Top", "Front", "Side" or "Camera".
QString view_title(render::View view);

/// Makes OpenGL 3.3 core with a 24-bit depth buffer the default surface format, as render/
/// needs; call before the QApplication is made.
void use_render_gl_format();

/// A view through one camera: middle drag pans (orbits the perspective camera; Shift pans
/// it), Alt+left drag does what middle drag does, the wheel zooms about the cursor.
class RenderView : public QOpenGLWidget {
    Q_OBJECT
public:
    /// A view of `view` kind.
    explicit RenderView(render::View view, QWidget* parent = nullptr);
    ~RenderView() override;

    /// Which view this is.
    render::View view() const { return camera_.view; }
    /// Makes this a view of another kind, fitted again on the next draw.
    void set_view(render::View view);
    /// The camera (world frame, model units).
    const render::Camera& camera() const { return camera_; }
    /// Framebuffer size in physical pixels (logical size times the device pixel ratio).
    QSize framebuffer_size() const;
    /// Fits the camera to fit_bounds() on the next draw (Home).
    void frame_all();
    /// True once the view has drawn with its camera fitted.
    bool has_drawn() const { return drawn_; }
    /// Draw time of the last frame, milliseconds (benchmarks).
    double last_draw_ms() const { return last_draw_ms_; }
    /// Number of frames painted so far (benchmarks check that a repaint painted).
    uint64_t frames_painted() const { return frames_painted_; }
    /// How the renderer made the last frame: drawn, recoloured or composited from its cache.
    render::DrawKind last_draw_kind() const { return last_draw_kind_; }

signals:
    /// A one-line message for the status bar.
    void message(const QString& text);

protected:
    /// Uploads what changed since the last draw; the context is current.
    virtual void upload(render::Renderer& renderer) = 0;
    /// Forgets every handle: the renderer that made them is gone.
    virtual void forget_uploads() = 0;
    /// What to draw now, with this view's uploads.
    virtual render::Frame frame() const = 0;
    /// The box frame_all() fits the camera to; by default everything `frame` shows.
    virtual render::Bounds fit_bounds(const render::Renderer& renderer, const render::Frame& frame) const;
    /// A left press without Alt; return true to take the drag (then left_move and
    /// left_release follow), false to leave it to navigation.
    virtual bool left_press(QMouseEvent*) { return false; }
    /// The mouse moved during a drag taken by left_press (logical pixels).
    virtual void left_move(const QPoint&) {}
    /// The left button went up after a drag taken by left_press (logical pixels).
    virtual void left_release(const QPoint&) {}
    /// The camera, for subclasses that move it (e.g. frame the selection).
    render::Camera& camera_mut() { return camera_; }

    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    enum class Drag { None, Taken, Pan, Orbit };
    void release_gl();
    render::Camera camera_;
    std::unique_ptr<render::Renderer> renderer_;
    bool fit_pending_ = true, drawn_ = false;
    double last_draw_ms_ = 0;
    render::DrawKind last_draw_kind_ = render::DrawKind::Full;
    uint64_t frames_painted_ = 0;
    Drag drag_ = Drag::None;
    QPoint last_;
    // The view's name in its top-left corner, as Blender's quad view shows it: a child widget
    // that Qt composes over the picture, so the framebuffer stays what `spt render` draws.
    QLabel* title_ = nullptr;
};

} // namespace spt::editor
