// MainWindow: preferences applied and the dialog.
#include "main_window.hpp"
#include "tree_panel.hpp"
#include <QAction>
#include <QSignalBlocker>

namespace spt::editor {

void MainWindow::apply_preferences(const Preferences& p, bool save) {
    preferences_ = p;
    if (p.autosave_seconds > 0) autosave_timer_.start(p.autosave_seconds * 1000);
    else autosave_timer_.stop();
    options_.swap_modifiers = p.swap_modifiers;
    options_.visible_only = p.visible_only;
    for (auto [action, on] : {std::pair{swap_action_, p.swap_modifiers}, std::pair{visible_action_, p.visible_only}}) {
        const QSignalBlocker block(action);
        action->setChecked(on);
    }
    scene_.set_color_by(p.color_by_node ? render::ColorBy::Node : render::ColorBy::Level);
    panel_->show_color_by_node(p.color_by_node);
    if (save) save_preferences(p);
}

void MainWindow::show_preferences() {
    auto* dialog = new PreferencesDialog(preferences_, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        apply_preferences(dialog->preferences());
        show_message("preferences saved");
    });
    dialog->open();
}

} // namespace spt::editor
