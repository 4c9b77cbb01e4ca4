// CountersPanel: one step's counters as `spt simulate` writes them.
#include "counters_panel.hpp"
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace spt::editor {

const QStringList& steps_csv_columns() {
    static const QStringList columns = {"step",        "time",         "candidate_pairs", "colliding_pairs",
                                        "node_pairs",  "sphere_tests", "triangle_tests",  "depth_queries",
                                        "ccd_queries", "responses",    "ns_broad",        "ns_narrow",
                                        "ns_depth",    "ns_ccd",       "ns_response",     "ns_deform",
                                        "ns_dynamics", "state_hash"};
    return columns;
}

CountersPanel::CountersPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    effects_ = new QLabel(this);
    effects_->setWordWrap(true);
    effects_->setObjectName("effects");
    layout->addWidget(effects_);
    table_ = new QTableWidget(int(steps_csv_columns().size()), 2, this);
    table_->setObjectName("counters");
    table_->setHorizontalHeaderLabels({"STEPS.csv column", "value"});
    table_->verticalHeader()->hide();
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    for (int r = 0; r < steps_csv_columns().size(); ++r) {
        table_->setItem(r, 0, new QTableWidgetItem(steps_csv_columns()[r]));
        auto* v = new QTableWidgetItem;
        v->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        table_->setItem(r, 1, v);
    }
    layout->addWidget(table_);
    show_step(nullptr, {}, 0);
}

void CountersPanel::show_step(const StepResult* step, EffectSet effects, uint64_t state_hash) {
    const std::string names = effects.names();
    // An empty list is written as the shell needs it, not as a dangling option.
    effects_->setText(QString("Effects simulated: %1.\nSame numbers as `spt simulate --effects %2`; ns_* are "
                              "nanoseconds of this run.")
                          .arg(names.empty() ? "none" : QString::fromStdString(names))
                          .arg(names.empty() ? "''" : QString::fromStdString(names)));
    const StepCounters c = step ? step->counters : StepCounters{};
    const QStringList values = {
        QString::number(step ? step->step : 0),
        QString::number(step ? step->time : 0.0, 'g', 9),
        QString::number(c.candidate_pairs),
        QString::number(c.colliding_pairs),
        QString::number(c.node_pairs),
        QString::number(c.sphere_tests),
        QString::number(c.triangle_tests),
        QString::number(c.depth_queries),
        QString::number(c.ccd_queries),
        QString::number(c.responses),
        QString::number(c.ns_broad),
        QString::number(c.ns_narrow),
        QString::number(c.ns_depth),
        QString::number(c.ns_ccd),
        QString::number(c.ns_response),
        QString::number(c.ns_deform),
        QString::number(c.ns_dynamics),
        QString("%1").arg(qulonglong(state_hash), 16, 16, QChar('0')),
    };
    for (int r = 0; r < values.size(); ++r) table_->item(r, 1)->setText(values[r]);
}

QString CountersPanel::value(const QString& column) const {
    const int r = int(steps_csv_columns().indexOf(column));
    return r < 0 ? QString() : table_->item(r, 1)->text();
}

} // namespace spt::editor
