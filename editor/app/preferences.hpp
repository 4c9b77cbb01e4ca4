#pragma once
// The editor's preferences (Edit > Preferences): kept in QSettings, applied at once.
#include <QDialog>

class QCheckBox;
class QComboBox;
class QSpinBox;

namespace spt::editor {

/// What the user can set once for every session.
struct Preferences {
    int autosave_seconds = 30;   ///< recovery file period, seconds; 0 turns it off
    bool swap_modifiers = false; ///< Ctrl adds and Shift subtracts (MeshLab's habit)
    bool color_by_node = true;   ///< sampling spheres coloured by node (siblings contrast), else by level
    bool visible_only = false;   ///< rectangle selection starts visible-only (key X toggles)
};

/// The preferences saved in the application's settings (defaults where none are saved).
Preferences load_preferences();
/// Saves the preferences to the application's settings.
void save_preferences(const Preferences& preferences);

/// A dialog that edits a copy of the preferences.
class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    /// A dialog showing `current`.
    explicit PreferencesDialog(const Preferences& current, QWidget* parent = nullptr);
    /// The preferences as the dialog shows them.
    Preferences preferences() const;

private:
    QSpinBox* autosave_ = nullptr;
    QCheckBox* swap_ = nullptr;
    QComboBox* color_by_ = nullptr;
    QCheckBox* visible_ = nullptr;
};

} // namespace spt::editor
