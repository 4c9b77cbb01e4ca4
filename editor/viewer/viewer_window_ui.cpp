// ViewerWindow: menus, toolbar, overlay toggles and PNG export.
#include "viewer_window.hpp"
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QSlider>
#include <QSpinBox>
#include <QThread>
#include <QToolBar>

namespace spt::editor {
namespace {

// Overlay toggles: name as `spt render --overlay` spells it, menu text, shortcut.
struct OverlayItem {
    const char* name;
    const char* text;
    const char* key;
};
const OverlayItem kOverlayItems[] = {
    {"contacts", "&Contact points", "C"},  {"normals", "Contact &normals", "N"},
    {"manifold", "Contact &manifolds (dynamics)", "M"},
    {"pairs", "Colliding sphere &pairs", "P"}, {"ghost", "&Ghost (pose before the response)", "G"},
    {"trails", "&Trails", "T"},             {"spheres", "&Sampling spheres", "S"},
    {"bounds", "&Bounding spheres", "B"},   {"broad", "Broa&d-phase spheres", "D"},
    {"grid", "G&rid", ""},                  {"axes", "&Axes", ""},
};

} // namespace

void ViewerWindow::build_actions() {
    QMenu* file = menuBar()->addMenu("&File");
    file->addAction("&Open...", QKeySequence::Open, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, "Open scene", QString(), "Scenes (*.json)");
        if (!path.isEmpty()) open(path);
    });
    file->addAction("&Reload", QKeySequence(Qt::Key_F5), this, &ViewerWindow::reload);
    file->addSeparator();
    file->addAction("&Export frame...", QKeySequence("Ctrl+E"), this, &ViewerWindow::export_frame_dialog);
    file->addAction("Export &range...", QKeySequence("Ctrl+Shift+E"), this, &ViewerWindow::export_range_dialog);
    file->addSeparator();
    file->addAction("&Quit", QKeySequence::Quit, this, &QWidget::close);

    QMenu* play = menuBar()->addMenu("&Playback");
    play_action_ = play->addAction("Play", QKeySequence(Qt::Key_Space), this, [this] { set_playing(!playing_); });
    play_action_->setCheckable(true);
    play->addAction("Step &forward", QKeySequence(Qt::Key_Right), this, [this] {
        set_playing(false);
        set_step(step() + 1);
    });
    play->addAction("Step &back", QKeySequence(Qt::Key_Left), this, [this] {
        set_playing(false);
        set_step(step() - 1);
    });
    play->addAction("F&irst step", QKeySequence(Qt::Key_Home), this, [this] { set_step(0); });
    play->addAction("&Last recorded step", QKeySequence(Qt::Key_End), this,
                    [this] { set_step(history_ ? history_->recorded() : 0); });

    QMenu* view = menuBar()->addMenu("&View");
    view->addAction("&Frame all", QKeySequence(Qt::Key_F), view_, &RenderView::frame_all);
    QMenu* overlays = menuBar()->addMenu("&Overlays");
    for (const OverlayItem& item : kOverlayItems) {
        QAction* a = overlays->addAction(item.text);
        a->setCheckable(true);
        a->setObjectName(QString("overlay_") + item.name);
        if (*item.key) a->setShortcut(QKeySequence(item.key));
        connect(a, &QAction::toggled, this, &ViewerWindow::overlay_toggled);
        overlay_actions_[item.name] = a;
    }
    set_overlays(overlays_); // check the actions
}

void ViewerWindow::build_toolbar() {
    QToolBar* bar = addToolBar("Playback");
    bar->setObjectName("playback");
    bar->setMovable(false);
    bar->addAction(play_action_);
    timeline_ = new QSlider(Qt::Horizontal, bar);
    timeline_->setObjectName("timeline");
    timeline_->setFocusPolicy(Qt::NoFocus); // Left and Right step the scene, not the slider
    timeline_->setMinimumWidth(300);
    timeline_->setRange(0, 0);
    connect(timeline_, &QSlider::valueChanged, this, [this](int v) {
        set_playing(false);
        set_step(v);
    });
    bar->addWidget(timeline_);
    step_label_ = new QLabel(bar);
    step_label_->setObjectName("step_label");
    step_label_->setMinimumWidth(260);
    bar->addWidget(step_label_);
    bar->addSeparator();
    bar->addWidget(new QLabel("speed ", bar));
    speed_box_ = new QComboBox(bar);
    speed_box_->setObjectName("speed");
    speed_box_->setFocusPolicy(Qt::NoFocus);
    for (double s : {0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 10.0}) speed_box_->addItem(QString("%1x").arg(s), s);
    if (speed_box_->findData(speed_) < 0) speed_box_->addItem(QString("%1x").arg(speed_), speed_);
    speed_box_->setCurrentIndex(speed_box_->findData(speed_));
    connect(speed_box_, &QComboBox::currentIndexChanged, this,
            [this](int i) { speed_ = speed_box_->itemData(i).toDouble(); });
    bar->addWidget(speed_box_);
    bar->addWidget(new QLabel("  view ", bar));
    view_box_ = new QComboBox(bar);
    view_box_->setObjectName("view_kind");
    view_box_->setFocusPolicy(Qt::NoFocus);
    for (render::View v : {render::View::Top, render::View::Front, render::View::Side, render::View::Camera})
        view_box_->addItem(render::view_name(v), int(v));
    view_box_->setCurrentIndex(view_box_->findData(int(view_->view())));
    connect(view_box_, &QComboBox::currentIndexChanged, this,
            [this](int i) { view_->set_view(render::View(view_box_->itemData(i).toInt())); });
    bar->addWidget(view_box_);
}

void ViewerWindow::overlay_toggled() {
    ViewerOverlays o = overlays_;
    for (const auto& [name, action] : overlay_actions_) *o.flag(name) = action->isChecked();
    set_overlays(o);
}

bool ViewerWindow::export_frames(int first, int last, const QString& pattern, QString* error) {
    if (!history_) return *error = "nothing to export: no scene is open", false;
    if (first < 0 || last < first || last > history_->target())
        return *error = QString("frames %1 to %2: expected 0 <= first <= last <= %3")
                            .arg(first)
                            .arg(last)
                            .arg(history_->target()),
               false;
    if (first != last && !pattern.contains("{frame}"))
        return *error = QString("%1: a range needs {frame} in the file name").arg(pattern), false;
    set_playing(false);
    const SceneHistory* h = history_.get();
    for (int k = first; k <= last; ++k) {
        // Steps not recorded yet: wait for the worker (the window stays live).
        while (h == history_.get() && h->recorded() < k && !h->finished()) {
            QApplication::processEvents(QEventLoop::AllEvents, 20);
            QThread::msleep(2);
        }
        if (h != history_.get()) return *error = "the scene was replaced during the export", false;
        if (h->recorded() < k) return *error = QString("step %1 was never recorded: %2").arg(k).arg(h->error()), false;
        set_step(k);
        QString name = pattern;
        name.replace("{frame}", QString::number(k));
        const QImage image = view_->grabFramebuffer();
        if (image.isNull() || !image.save(name, "PNG"))
            return *error = QString("%1: cannot write the PNG").arg(name), false;
    }
    show_message(QString("exported %1 frame(s) to %2").arg(last - first + 1).arg(pattern));
    return true;
}

void ViewerWindow::export_frame_dialog() {
    const QString path = QFileDialog::getSaveFileName(this, "Export frame", QString("frame%1.png").arg(step()),
                                                      "PNG images (*.png)");
    if (path.isEmpty()) return;
    QString error;
    if (!export_frames(step(), step(), path, &error)) show_error(error);
}

void ViewerWindow::export_range_dialog() {
    if (!history_) return show_error("nothing to export: no scene is open");
    QDialog dialog(this);
    dialog.setWindowTitle("Export range");
    auto* form = new QFormLayout(&dialog);
    auto* from = new QSpinBox(&dialog);
    auto* to = new QSpinBox(&dialog);
    from->setRange(0, history_->target()), to->setRange(0, history_->target());
    from->setValue(step()), to->setValue(history_->target());
    auto* name = new QLineEdit("frame{frame}.png", &dialog);
    form->addRow("First step", from);
    form->addRow("Last step", to);
    form->addRow("File ({frame} = step)", name);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    if (dialog.exec() != QDialog::Accepted) return;
    QString error;
    if (!export_frames(from->value(), to->value(), name->text(), &error)) show_error(error);
}

} // namespace spt::editor
