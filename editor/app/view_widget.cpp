// ViewWidget: drawing through render/, navigation, and rectangle selection.
#include "view_widget.hpp"
#include "view_navigation.hpp"
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QRubberBand>
#include <QSurfaceFormat>
#include <QWheelEvent>

namespace spt::editor {

void use_render_gl_format() {
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
}

ViewWidget::ViewWidget(render::View view, EditorDocument& doc, Scene& scene, const ViewOptions& options,
                       QWidget* parent)
    : QOpenGLWidget(parent), doc_(doc), scene_(scene), options_(options) {
    camera_.view = view;
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(80, 60);
    setAccessibleName(render::view_name(view));
    setObjectName(QString("view_") + render::view_name(view));
    connect(&scene_, &Scene::changed, this, qOverload<>(&QWidget::update));
    connect(&doc_, &EditorDocument::documentReset, this, &ViewWidget::frame_all);
}

ViewWidget::~ViewWidget() { release_gl(); }

void ViewWidget::release_gl() {
    if (!renderer_) return;
    // GL objects go before their context, with it current.
    makeCurrent();
    renderer_.reset();
    doneCurrent();
}

QSize ViewWidget::framebuffer_size() const { return size() * devicePixelRatioF(); }

ViewProjection ViewWidget::view_projection() const {
    const QSize fb = framebuffer_size();
    ViewProjection v;
    v.view = camera_.view_matrix();
    v.projection = camera_.projection_matrix(float(fb.width()) / float(std::max(fb.height(), 1)));
    v.perspective = camera_.perspective();
    v.width = fb.width();
    v.height = fb.height();
    return v;
}

void ViewWidget::frame_all() {
    fit_pending_ = true;
    drawn_ = false;
    update();
}

void ViewWidget::frame_selection() {
    if (doc_.selection().empty()) return frame_all();
    render::Bounds b;
    for (const auto& s : scene_.data().selected) b.add_sphere(s.sphere.center, s.sphere.radius);
    const render::Camera fitted = render::fit_camera(camera_.view, b);
    camera_.target = fitted.target;
    camera_.radius = fitted.radius;
    camera_.zoom = 1;
    update();
}

void ViewWidget::initializeGL() {
    QOpenGLContext* ctx = context();
    connect(ctx, &QOpenGLContext::aboutToBeDestroyed, this, &ViewWidget::release_gl, Qt::DirectConnection);
    renderer_ = std::make_unique<render::Renderer>(
        [ctx](const char* name) { return reinterpret_cast<void*>(ctx->getProcAddress(name)); });
    mesh_rev_ = spheres_rev_ = selected_rev_ = 0;
    mesh_ = {}, spheres_ = {}, selected_ = {};
}

void ViewWidget::upload() {
    const SceneData& d = scene_.data();
    if (mesh_rev_ != d.mesh_revision) {
        renderer_->remove_mesh(mesh_);
        mesh_ = d.mesh ? renderer_->add_mesh(*d.mesh) : render::MeshHandle{};
        mesh_rev_ = d.mesh_revision;
    }
    if (spheres_rev_ != d.spheres_revision) {
        renderer_->remove_spheres(spheres_);
        spheres_ = d.spheres.empty() ? render::SphereSetHandle{} : renderer_->add_spheres(d.spheres);
        spheres_rev_ = d.spheres_revision;
    }
    if (selected_rev_ != d.selected_revision) {
        renderer_->remove_spheres(selected_);
        selected_ = d.selected.empty() ? render::SphereSetHandle{} : renderer_->add_spheres(d.selected);
        selected_rev_ = d.selected_revision;
    }
}

void ViewWidget::paintGL() {
    QElapsedTimer timer;
    timer.start();
    upload();
    const render::Frame frame = scene_.frame(mesh_, spheres_, selected_);
    if (fit_pending_) {
        // What `spt render` does: fit the view to everything the frame shows.
        render::Bounds b = renderer_->bounds(frame);
        if (b.empty()) b.add(Eigen::Vector3f::Zero());
        const render::Camera fitted = render::fit_camera(camera_.view, b);
        camera_ = fitted;
        fit_pending_ = false;
    }
    const QSize fb = framebuffer_size();
    renderer_->draw(frame, camera_, render::Viewport{0, 0, fb.width(), fb.height()}, defaultFramebufferObject());
    drawn_ = true;
    last_draw_ms_ = double(timer.nsecsElapsed()) * 1e-6;
}

void ViewWidget::mousePressEvent(QMouseEvent* event) {
    setFocus(Qt::MouseFocusReason);
    press_ = last_ = event->position().toPoint();
    const Qt::KeyboardModifiers m = event->modifiers();
    if (event->button() == Qt::LeftButton && !(m & Qt::AltModifier)) {
        // The mode is fixed now: mouse moves carry no modifiers reliably.
        const Qt::KeyboardModifier add = options_.swap_modifiers ? Qt::ControlModifier : Qt::ShiftModifier;
        const Qt::KeyboardModifier sub = options_.swap_modifiers ? Qt::ShiftModifier : Qt::ControlModifier;
        mode_ = (m & add) ? SelectionMode::Add : (m & sub) ? SelectionMode::Subtract : SelectionMode::Replace;
        drag_ = Drag::Select;
        if (!band_) band_ = new QRubberBand(QRubberBand::Rectangle, this);
        band_->setGeometry(QRect(press_, QSize()));
        band_->show();
    } else if (event->button() == Qt::MiddleButton || (event->button() == Qt::LeftButton && (m & Qt::AltModifier))) {
        const bool orbit_camera = camera_.perspective() && !(m & Qt::ShiftModifier);
        drag_ = orbit_camera ? Drag::Orbit : Drag::Pan;
    }
}

void ViewWidget::mouseMoveEvent(QMouseEvent* event) {
    const QPoint p = event->position().toPoint();
    const QPoint d = p - last_;
    last_ = p;
    switch (drag_) {
    case Drag::Select: band_->setGeometry(QRect(press_, p).normalized()); break;
    case Drag::Pan: pan(camera_, float(d.x()), float(d.y()), width(), height()), update(); break;
    case Drag::Orbit: orbit(camera_, float(d.x()), float(d.y())), update(); break;
    case Drag::None: break;
    }
}

void ViewWidget::mouseReleaseEvent(QMouseEvent* event) {
    if (drag_ == Drag::Select && event->button() == Qt::LeftButton) finish_selection(event->position().toPoint());
    else if (drag_ != Drag::Select) drag_ = Drag::None;
}

void ViewWidget::finish_selection(const QPoint& end) {
    drag_ = Drag::None;
    if (band_) band_->hide();
    if (!doc_.has_tree()) return;
    // Logical pixels from the top left to GL window pixels from the bottom left.
    const double dpr = devicePixelRatioF();
    const float h = float(framebuffer_size().height());
    const PixelRect rect{float(press_.x() * dpr), h - float(press_.y() * dpr), float(end.x() * dpr),
                         h - float(end.y() * dpr)};
    const bool visible = options_.visible_only && doc_.mesh();
    const size_t hits = doc_.select_rect(view_projection(), rect, mode_, visible);
    emit message(QString("%1 samples in the rectangle (%2); %3 selected in node %4")
                     .arg(hits)
                     .arg(visible ? "visible only" : "through")
                     .arg(doc_.selection().size())
                     .arg(qulonglong(doc_.current())));
}

void ViewWidget::wheelEvent(QWheelEvent* event) {
    const float steps = float(event->angleDelta().y()) / 120.0f;
    if (steps == 0) return;
    const QPointF p = event->position();
    zoom_about(camera_, std::pow(1.15f, steps), float(p.x()), float(p.y()), width(), height());
    update();
}

void ViewWidget::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && drag_ == Drag::Select) {
        drag_ = Drag::None;
        if (band_) band_->hide();
        emit message("selection cancelled");
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

} // namespace spt::editor
