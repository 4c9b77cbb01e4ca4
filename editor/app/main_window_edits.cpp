// MainWindow's edits: each becomes an undo command, or its refusal goes to the status bar.
#include "edit_commands.hpp"
#include "main_window.hpp"
#include "tree_panel.hpp"

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
    return push(make_build_subtree(doc_, doc_.current(), panel_->build_options()));
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
