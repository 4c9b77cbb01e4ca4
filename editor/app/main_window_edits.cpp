// MainWindow's edits: each becomes an undo command, or its refusal goes to the status bar.
#include "edit_commands.hpp"
#include "main_window.hpp"
#include "tree_panel.hpp"
#include "spt/error.hpp"
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
    // A large node: core builds it on a copy while the views stay live; the result is pushed
    // only if the document has not been edited meanwhile.
    build_stack_index_ = stack_.index();
    build_tree_index_ = doc_.tree_index();
    build_node_ = doc_.current();
    build_options_ = panel_->build_options();
    build_cancel_flag_ = std::make_shared<std::atomic<bool>>(false);
    build_pending_ = true;
    build_progress_->show();
    build_cancel_->show();
    show_message(QString("building a subtree under node %1 (%2 samples)...")
                     .arg(qulonglong(build_node_))
                     .arg(node->samples.size()));
    // The flag goes to this build only: the options kept for the undo stack hold none. The
    // worker holds the flag too, so it outlives a window closed while the build runs.
    BuildOptions options = build_options_;
    options.cancel = build_cancel_flag_.get();
    build_watcher_.setFuture(QtConcurrent::run(
        [tree = doc_.tree(), samples = doc_.samples(), id = build_node_, options, flag = build_cancel_flag_]() mutable {
            BuildJob job;
            try {
                const EditResult r = tree.build_subtree(id, samples, options);
                if (!r) job.refusal = QString::fromStdString(r.reason);
                job.tree = std::move(tree);
            } catch (const Cancelled&) {
                job.stopped = true;
            }
            return job;
        }));
    return true;
}

void MainWindow::build_finished() {
    build_pending_ = false;
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
