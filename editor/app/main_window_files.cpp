// MainWindow's files: background opening, atomic saves, recent files, recovery.
#include "main_window.hpp"
#include "tree_panel.hpp"
#include "spt/error.hpp"
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QUndoView>
#include <QtConcurrent/QtConcurrentRun>

namespace spt::editor {

void MainWindow::open_file(const QString& path, const QString& mesh_path) {
    if (watcher_.isRunning()) {
        show_message("a file is still being opened");
        return;
    }
    if (modified() && !discard_on_open_ && !maybe_save()) return;
    cancelled_ = false;
    opening_ = true;
    progress_->show();
    cancel_->show();
    show_message(QString("opening %1...").arg(path));
    open_cancel_ = std::make_shared<std::atomic<bool>>(false);
    // Stage names come from the worker thread; the message is shown on the UI thread while
    // this opening is still the one running.
    auto stage = [this, path, flag = open_cancel_](const std::string& name) {
        QMetaObject::invokeMethod(this, [this, path, flag, name] {
            if (flag == open_cancel_ && !*flag) show_message(QString("opening %1: %2...").arg(path, QString::fromStdString(name)));
        }, Qt::QueuedConnection);
    };
    watcher_.setFuture(QtConcurrent::run([path, mesh_path, flag = open_cancel_, stage] {
        return load_document(path, mesh_path, flag.get(), stage);
    }));
    update_title();
}

void MainWindow::loaded(const LoadResult& r) {
    if (!r.doc) {
        // The open document stays as it was.
        show_error(r.error);
        return;
    }
    if (r.doc->trees.empty()) {
        show_error(QString("%1: holds no sampling tree").arg(r.path));
        return;
    }
    const bool recovered = recovering_;
    recovering_ = false;
    stack_.clear();
    doc_.reset(*r.doc, r.mesh, r.animated);
    history_->setEmptyLabel(recovered ? QString("Recovered unsaved work") : QString("Opened %1").arg(QFileInfo(r.path).fileName()));
    source_path_ = r.path;
    mesh_path_ = r.mesh_path;
    // A converted mesh or a recovered document exists nowhere on disk yet.
    unsaved_new_ = r.converted || recovered;
    if (!start_.output.isEmpty()) save_path_ = start_.output;
    else if (recovered) save_path_ = pending_save_path_;
    else save_path_ = r.converted ? QString() : r.path;
    if (!r.converted && !recovered) add_recent(r.path);
    update_title();
    if (!r.warning.isEmpty()) show_error(r.warning);
    else show_message(QString("%1: %2 samples, %3 tree(s)").arg(r.path).arg(r.doc->samples.size()).arg(r.doc->trees.size()));
    // A motion's counts and poses belong to the document it was recorded with.
    motion_.clear();
    measured_.clear();
    panel_->set_measured(measured_);
    if (start_motion_pending_) { // --scene: the motion of the command line, once
        start_motion_pending_ = false;
        QString object = start_.object;
        if (object.isEmpty()) {
            // The object whose model is the document's, known now that the document is in.
            const SceneObjects objects = read_scene_objects(start_.scene);
            const int match = matching_object(objects, QString::fromStdString(doc_.document().mesh.name), source_path_);
            if (match < 0)
                return show_error(QString("%1: no object's model or mesh is %2 or %3; name one with --object or File > "
                                          "Load motion ('%4')")
                                      .arg(start_.scene, QFileInfo(source_path_).fileName(),
                                           QString::fromStdString(doc_.document().mesh.name), objects.names.join("', '")));
            object = objects.names[match];
        }
        load_motion(start_.scene, object, start_.motion_steps);
    }
}

bool MainWindow::save_to(const QString& path) {
    if (!doc_.has_tree()) {
        show_error("nothing to save: no document is open");
        return false;
    }
    try {
        save_spt(doc_.document(), path.toStdString());
    } catch (const std::exception& e) {
        show_error(QString::fromStdString(e.what()));
        return false;
    }
    save_path_ = path;
    unsaved_new_ = false;
    stack_.setClean();
    recovery_.clear();
    add_recent(path);
    update_title();
    show_message(QString("saved %1").arg(path));
    return true;
}

bool MainWindow::save() { return save_path_.isEmpty() ? save_as() : save_to(save_path_); }

bool MainWindow::save_as() {
    const QString path = QFileDialog::getSaveFileName(this, "Save sampling trees", save_path_, "Sampling trees (*.spt)");
    return !path.isEmpty() && save_to(path);
}

void MainWindow::autosave() {
    if (!modified() || !doc_.has_tree()) return;
    QString error;
    if (!recovery_.write(doc_.encode(), save_path_, mesh_path_, source_path_, &error))
        show_message("recovery file not written: " + error);
}

bool MainWindow::offer_recovery() {
    const std::vector<RecoveryEntry> entries = recovery_.orphans();
    if (entries.empty()) return false;
    const RecoveryEntry& e = entries.front();
    const QString what = e.save_path.isEmpty() ? e.source : e.save_path;
    const auto answer = QMessageBox::question(
        this, "Recover unsaved work",
        QString("spt-editor stopped with unsaved changes to %1 (recovery file written %2). Recover them?")
            .arg(what, e.written.toLocalTime().toString()),
        QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
    if (answer != QMessageBox::Yes) {
        for (const RecoveryEntry& old : entries) Recovery::discard(old);
        return false;
    }
    // Loaded synchronously: the recovery file is the app's own, already a .spt.
    LoadResult r = load_document(e.spt_path, e.mesh_path);
    for (const RecoveryEntry& old : entries) Recovery::discard(old);
    if (!r.doc) {
        show_error(r.error);
        return false;
    }
    // The recovered work wins over a file still opening from the command line.
    cancelled_ = true;
    progress_->hide();
    cancel_->hide();
    recovering_ = true;
    pending_save_path_ = e.save_path;
    r.path = e.source;
    r.mesh_path = e.mesh_path;
    loaded(r);
    autosave(); // this process now holds the recovered work
    return true;
}

void MainWindow::add_recent(const QString& path) {
    QStringList recent = recent_files();
    const QString abs = QFileInfo(path).absoluteFilePath();
    recent.removeAll(abs);
    recent.prepend(abs);
    while (recent.size() > 10) recent.removeLast();
    QSettings().setValue("recent", recent);
    refresh_recent();
}

QStringList MainWindow::recent_files() const { return QSettings().value("recent").toStringList(); }

bool MainWindow::revert() {
    if (source_path_.isEmpty() || unsaved_new_) {
        show_message("nothing to revert to: the document has not been saved to a file");
        return false;
    }
    if (modified()) {
        const auto answer = QMessageBox::question(
            this, "Revert", QString("Revert to %1? The unsaved changes are lost.").arg(source_path_),
            QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Discard) return false;
    }
    // The changes stay (and count as unsaved) until the file has loaded; open_file must not
    // ask to save them.
    discard_on_open_ = true;
    open_file(source_path_, mesh_path_);
    discard_on_open_ = false;
    return true;
}

void MainWindow::refresh_recent() {
    recent_menu_->clear();
    for (const QString& p : recent_files())
        recent_menu_->addAction(p, this, [this, p] { open_file(p); });
    recent_menu_->setEnabled(!recent_menu_->isEmpty());
}

} // namespace spt::editor
