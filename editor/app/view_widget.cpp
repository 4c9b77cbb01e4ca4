// ViewWidget: the editor's scene in a RenderView, and rectangle, lasso and brush selection.
#include "view_widget.hpp"
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <cmath>

namespace spt::editor {

/// The outline of the stroke being drawn, a child widget composed over the view's picture (as
/// the view's title is): the framebuffer stays what `spt render` draws, and nothing shows when
/// nothing is drawn. Not antialiased, so its outline colour is exact (tests find it).
class StrokeOverlay : public QWidget {
public:
    explicit StrokeOverlay(QWidget* parent) : QWidget(parent) {
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setAttribute(Qt::WA_NoSystemBackground);
        setFocusPolicy(Qt::NoFocus);
    }
    /// Shows `tool`'s outline along `path` (logical pixels); `radius` for the brush; `active`:
    /// being dragged (else only the brush's circle at the cursor, or nothing).
    void show_stroke(SelectTool tool, const std::vector<QPointF>& path, double radius, bool active) {
        tool_ = tool, path_ = path, radius_ = radius, active_ = active;
        setVisible(active || (tool == SelectTool::Brush && !path.empty()));
        update();
    }
    void clear() {
        path_.clear();
        active_ = false;
        hide();
    }

protected:
    void paintEvent(QPaintEvent*) override {
        if (path_.empty()) return;
        QPainter p(this);
        const QColor outline = stroke_outline_color();
        QColor fill = outline;
        fill.setAlpha(60);
        const QPen pen(outline, 1.5);
        switch (tool_) {
        case SelectTool::Rectangle:
            if (path_.size() < 2) return;
            p.setPen(pen);
            p.setBrush(fill);
            p.drawRect(QRectF(path_.front(), path_.back()).normalized());
            break;
        case SelectTool::Lasso: {
            QPolygonF poly;
            for (const QPointF& q : path_) poly << q;
            p.setPen(pen);
            p.setBrush(fill);
            p.drawPolygon(poly); // closed from the last point to the first, as the lasso selects
            break;
        }
        case SelectTool::Brush: {
            if (active_) { // the band it has swept
                QPainterPath swept(path_.front());
                for (const QPointF& q : path_) swept.lineTo(q);
                p.setPen(QPen(fill, 2 * radius_, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
                p.drawPath(swept);
            }
            p.setPen(pen);
            p.setBrush(Qt::NoBrush);
            p.drawEllipse(path_.back(), radius_, radius_);
            break;
        }
        }
    }

private:
    SelectTool tool_ = SelectTool::Rectangle;
    std::vector<QPointF> path_;
    double radius_ = 0;
    bool active_ = false;
};

QColor stroke_outline_color() { return QColor(255, 128, 0); }

ViewWidget::ViewWidget(render::View view, EditorDocument& doc, Scene& scene, const ViewOptions& options,
                       QWidget* parent)
    : RenderView(view, parent), doc_(doc), scene_(scene), options_(options) {
    setMouseTracking(true); // the hover point: select linked picks there, the brush shows its circle there
    overlay_ = new StrokeOverlay(this);
    overlay_->hide();
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

Eigen::Vector2f ViewWidget::window_point(const QPointF& p) const {
    const double dpr = devicePixelRatioF();
    return {float(p.x() * dpr), float(framebuffer_size().height()) - float(p.y() * dpr)};
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
    // The mode and the tool are fixed now: mouse moves carry no modifiers reliably.
    const Qt::KeyboardModifiers m = event->modifiers();
    const Qt::KeyboardModifier add = options_.swap_modifiers ? Qt::ControlModifier : Qt::ShiftModifier;
    const Qt::KeyboardModifier sub = options_.swap_modifiers ? Qt::ShiftModifier : Qt::ControlModifier;
    mode_ = (m & add) ? SelectionMode::Add : (m & sub) ? SelectionMode::Subtract : SelectionMode::Replace;
    tool_ = options_.tool;
    selecting_ = true;
    path_ = {event->position()};
    overlay_->show_stroke(tool_, path_, options_.brush_radius, true);
    return true;
}

void ViewWidget::left_move(const QPoint& p) {
    if (!selecting_) return;
    switch (tool_) {
    case SelectTool::Rectangle: path_ = {path_.front(), QPointF(p)}; break;
    case SelectTool::Lasso:
    case SelectTool::Brush:
        // A point a pixel or more from the last: a slow drag does not pile up points.
        if (QLineF(path_.back(), QPointF(p)).length() >= 1.0) path_.push_back(QPointF(p));
        break;
    }
    overlay_->show_stroke(tool_, path_, options_.brush_radius, true);
}

void ViewWidget::end_stroke() {
    selecting_ = false;
    path_.clear();
    overlay_->clear();
}

void ViewWidget::left_release(const QPoint& end) {
    if (!selecting_) return; // cancelled with Esc
    left_move(end);
    std::vector<QPointF> path = std::move(path_);
    const SelectTool tool = tool_;
    end_stroke();
    if (!doc_.has_tree()) return;
    const bool visible = options_.visible_only && doc_.mesh();
    RecipeStroke stroke{view_projection(), {}, mode_, visible};
    QString shape;
    switch (tool) {
    case SelectTool::Rectangle: {
        const Eigen::Vector2f a = window_point(QPointF(press_)), b = window_point(QPointF(end));
        stroke.rect = {a.x(), a.y(), b.x(), b.y()};
        shape = "rectangle";
        break;
    }
    case SelectTool::Lasso:
        stroke.kind = StrokeKind::Lasso;
        for (const QPointF& q : path) stroke.points.push_back(window_point(q));
        shape = "lasso";
        if (stroke.points.size() < 3) {
            emit message("a lasso needs three points or more: drag around the samples");
            return;
        }
        break;
    case SelectTool::Brush:
        stroke.kind = StrokeKind::Brush;
        for (const QPointF& q : path) stroke.points.push_back(window_point(q));
        stroke.radius = float(options_.brush_radius * devicePixelRatioF());
        shape = "brush";
        break;
    }
    const size_t hits = doc_.apply(std::move(stroke));
    emit message(QString("%1 samples in the %2 (%3); %4 selected in node %5")
                     .arg(hits)
                     .arg(shape, visible ? "visible only" : "through")
                     .arg(doc_.selection().size())
                     .arg(qulonglong(doc_.current())));
}

void ViewWidget::select_linked(SelectionMode mode) {
    QString why;
    const bool visible = options_.visible_only && doc_.mesh();
    const size_t hits = doc_.select_linked(view_projection(), window_point(QPointF(hover_)), mode, visible, &why);
    if (!why.isEmpty()) return emit message("select linked: " + why);
    emit message(QString("%1 linked samples; %2 selected in node %3")
                     .arg(hits)
                     .arg(doc_.selection().size())
                     .arg(qulonglong(doc_.current())));
}

void ViewWidget::mouseMoveEvent(QMouseEvent* event) {
    hover_ = event->position().toPoint();
    emit hovered(this);
    if (!selecting_ && options_.tool == SelectTool::Brush) // the brush's circle follows the cursor
        overlay_->show_stroke(SelectTool::Brush, {event->position()}, options_.brush_radius, false);
    else if (!selecting_)
        overlay_->clear();
    RenderView::mouseMoveEvent(event);
}

void ViewWidget::leaveEvent(QEvent* event) {
    if (!selecting_) overlay_->clear();
    RenderView::leaveEvent(event);
}

void ViewWidget::resizeEvent(QResizeEvent* event) {
    overlay_->setGeometry(rect());
    RenderView::resizeEvent(event);
    if (legend_) legend_->move(width() - legend_->width() - 4, height() - legend_->height() - 4);
}

void ViewWidget::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && selecting_) {
        end_stroke();
        emit message("selection cancelled");
        return;
    }
    RenderView::keyPressEvent(event);
}

} // namespace spt::editor
