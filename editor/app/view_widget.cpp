// ViewWidget: the editor's scene in a RenderView, and rectangle selection.
#include "view_widget.hpp"
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QRubberBand>

namespace spt::editor {

ViewWidget::ViewWidget(render::View view, EditorDocument& doc, Scene& scene, const ViewOptions& options,
                       QWidget* parent)
    : RenderView(view, parent), doc_(doc), scene_(scene), options_(options) {
    connect(&scene_, &Scene::changed, this, qOverload<>(&QWidget::update));
    connect(&scene_, &Scene::changed, this, &ViewWidget::update_legend);
    connect(&doc_, &EditorDocument::documentReset, this, &ViewWidget::frame_all);
    // The heat map's legend: a Qt label composed over the picture (as the view's name is), so the
    // framebuffer stays what `spt render` draws.
    legend_ = new QLabel(this);
    legend_->setObjectName("heat_legend");
    legend_->setAttribute(Qt::WA_TransparentForMouseEvents);
    legend_->setStyleSheet("QLabel { color: #202020; background: rgba(255, 255, 255, 190); padding: 2px 5px; }");
    legend_->setTextFormat(Qt::RichText);
    legend_->hide();
}

void ViewWidget::update_legend() {
    const SceneData& d = scene_.data();
    if (d.legend.empty()) {
        legend_->hide();
        return;
    }
    QString html = QString("<b>steps in contact</b>%1<table cellspacing=0 cellpadding=0>").arg(d.heat.log ? " (log)" : "");
    for (const render::HeatLegendRow& row : d.legend) {
        const QColor c = QColor::fromRgbF(row.color.r, row.color.g, row.color.b);
        const QString range = row.to == row.from ? QString::number(row.from) : QString("%1-%2").arg(row.from).arg(row.to);
        html += QString("<tr><td><span style='color:%1'>&#9632;</span>&nbsp;</td><td align=right>%2</td>"
                        "<td>&nbsp;%3 samples</td></tr>")
                    .arg(c.name(), range)
                    .arg(row.samples);
    }
    if (d.heat.high == 0) html += "<tr><td colspan=3>no motion loaded or no contact</td></tr>";
    legend_->setText(html + "</table>");
    legend_->adjustSize();
    legend_->move(width() - legend_->width() - 4, height() - legend_->height() - 4);
    legend_->show();
}

void ViewWidget::resizeEvent(QResizeEvent* event) {
    RenderView::resizeEvent(event);
    if (legend_) legend_->move(width() - legend_->width() - 4, height() - legend_->height() - 4);
}

ViewProjection ViewWidget::view_projection() const {
    const QSize fb = framebuffer_size();
    ViewProjection v;
    v.view = camera().view_matrix();
    v.projection = camera().projection_matrix(float(fb.width()) / float(std::max(fb.height(), 1)));
    v.perspective = camera().perspective();
    v.width = fb.width();
    v.height = fb.height();
    return v;
}

void ViewWidget::frame_selection() {
    if (doc_.selection().empty()) return frame_all();
    render::Bounds b;
    for (uint32_t i : scene_.data().selected)
        b.add_sphere(render::local_frame(scene_.data().origin) * scene_.data().spheres[i].sphere.center,
                     scene_.data().spheres[i].sphere.radius);
    const render::Camera fitted = render::fit_camera(view(), b);
    camera_mut().target = fitted.target;
    camera_mut().radius = fitted.radius;
    camera_mut().zoom = 1;
    update();
}

void ViewWidget::forget_uploads() {
    mesh_rev_ = spheres_rev_ = selected_rev_ = pose_rev_ = 0;
    mesh_ = {}, spheres_ = {};
}

void ViewWidget::upload(render::Renderer& renderer) {
    const SceneData& d = scene_.data();
    if (mesh_rev_ != d.mesh_revision) {
        renderer.remove_mesh(mesh_);
        mesh_ = d.mesh ? renderer.add_mesh(*d.mesh, d.origin) : render::MeshHandle{};
        mesh_rev_ = d.mesh_revision;
        pose_rev_ = 0; // uploaded at the bind pose
    }
    if (pose_rev_ != d.pose_revision) {
        if (mesh_.id && d.vertices) renderer.update_mesh(mesh_, *d.vertices, *d.normals, d.origin);
        pose_rev_ = d.pose_revision;
    }
    if (spheres_rev_ != d.spheres_revision) {
        renderer.remove_spheres(spheres_);
        spheres_ = d.spheres.empty() ? render::SphereSetHandle{} : renderer.add_spheres(d.spheres);
        spheres_rev_ = d.spheres_revision;
        selected_rev_ = 0; // a new set has no marks
    }
    if (selected_rev_ != d.selected_revision) {
        if (spheres_.id) renderer.set_sphere_marks(spheres_, d.selected);
        selected_rev_ = d.selected_revision;
    }
}

render::Frame ViewWidget::frame() const { return scene_.frame(mesh_, spheres_); }

bool ViewWidget::left_press(QMouseEvent* event) {
    press_ = event->position().toPoint();
    // The mode is fixed now: mouse moves carry no modifiers reliably.
    const Qt::KeyboardModifiers m = event->modifiers();
    const Qt::KeyboardModifier add = options_.swap_modifiers ? Qt::ControlModifier : Qt::ShiftModifier;
    const Qt::KeyboardModifier sub = options_.swap_modifiers ? Qt::ShiftModifier : Qt::ControlModifier;
    mode_ = (m & add) ? SelectionMode::Add : (m & sub) ? SelectionMode::Subtract : SelectionMode::Replace;
    selecting_ = true;
    if (!band_) band_ = new QRubberBand(QRubberBand::Rectangle, this);
    band_->setGeometry(QRect(press_, QSize()));
    band_->show();
    return true;
}

void ViewWidget::left_move(const QPoint& p) {
    if (selecting_) band_->setGeometry(QRect(press_, p).normalized());
}

void ViewWidget::left_release(const QPoint& end) {
    if (!selecting_) return; // cancelled with Esc
    selecting_ = false;
    band_->hide();
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

void ViewWidget::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && selecting_) {
        selecting_ = false;
        band_->hide();
        emit message("selection cancelled");
        return;
    }
    RenderView::keyPressEvent(event);
}

} // namespace spt::editor
