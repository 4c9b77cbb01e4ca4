// ViewerWindow: histories (open, reload, re-record for overlays), playback and the shown state.
#include "viewer_window.hpp"
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QSlider>
#include <QStatusBar>
#include <QVBoxLayout>
#include <cmath>
#include <sys/stat.h>

namespace spt::editor {

ViewerWindow::ViewerWindow(const ViewerStart& start, QWidget* parent)
    : QMainWindow(parent), overlays_(start.overlays), speed_(start.speed) {
    setWindowTitle("spt-viewer");
    view_ = new SceneView(start.view, this);
    view_->set_overlays(overlays_);
    setCentralWidget(view_);
    connect(view_, &RenderView::message, this, &ViewerWindow::show_message);
    // The dock holds the step's counters and, under them, the energy so far.
    auto* dock_body = new QWidget(this);
    auto* dock_layout = new QVBoxLayout(dock_body);
    dock_layout->setContentsMargins(0, 0, 0, 0);
    counters_ = new CountersPanel(dock_body);
    energy_ = new EnergyPlot(dock_body);
    dock_layout->addWidget(counters_, 1);
    dock_layout->addWidget(energy_);
    auto* dock = new QDockWidget("Step counters", this);
    dock->setObjectName("counters_dock");
    dock->setWidget(dock_body);
    dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    addDockWidget(Qt::RightDockWidgetArea, dock);
    build_actions();
    build_toolbar();
    resize(1280, 800);

    play_timer_.setInterval(15);
    connect(&play_timer_, &QTimer::timeout, this, &ViewerWindow::tick);
    // Editors write a file in pieces (or replace it): reload once it has been quiet a moment.
    reload_timer_.setSingleShot(true);
    reload_timer_.setInterval(300);
    connect(&reload_timer_, &QTimer::timeout, this, &ViewerWindow::reload);
    connect(&watcher_, &QFileSystemWatcher::fileChanged, this, [this](const QString&) { reload_timer_.start(); });
    // The watcher can miss a change (a file replaced by rename at the wrong moment, or no inotify
    // instance left: Qt then polls by time stamps): a stat of the file every second backs it up.
    poll_timer_.setInterval(1000);
    connect(&poll_timer_, &QTimer::timeout, this, [this] {
        if (history_ && file_stamp(history_->path()) != watched_stamp_ && !reload_timer_.isActive()) reload_timer_.start();
    });
    poll_timer_.start();

    if (!start.file.isEmpty()) {
        open(start.file);
        pending_step_ = start.step;
        if (start.play) connect(this, &ViewerWindow::historyChanged, this, [this] { set_playing(true); },
                                Qt::SingleShotConnection);
    }
    show_state();
}

ViewerWindow::~ViewerWindow() = default;

void ViewerWindow::open(const QString& path) {
    show_message(QString("opening %1 ...").arg(path));
    start_pending(std::make_unique<SceneHistory>(path, overlays_.scene), 0, true);
}

void ViewerWindow::reload() {
    if (!history_) return;
    watch(history_->path());
    show_message(QString("%1 changed on disk: reloading ...").arg(history_->path()));
    start_pending(std::make_unique<SceneHistory>(history_->path(), overlays_.scene), kFollowShownStep, false);
}

void ViewerWindow::start_pending(std::unique_ptr<SceneHistory> h, int want_step, bool refit) {
    if (pending_) pending_.release()->deleteLater(); // superseded; it may be emitting
    pending_ = std::move(h);
    pending_step_ = want_step;
    pending_refit_ = refit;
    SceneHistory* p = pending_.get();
    connect(p, &SceneHistory::progressed, this, [this, p](int n) {
        if (p == pending_.get()) pending_progress(n);
        else if (p == history_.get()) show_state(); // the step label says how far recording has got
    });
    connect(p, &SceneHistory::stopped, this, [this, p] {
        if (p == pending_.get()) pending_progress(p->recorded());
        else if (p == history_.get()) show_state();
    });
    connect(p, &SceneHistory::failed, this, [this, p](const QString& message) {
        if (p == pending_.get() && !p->loaded()) {
            // Nothing replaced: the scene shown stays. (Deleted later: it is emitting.)
            pending_.release()->deleteLater();
            show_error(message);
            show_state();
            return;
        }
        show_error(message);
    });
    show_state();
}

void ViewerWindow::pending_progress(int recorded) {
    // Replace the shown history once the new one has reached the step shown, so playback
    // does not jump back while a scene is re-recorded.
    if (!pending_ || !pending_->loaded()) return;
    const int want = pending_step_ == kFollowShownStep ? step() : pending_step_;
    if (recorded >= std::min(want, pending_->target()) || pending_->finished()) adopt_pending();
    else show_message(QString("recording %1 / %2 ...").arg(recorded).arg(want));
}

void ViewerWindow::adopt_pending() {
    const bool refit = pending_refit_;
    const int want = pending_step_ == kFollowShownStep ? step() : pending_step_;
    const bool new_file = !history_ || history_->path() != pending_->path();
    if (history_) history_.release()->deleteLater(); // it may be emitting
    history_ = std::move(pending_);
    view_->set_history(history_.get(), refit);
    if (new_file) {
        watch(history_->path());
        setWindowTitle(QString("%1 - spt-viewer").arg(QFileInfo(history_->path()).fileName()));
        const std::string problem = render::scene_overlays_problem(history_->effects(), overlays_.scene);
        show_message(QString("%1: %2 objects, %3 steps of %4 s%5")
                         .arg(history_->path())
                         .arg(history_->scene().objects.size())
                         .arg(history_->target())
                         .arg(history_->scene().dt)
                         .arg(problem.empty() ? QString() : "; " + QString::fromStdString(problem)));
    } else {
        show_message(QString("%1 recorded again (effects %2)")
                         .arg(history_->path(), QString::fromStdString(history_->effects().names())));
    }
    timeline_->setMaximum(history_->target());
    set_step(want);
    emit historyChanged();
}

void ViewerWindow::set_step(int k) {
    const int last = history_ ? std::max(history_->recorded(), 0) : 0;
    view_->set_step(std::clamp(k, 0, last));
    show_state();
    emit stepShown(view_->step());
}

void ViewerWindow::show_state() {
    const int k = view_->step();
    if (!history_) {
        step_label_->setText(pending_ ? "loading ..." : "no scene");
        timeline_->setEnabled(false);
        counters_->show_step(nullptr, {}, 0);
        energy_->clear();
        return;
    }
    timeline_->setEnabled(true);
    {
        const QSignalBlocker block(timeline_);
        timeline_->setValue(k);
    }
    const int rec = history_->recorded();
    step_label_->setText(QString("step %1 / %2%3  t = %4 s")
                             .arg(k)
                             .arg(history_->target())
                             .arg(rec >= history_->target() ? QString()
                                  : history_->finished()  ? QString(" (stopped at %1)").arg(rec)
                                                          : QString(" (recorded %1)").arg(rec))
                             .arg(double(k) * history_->scene().dt, 0, 'f', 3));
    const auto s = history_->state(k);
    if (s) counters_->show_step(s->step ? &*s->step : nullptr, history_->effects(), state_hash(s->poses));
    const double dt = history_->scene().dt;
    energy_->show_energies(history_->energies(k), dt, double(history_->target()) * dt);
}

void ViewerWindow::set_playing(bool playing) {
    playing_ = playing && history_;
    play_action_->setChecked(playing_);
    play_action_->setText(playing_ ? "Pause" : "Play");
    carry_ = 0;
    if (playing_) {
        if (history_ && view_->step() >= history_->target()) set_step(0); // play again from the start
        clock_.start();
        play_timer_.start();
    } else {
        play_timer_.stop();
    }
}

void ViewerWindow::set_speed(double speed) {
    speed_ = std::clamp(speed, 0.01, 100.0);
    const int i = speed_box_->findData(speed_);
    if (i >= 0) speed_box_->setCurrentIndex(i);
}

void ViewerWindow::tick() {
    if (!history_ || !playing_) return;
    // Real time times the speed: dt seconds of the scene a step.
    const double seconds = double(clock_.restart()) * 1e-3;
    carry_ += seconds * speed_ / std::max(history_->scene().dt, 1e-9);
    const int advance = int(std::floor(carry_));
    if (advance <= 0) return;
    const int rec = history_->recorded();
    const int want = std::min(view_->step() + advance, history_->target());
    if (want > rec) {
        // Ahead of the recording: wait for it instead of skipping, or stop where it stopped.
        carry_ = 0;
        if (view_->step() < rec) set_step(rec);
        else if (history_->finished()) set_playing(false);
        return;
    }
    carry_ -= advance;
    set_step(want);
    if (want >= history_->target()) set_playing(false);
}

void ViewerWindow::set_overlays(const ViewerOverlays& overlays) {
    overlays_ = overlays;
    view_->set_overlays(overlays_);
    for (auto& [name, action] : overlay_actions_) {
        const QSignalBlocker block(action);
        action->setChecked(*overlays_.flag(name));
    }
    // Only what an overlay needs is simulated: record again when the effects differ.
    const SceneHistory* base = pending_ && pending_->loaded() ? pending_.get() : history_.get();
    if (!base || !base->loaded()) return;
    // An overlay the scene has nothing for (manifold without dynamics) stays on; the status bar says why it is empty.
    const std::string problem = render::scene_overlays_problem(base->scene().effects, overlays_.scene);
    if (!problem.empty()) show_message(QString::fromStdString(problem));
    const EffectSet want = render::effects_for_overlays(base->scene().effects, overlays_.scene);
    if (want.bits() == base->effects().bits()) return;
    start_pending(std::make_unique<SceneHistory>(base->shared_scene(), overlays_.scene), kFollowShownStep, false);
}

std::array<int64_t, 4> ViewerWindow::file_stamp(const QString& path) {
    struct stat st {};
    if (::stat(QFile::encodeName(path).constData(), &st) != 0) return {-1, -1, -1, -1};
    return {int64_t(st.st_ino), int64_t(st.st_size), int64_t(st.st_mtim.tv_sec), int64_t(st.st_mtim.tv_nsec)};
}

void ViewerWindow::watch(const QString& path) {
    // A file replaced by rename drops out of the watcher: add it again each time.
    if (!watcher_.files().isEmpty()) watcher_.removePaths(watcher_.files());
    if (QFileInfo::exists(path)) watcher_.addPath(path);
    watched_stamp_ = file_stamp(path);
}

void ViewerWindow::show_error(const QString& text) {
    last_error_ = text;
    show_message(text);
    // Window-modal and not blocking: the scene shown stays.
    auto* box = new QMessageBox(QMessageBox::Warning, "spt-viewer", text, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void ViewerWindow::show_message(const QString& text) {
    last_message_ = text;
    statusBar()->showMessage(text);
}

} // namespace spt::editor
