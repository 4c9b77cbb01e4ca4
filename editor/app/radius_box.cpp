// RadiusBox: significant digits instead of fixed decimals.
#include "radius_box.hpp"
#include <QLocale>
#include <cfloat>

namespace spt::editor {

RadiusBox::RadiusBox(QWidget* parent) : QDoubleSpinBox(parent) {
    // Qt rounds every value to `decimals` places: enough places for the smallest normal float
    // (a radius is stored as one), shown through textFromValue, not as so many digits.
    setDecimals(DBL_MAX_10_EXP + DBL_DIG);
    setRange(FLT_MIN, 1e30);
    setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
}

QString RadiusBox::textFromValue(double value) const { return locale().toString(value, 'g', 6); }

double RadiusBox::valueFromText(const QString& text) const {
    bool ok = false;
    const double v = locale().toDouble(text.trimmed(), &ok);
    return ok ? v : value();
}

QValidator::State RadiusBox::validate(QString& text, int&) const {
    const QString t = text.trimmed();
    if (!specialValueText().isEmpty() && t == specialValueText()) return QValidator::Acceptable;
    if (t.isEmpty()) return QValidator::Intermediate;
    bool ok = false;
    const double v = locale().toDouble(t, &ok);
    if (ok) return v >= minimum() && v <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
    // On the way to a number: "1e", "1.5e-", "-", "."
    static const QString partial = "0123456789.,eE+-";
    for (const QChar c : t)
        if (!partial.contains(c)) return QValidator::Invalid;
    return QValidator::Intermediate;
}

} // namespace spt::editor
