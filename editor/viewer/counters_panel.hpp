#pragma once
// The viewer's counters panel: what one step did, under the column names of
// `spt simulate`'s STEPS.csv, so a row there and this panel show the same numbers.
#include "spt/simulation.hpp"
#include <QWidget>

class QLabel;
class QTableWidget;

namespace spt::editor {

/// Counters and time per effect of the step shown.
class CountersPanel : public QWidget {
    Q_OBJECT
public:
    /// An empty panel.
    explicit CountersPanel(QWidget* parent = nullptr);
    /// Shows `step` (nullptr: the initial state, every counter 0), simulated with `effects`,
    /// and `state_hash` of the state shown.
    void show_step(const StepResult* step, EffectSet effects, uint64_t state_hash);
    /// The value shown for a STEPS.csv column (e.g. "node_pairs"), as text; empty if unknown.
    QString value(const QString& column) const;

private:
    QLabel* effects_ = nullptr;
    QTableWidget* table_ = nullptr;
};

/// The STEPS.csv columns of `spt simulate`, in order.
const QStringList& steps_csv_columns();

} // namespace spt::editor
