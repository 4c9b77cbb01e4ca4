// MainWindow's authoring from motion (issue 40): loading a scene's motion in the background,
// the heat map, builds from motion, and the cost panel's motion column.
#include "cost_panel.hpp"
#include "main_window.hpp"
#include "tree_panel.hpp"
#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QProgressBar>
#include <QPushButton>
#include <QThread>

namespace spt::editor {

bool MainWindow::load_motion(const QString& scene_path, const QString& object, int steps) {
    if (!doc_.has_tree()) return show_message("no document is open: open one before loading a motion"), false;
    if (motion_.loading()) return show_message("a motion is still being loaded"), false;
    // The scene runs with the edited tree in place of the object's model (core's record_motion).
    MotionModel model{std::make_shared<const SptDocument>(doc_.document()), doc_.tree().name(), doc_.shared_animation()};
    motion_progress_->setRange(0, 0);
    motion_progress_->show();
    motion_cancel_->show();
    show_message(QString("loading the motion of %1 in %2...").arg(object, scene_path));
    const bool started = motion_.load(scene_path, object, steps, std::move(model));
    update_title();
    return started;
}

void MainWindow::choose_motion() {
    if (!doc_.has_tree()) return show_message("no document is open: open one before loading a motion");
    const QString path = QFileDialog::getOpenFileName(this, "Load the motion of a scene", {}, "Scenes (*.json);;All files (*)");
    if (path.isEmpty()) return;
    const SceneObjects objects = read_scene_objects(path);
    if (!objects.error.isEmpty()) return show_error(objects.error);
    // The object whose model is this document's mesh comes first.
    const int match = matching_object(objects, QString::fromStdString(doc_.document().mesh.name), source_path_);
    bool ok = false;
    const QString object = QInputDialog::getItem(this, "Load motion", QString("Object of %1 to record with the edited tree")
                                                                          .arg(QFileInfo(path).fileName()),
                                                 objects.names, std::max(match, 0), false, &ok);
    if (ok && !object.isEmpty()) load_motion(path, object);
}

void MainWindow::motion_loaded() {
    update_title();
    motion_progress_->hide();
    motion_cancel_->hide();
    const std::shared_ptr<const MotionRecording> rec = motion_.recording();
    scene_.set_motion(rec);
    cost_->set_motion(rec, motion_.label());
    panel_->show_color_by(render::ColorBy::Contacts);
    scene_.set_color_by(render::ColorBy::Contacts);
    update_motion_actions();
    show_message(QString("motion %1: %2 steps, %3 in contact, a sample in contact at %4 steps at most")
                     .arg(motion_.label())
                     .arg(rec->steps.size())
                     .arg(rec->steps_in_contact)
                     .arg(rec->most_contact_steps));
}

void MainWindow::update_motion_actions() {
    if (!build_motion_action_) return;
    const TreeNode* node = doc_.has_tree() ? doc_.tree().find(doc_.current()) : nullptr;
    build_motion_action_->setEnabled(motion_.recording() && node && node->active && !build_pending_);
}

QString MainWindow::motion_scene_for_file() const {
    // Relative to the folder of the .spt file the tree goes to, when it is known (the recipe's rule).
    const QString scene = QFileInfo(motion_.scene_path()).absoluteFilePath();
    QString file = save_path_;
    if (file.isEmpty() && is_spt_file(source_path_)) file = source_path_;
    if (file.isEmpty()) return scene;
    return QDir(QFileInfo(file).absolutePath()).relativeFilePath(scene);
}

} // namespace spt::editor
