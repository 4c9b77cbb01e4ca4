#pragma once
// A spin box for a sampling-sphere radius at any model scale: six significant digits shown
// ("1.2e-07" as well as "350"), scientific notation accepted when typed, steps of a tenth
// of the leading digit. QDoubleSpinBox alone rounds to a fixed number of decimals, so a
// model 10^-4 units across showed its radii as the box's minimum and Set wrote that.
#include <QDoubleSpinBox>

namespace spt::editor {

/// A positive radius in model units.
class RadiusBox : public QDoubleSpinBox {
    Q_OBJECT
public:
    explicit RadiusBox(QWidget* parent = nullptr);
    QString textFromValue(double value) const override;
    double valueFromText(const QString& text) const override;
    QValidator::State validate(QString& text, int& pos) const override;
};

} // namespace spt::editor
