// CostPanel: cost runs in the background, their figures as a table and a chart.
#include "cost_panel.hpp"
#include "spt/error.hpp"
#include "spt/motion_tree.hpp"
#include "spt/plot/chart.hpp"
#include "spt/pose_file.hpp"
#include "spt/spt_file.hpp"
#include "spt/tree_builder.hpp"
#include <QFileDialog>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QThread>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>

namespace spt::editor {
namespace {

// The worker: both trees' models over a copy of the document, the poses, the two runs.
CostReport measure(SptDocument doc, int tree, QString other, CostOptions options,
                   std::shared_ptr<std::atomic<bool>> cancel, QPointer<QProgressBar> bar,
                   std::shared_ptr<const MotionRecording> motion, QString motion_label) {
    CostReport r;
    r.against = other.isEmpty() ? QString("itself") : other;
    try {
        const std::string edited = doc.trees[size_t(tree)].name();
        r.tree = QString::fromStdString(edited);
        std::string automatic = "automatic";
        while (doc.tree(automatic)) automatic += "'";
        doc.trees.push_back(build_tree(automatic, doc.samples));
        const CollisionModel me(doc, edited), ma(doc, automatic);
        std::unique_ptr<CollisionModel> mb;
        SptDocument other_doc;
        if (!other.isEmpty()) {
            other_doc = load_spt(other.toStdString());
            mb = std::make_unique<CollisionModel>(other_doc);
        }
        r.poses = cost_poses(ma, mb ? *mb : ma, options);
        // With a motion, a third share of the bar is its run.
        const double part = motion ? 1.0 / 3.0 : 0.5;
        auto report = [bar, part](double base) {
            return [bar, base, part](double share) {
                QMetaObject::invokeMethod(bar, [bar, v = int(100 * (base + part * share))] {
                    if (bar) bar->setValue(v);
                });
            };
        };
        r.edited = measure_cost(me, mb ? *mb : me, r.poses, options, cancel.get(), report(0));
        r.automatic = measure_cost(ma, mb ? *mb : ma, r.poses, options, cancel.get(), report(part));
        if (motion && !r.edited.cancelled && !r.automatic.cancelled) {
            // The three trees on the recorded steps, at spt query's default query, taking turns.
            MotionBuildOptions built;
            built.build.threads = std::max(1, QThread::idealThreadCount());
            built.build.cancel = cancel.get();
            const SamplingTree for_motion = build_motion_tree("motion", doc.samples, *motion, built);
            r.motion = measure_motion_cost(*motion, {doc.tree(edited), doc.tree(automatic), &for_motion}, QueryOptions{}, 3,
                                           cancel.get(), report(2 * part));
            r.motion_label = motion_label;
        }
    } catch (const Cancelled&) {
        r.edited.cancelled = true;
    } catch (const std::exception& e) {
        r.error = QString::fromStdString(e.what());
    }
    return r;
}

QString micro(double ns) { return QString::number(ns * 1e-3, 'f', 2); }
QString count(double v) { return QString::number(v, 'f', 1); }

} // namespace

CostPanel::CostPanel(EditorDocument& doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* form = new QGridLayout;
    against_ = new QLabel("against: itself", this);
    other_button_ = new QPushButton("Other object...", this);
    connect(other_button_, &QPushButton::clicked, this, [this] {
        const QString p = QFileDialog::getOpenFileName(this, "Measure against", {}, "Sampling trees (*.spt)");
        set_other(p);
    });
    form->addWidget(against_, 0, 0, 1, 2);
    form->addWidget(other_button_, 0, 2);
    random_ = new QSpinBox(this);
    near_ = new QSpinBox(this);
    for (QSpinBox* s : {random_, near_}) s->setRange(1, 100000), s->setValue(100);
    form->addWidget(new QLabel("random poses", this), 1, 0);
    form->addWidget(random_, 1, 1);
    form->addWidget(new QLabel("near-contact poses", this), 2, 0);
    form->addWidget(near_, 2, 1);
    run_ = new QPushButton("Run", this);
    run_->setObjectName("cost_run");
    cancel_ = new QPushButton("Cancel", this);
    cancel_->setEnabled(false);
    form->addWidget(run_, 1, 2);
    form->addWidget(cancel_, 2, 2);
    layout->addLayout(form);
    progress_ = new QProgressBar(this);
    progress_->setRange(0, 100);
    progress_->hide();
    layout->addWidget(progress_);

    table_ = new QTableWidget(7, 2, this);
    table_->setObjectName("cost_table");
    table_->setHorizontalHeaderLabels({"edited tree", "automatic tree"});
    table_->setVerticalHeaderLabels({"median µs, random", "median µs, near", "node pairs, random", "node pairs, near",
                                     "sphere tests, random", "sphere tests, near", "memory KiB"});
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setMinimumHeight(7 * (table_->fontMetrics().height() + 6) + table_->horizontalHeader()->sizeHint().height() + 4);
    layout->addWidget(table_);
    // On the loaded motion: the edited, automatic and motion-built trees side by side.
    motion_label_ = new QLabel("on a motion: none loaded (File > Load motion...)", this);
    motion_label_->setWordWrap(true);
    layout->addWidget(motion_label_);
    motion_table_ = new QTableWidget(3, 3, this);
    motion_table_->setObjectName("cost_motion_table");
    motion_table_->setHorizontalHeaderLabels({"edited", "auto", "motion"});
    motion_table_->horizontalHeaderItem(2)->setToolTip("build_motion_tree over the same samples, for the loaded motion");
    motion_table_->setVerticalHeaderLabels({"median µs a step", "node pairs a query", "sphere tests a query"});
    motion_table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    motion_table_->verticalHeader()->setDefaultSectionSize(motion_table_->fontMetrics().height() + 6);
    motion_table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    motion_table_->setFixedHeight(3 * (motion_table_->fontMetrics().height() + 6) +
                                  motion_table_->horizontalHeader()->sizeHint().height() + 4);
    motion_table_->horizontalHeader()->setMinimumSectionSize(40);
    layout->addWidget(motion_table_);
    chart_ = new QLabel(this);
    chart_->setMinimumSize(260, 180);
    layout->addWidget(chart_);
    save_ = new QPushButton("Save poses for spt query...", this);
    save_->setEnabled(false);
    connect(save_, &QPushButton::clicked, this, [this] {
        const QString prefix = QFileDialog::getSaveFileName(this, "Save poses (PREFIX-random.txt, PREFIX-near.txt)");
        QString error;
        if (!prefix.isEmpty() && !save_poses(prefix, &error)) emit message(error);
    });
    layout->addWidget(save_);
    layout->addStretch();

    connect(run_, &QPushButton::clicked, this, &CostPanel::run);
    connect(cancel_, &QPushButton::clicked, this, &CostPanel::cancel);
    connect(&watcher_, &QFutureWatcher<CostReport>::finished, this, [this] {
        progress_->hide();
        run_->setEnabled(true);
        cancel_->setEnabled(false);
        CostReport r = watcher_.result();
        if (!r.error.isEmpty()) {
            emit message(r.error);
        } else if (r.edited.cancelled || r.automatic.cancelled ||
                   std::any_of(r.motion.begin(), r.motion.end(), [](const MotionCost& c) { return c.cancelled; })) {
            emit message("cost run cancelled");
        } else {
            report_ = std::make_unique<CostReport>(std::move(r));
            show_report();
            emit message(QString("cost run done: %1 random and %2 near-contact poses against %3")
                             .arg(report_->poses.random.size())
                             .arg(report_->poses.near.size())
                             .arg(report_->against));
        }
        emit finished();
    });
}

CostPanel::~CostPanel() {
    if (cancel_flag_) *cancel_flag_ = true;
    watcher_.waitForFinished();
}

bool CostPanel::run() {
    if (running() || !doc_.has_tree()) return false;
    CostOptions o;
    o.random_poses = random_->value();
    o.near_poses = near_->value();
    cancel_flag_ = std::make_shared<std::atomic<bool>>(false);
    progress_->setValue(0);
    progress_->show();
    run_->setEnabled(false);
    cancel_->setEnabled(true);
    emit message("cost run started");
    watcher_.setFuture(QtConcurrent::run(measure, doc_.document(), doc_.tree_index(), other_, o, cancel_flag_,
                                         QPointer<QProgressBar>(progress_), motion_, motion_name_));
    return true;
}

void CostPanel::cancel() {
    if (cancel_flag_) *cancel_flag_ = true;
}

void CostPanel::set_other(const QString& spt_path) {
    other_ = spt_path;
    against_->setText("against: " + (other_.isEmpty() ? QString("itself") : other_));
}

void CostPanel::set_motion(std::shared_ptr<const MotionRecording> motion, const QString& label) {
    motion_ = std::move(motion);
    motion_name_ = motion_ ? label : QString();
    motion_label_->setText(motion_ ? QString("on the motion %1 (%2 steps), with the tree built for it").arg(label).arg(motion_->steps.size())
                                   : QString("on a motion: none loaded (File > Load motion...)"));
}

void CostPanel::set_pose_counts(int random, int near) {
    random_->setValue(random);
    near_->setValue(near);
}

void CostPanel::show_report() {
    const CostReport& r = *report_;
    int col = 0;
    for (const TreeCost* c : {&r.edited, &r.automatic}) {
        const QStringList values = {micro(c->random.median_ns),       micro(c->near.median_ns),
                                    count(c->random.mean_node_pairs), count(c->near.mean_node_pairs),
                                    count(c->random.mean_sphere_tests), count(c->near.mean_sphere_tests),
                                    QString::number(double(c->memory_bytes) / 1024.0, 'f', 1)};
        for (int row = 0; row < values.size(); ++row) {
            auto* item = new QTableWidgetItem(values[row]);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            table_->setItem(row, col, item);
        }
        ++col;
    }
    motion_table_->clearContents();
    for (int col = 0; col < int(r.motion.size()) && col < 3; ++col) {
        const MotionCost& c = r.motion[size_t(col)];
        const QStringList values = {micro(c.median_ns), count(c.mean_node_pairs), count(c.mean_sphere_tests)};
        for (int row = 0; row < values.size(); ++row) {
            auto* item = new QTableWidgetItem(values[row]);
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            motion_table_->setItem(row, col, item);
        }
    }
    // Time against work: where each tree sits, at random and near-contact poses.
    plot::Chart chart;
    chart.x.title = "sphere tests per query";
    chart.y.title = "median µs per query";
    chart.x.scale = chart.y.scale = plot::Scale::Log10; // the trees differ by orders of magnitude
    chart.x.format = chart.y.format = [](double v) {
        return v >= 1e4 || v < 1e-2 ? QString("1e%1").arg(std::lround(std::log10(v))) : QString::number(v);
    };
    chart.style.font_px = 10, chart.style.title_px = 12;
    const std::pair<const TreeCost*, plot::Series> series[] = {
        {&r.edited, {"edited", plot::Marker::Disc, QColor(230, 120, 20), QColor(60, 60, 60), 9, {}}},
        {&r.automatic, {"automatic", plot::Marker::Square, QColor(40, 110, 220), QColor(60, 60, 60), 9, {}}},
    };
    for (auto [c, s] : series) {
        s.points = {{c->random.mean_sphere_tests, c->random.median_ns * 1e-3},
                    {c->near.mean_sphere_tests, c->near.median_ns * 1e-3}};
        chart.series.push_back(s);
    }
    const QSize size(std::max(chart_->width(), 260), 200);
    chart_->setPixmap(QPixmap::fromImage(plot::render_chart(chart, size, devicePixelRatioF())));
    save_->setEnabled(true);
}

bool CostPanel::save_poses(const QString& prefix, QString* error) const {
    if (!report_) return *error = "no cost run to save", false;
    for (const auto& [suffix, poses] : {std::make_pair(QString("-random.txt"), &report_->poses.random),
                                        std::make_pair(QString("-near.txt"), &report_->poses.near)}) {
        try {
            write_pose_file((prefix + suffix).toStdString(), *poses,
                            "B's poses in A's frame (tx ty tz qw qx qy qz), from the editor's cost run against " +
                                report_->against.toStdString());
        } catch (const Error& e) {
            return *error = QString::fromStdString(e.what()), false;
        }
    }
    return true;
}

} // namespace spt::editor
