// Preferences: QSettings keys and the dialog.
#include "preferences.hpp"
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSettings>
#include <QSpinBox>
#include <algorithm>

namespace spt::editor {

Preferences load_preferences() {
    QSettings s;
    Preferences p;
    // A hand-edited settings file with nonsense gets the default, not a negative period.
    bool ok = false;
    const int seconds = s.value("preferences/autosave_seconds", p.autosave_seconds).toInt(&ok);
    p.autosave_seconds = ok && seconds >= 0 ? std::min(seconds, 86400) : 30;
    p.swap_modifiers = s.value("preferences/swap_modifiers", false).toBool();
    p.color_by_node = s.value("preferences/color_by_node", true).toBool();
    p.visible_only = s.value("preferences/visible_only", false).toBool();
    return p;
}

void save_preferences(const Preferences& p) {
    QSettings s;
    s.setValue("preferences/autosave_seconds", p.autosave_seconds);
    s.setValue("preferences/swap_modifiers", p.swap_modifiers);
    s.setValue("preferences/color_by_node", p.color_by_node);
    s.setValue("preferences/visible_only", p.visible_only);
}

PreferencesDialog::PreferencesDialog(const Preferences& current, QWidget* parent) : QDialog(parent) {
    setWindowTitle("Preferences");
    auto* form = new QFormLayout(this);
    autosave_ = new QSpinBox(this);
    autosave_->setObjectName("autosave_seconds");
    autosave_->setRange(0, 86400);
    autosave_->setSuffix(" s");
    autosave_->setSpecialValueText("off");
    autosave_->setValue(current.autosave_seconds);
    form->addRow("Recovery file every", autosave_);
    swap_ = new QCheckBox("Ctrl adds, Shift subtracts (MeshLab)", this);
    swap_->setObjectName("swap_modifiers");
    swap_->setChecked(current.swap_modifiers);
    form->addRow("Selection keys", swap_);
    visible_ = new QCheckBox("Visible only (X toggles)", this);
    visible_->setObjectName("visible_only");
    visible_->setChecked(current.visible_only);
    form->addRow("Selection starts", visible_);
    color_by_ = new QComboBox(this);
    color_by_->setObjectName("color_by");
    color_by_->addItems({"level", "node"});
    color_by_->setCurrentIndex(current.color_by_node ? 1 : 0);
    form->addRow("Colour spheres by", color_by_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

Preferences PreferencesDialog::preferences() const {
    Preferences p;
    p.autosave_seconds = autosave_->value();
    p.swap_modifiers = swap_->isChecked();
    p.color_by_node = color_by_->currentIndex() == 1;
    p.visible_only = visible_->isChecked();
    return p;
}

} // namespace spt::editor
