// MainWindow's edits: each becomes an undo command, or its refusal goes to the status bar.
#include "edit_commands.hpp"
#include "main_window.hpp"
#include "tree_panel.hpp"
#include "spt/error.hpp"
#include "spt/motion_tree.hpp"
#include <QProgressBar>
#include <QPushButton>
#include <QtConcurrent/QtConcurrentRun>

namespace spt::editor {

bool MainWindow::push(EditOutcome outcome) {
    if (!outcome.command) {
        show_message(outcome.reason);
        return false;
    }
    const QString text = outcome.command->text();
    stack_.push(outcome.command.release());
    show_message(text);
    return true;
}

bool MainWindow::split() { return push(make_split(doc_)); }

bool MainWindow::merge() { return push(make_merge(doc_, doc_.current())); }

bool MainWindow::set_radius(float radius) { return push(make_set_radius(doc_, doc_.current(), radius)); }

bool MainWindow::build_subtree() {
    if (building()) return push({nullptr, "a subtree is still being built"});
    const TreeNode* node = doc_.has_tree() ? doc_.tree().find(doc_.current()) : nullptr;
    if (!node || node->samples.size() < background_build_samples_)
        return push(make_build_subtree(doc_, doc_.current(), panel_->build_options()));
    return start_build(doc_.current(), node->samples.size(), false);
}

bool MainWindow::build_from_motion() {
    if (building()) return push({nullptr, "a subtree is still being built"});
    const std::shared_ptr<const MotionRecording> rec = motion_.recording();
    if (!rec) return push({nullptr, "no motion is loaded: File > Load motion..."});
    const TreeNode* node = doc_.has_tree() ? doc_.tree().find(doc_.current()) : nullptr;
    if (!node || !node->active)
        return push({nullptr, QString("node %1 is not active: build from motion under an active node")
                                  .arg(qulonglong(doc_.current()))});
    build_motion_step_ = MotionBuildStep{};
    build_motion_step_.node = doc_.current();
    build_motion_step_.scene = motion_scene_for_file().toStdString();
    build_motion_step_.object = rec->object;
    build_motion_step_.steps = motion_.steps();
    build_motion_step_.leaf_size = panel_->build_options().leaf_size;
    build_motion_label_ = motion_.label();
    // Always in the background: the tree is built on a copy, the views stay live.
    return start_build(doc_.current(), node->samples.size(), true);
}

bool MainWindow::start_build(NodeId id, size_t samples, bool from_motion) {
    // Core builds on a copy while the views stay live; the result is pushed only if the document
    // has not been edited meanwhile.
    build_motion_ = from_motion;
    build_stack_index_ = stack_.index();
    build_tree_index_ = doc_.tree_index();
    build_node_ = id;
    build_options_ = panel_->build_options();
    build_cancel_flag_ = std::make_shared<std::atomic<bool>>(false);
    build_pending_ = true;
    build_progress_->show();
    build_cancel_->show();
    update_motion_actions();
    show_message(QString("building %1 under node %2 (%3 samples)...")
                     .arg(from_motion ? "for the motion " + build_motion_label_ : QString("a subtree"))
                     .arg(qulonglong(id))
                     .arg(samples));
    // The flag goes to this build only: the options kept for the undo stack hold none. The
    // worker holds the flag too, so it outlives a window closed while the build runs.
    BuildOptions options = build_options_;
    options.cancel = build_cancel_flag_.get();
    build_watcher_.setFuture(QtConcurrent::run([tree = doc_.tree(), samples = doc_.samples(), id, options,
                                                flag = build_cancel_flag_,
                                                rec = from_motion ? motion_.recording() : nullptr]() mutable {
        BuildJob job;
        try {
            MotionBuildOptions motion_options;
            motion_options.build = options;
            const EditResult r = rec ? build_motion_subtree(tree, id, samples, *rec, motion_options)
                                     : tree.build_subtree(id, samples, options);
            if (!r) job.refusal = QString::fromStdString(r.reason);
            job.tree = std::move(tree);
        } catch (const Cancelled&) {
            job.stopped = true;
        } catch (const std::exception& e) {
            job.refusal = QString::fromStdString(e.what());
        }
        return job;
    }));
    return true;
}

void MainWindow::build_finished() {
    build_pending_ = false;
    update_motion_actions();
    build_progress_->hide();
    build_cancel_->hide();
    BuildJob job = build_watcher_.result();
    const bool cancelled = build_cancel_flag_ && *build_cancel_flag_;
    build_cancel_flag_.reset();
    if (job.stopped) return show_message("building the subtree cancelled");
    if (cancelled) return show_message("building the subtree cancelled (it had finished; not applied)");
    if (!job.refusal.isEmpty()) return show_message(job.refusal);
    if (stack_.index() != build_stack_index_ || doc_.tree_index() != build_tree_index_)
        return show_message("the tree was edited while the subtree was being built: not applied, build again");
    doc_.set_current(build_node_);
    if (build_motion_)
        push(make_built_motion_subtree(doc_, build_node_, std::move(*job.tree), build_motion_step_, build_motion_label_));
    else
        push(make_built_subtree(doc_, build_node_, std::move(*job.tree), build_options_));
}

bool MainWindow::add_tree(const QString& name) {
    return push(make_add_tree(doc_, name.isEmpty() ? unused_tree_name(doc_, "tree") : name));
}

bool MainWindow::rename_tree(const QString& name) { return push(make_rename_tree(doc_, doc_.tree_index(), name)); }

bool MainWindow::duplicate_tree(const QString& name) {
    if (!doc_.has_tree()) return push({nullptr, "no document is open"});
    const QString base = QString::fromStdString(doc_.tree().name()) + " copy";
    return push(make_duplicate_tree(doc_, doc_.tree_index(), name.isEmpty() ? unused_tree_name(doc_, base) : name));
}

bool MainWindow::delete_tree() { return push(make_delete_tree(doc_, doc_.tree_index())); }

} // namespace spt::editor
