// RenderView: the renderer in a QOpenGLWidget, camera fitting and navigation.
#include "render_view.hpp"
#include "view_navigation.hpp"
#include <QElapsedTimer>
#include <QLabel>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QSurfaceFormat>
#include <QWheelEvent>
#include <cmath>

namespace spt::editor {

QString view_title(render::View view) {
    QString name = render::view_name(view);
    if (!name.isEmpty()) name[0] = name[0].toUpper();
    return name;
}

void use_render_gl_format() {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
}

RenderView::RenderView(render::View view, QWidget* parent) : QOpenGLWidget(parent) {
    camera_.view = view;
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(80, 60);
    setAccessibleName(render::view_name(view));
    setObjectName(QString("view_") + render::view_name(view));
    title_ = new QLabel(view_title(view), this);
    title_->setObjectName("view_title");
    title_->setAttribute(Qt::WA_TransparentForMouseEvents); // a drag that starts on it selects or pans
    title_->setStyleSheet("QLabel { color: #303030; background: rgba(255, 255, 255, 170); padding: 1px 5px; }");
    title_->adjustSize();
    title_->move(4, 4);
}

RenderView::~RenderView() {
    // ~QOpenGLWidget destroys the context after this part of the object is gone: its
    // aboutToBeDestroyed must not reach release_gl then (UBSan: a call through a dead RenderView).
    if (QOpenGLContext* ctx = context()) disconnect(ctx, nullptr, this, nullptr);
    release_gl();
}

void RenderView::release_gl() {
    if (!renderer_) return;
    // GL objects go before their context, with it current.
    // (Subclass handles die with the renderer; initializeGL makes them forget.)
    makeCurrent();
    renderer_.reset();
    doneCurrent();
}

void RenderView::set_view(render::View view) {
    camera_.view = view;
    setAccessibleName(render::view_name(view));
    title_->setText(view_title(view));
    title_->adjustSize();
    frame_all();
}

QSize RenderView::framebuffer_size() const { return size() * devicePixelRatioF(); }

void RenderView::frame_all() {
    fit_pending_ = true;
    drawn_ = false;
    update();
}

render::Bounds RenderView::fit_bounds(const render::Renderer& renderer, const render::Frame& frame) const {
    render::Bounds b = renderer.bounds(frame);
    if (b.empty()) b.add(Eigen::Vector3f::Zero());
    return b;
}

void RenderView::initializeGL() {
    QOpenGLContext* ctx = context();
    connect(ctx, &QOpenGLContext::aboutToBeDestroyed, this, &RenderView::release_gl, Qt::DirectConnection);
    forget_uploads();
    renderer_ = std::make_unique<render::Renderer>(
        [ctx](const char* name) { return reinterpret_cast<void*>(ctx->getProcAddress(name)); });
}

void RenderView::paintGL() {
    QElapsedTimer timer;
    timer.start();
    upload(*renderer_);
    const render::Frame f = frame();
    if (fit_pending_) {
        // What `spt render` does: fit the view to the frame (or what the subclass says).
        camera_ = render::fit_camera(camera_.view, fit_bounds(*renderer_, f));
        fit_pending_ = false;
    }
    const QSize fb = framebuffer_size();
    renderer_->draw(f, camera_, render::Viewport{0, 0, fb.width(), fb.height()}, defaultFramebufferObject());
    drawn_ = true;
    last_draw_kind_ = renderer_->last_draw_kind();
    ++frames_painted_;
    last_draw_ms_ = double(timer.nsecsElapsed()) * 1e-6;
}

void RenderView::mousePressEvent(QMouseEvent* event) {
    setFocus(Qt::MouseFocusReason);
    last_ = event->position().toPoint();
    const Qt::KeyboardModifiers m = event->modifiers();
    if (event->button() == Qt::LeftButton && !(m & Qt::AltModifier)) {
        if (left_press(event)) drag_ = Drag::Taken;
    } else if (event->button() == Qt::MiddleButton || (event->button() == Qt::LeftButton && (m & Qt::AltModifier))) {
        const bool orbit_camera = camera_.perspective() && !(m & Qt::ShiftModifier);
        drag_ = orbit_camera ? Drag::Orbit : Drag::Pan;
    }
}

void RenderView::mouseMoveEvent(QMouseEvent* event) {
    const QPoint p = event->position().toPoint();
    const QPoint d = p - last_;
    last_ = p;
    switch (drag_) {
    case Drag::Taken: left_move(p); break;
    case Drag::Pan: pan(camera_, float(d.x()), float(d.y()), width(), height()), update(); break;
    case Drag::Orbit: orbit(camera_, float(d.x()), float(d.y())), update(); break;
    case Drag::None: break;
    }
}

void RenderView::mouseReleaseEvent(QMouseEvent* event) {
    if (drag_ == Drag::Taken) {
        if (event->button() != Qt::LeftButton) return;
        drag_ = Drag::None;
        left_release(event->position().toPoint());
    } else {
        drag_ = Drag::None;
    }
}

void RenderView::wheelEvent(QWheelEvent* event) {
    const float steps = float(event->angleDelta().y()) / 120.0f;
    if (steps == 0) return;
    const QPointF p = event->position();
    zoom_about(camera_, std::pow(1.15f, steps), float(p.x()), float(p.y()), width(), height());
    update();
}

} // namespace spt::editor
