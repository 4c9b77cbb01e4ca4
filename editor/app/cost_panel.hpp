#pragma once
// The cost panel: what the edited tree costs at query time next to the automatic tree of
// the same samples (paper: regions likely to collide belong high in the tree). Runs core's
// cost run (spt/tree_cost.hpp) in the background on demand; the figures are those
// `spt query` reports for the same poses, which the panel can save as pose files.
#include "editor_document.hpp"
#include "spt/motion.hpp"
#include "spt/tree_cost.hpp"
#include <QFutureWatcher>
#include <QWidget>
#include <atomic>
#include <memory>

class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace spt::editor {

/// One finished cost run.
struct CostReport {
    TreeCost edited;     ///< the tree being edited
    TreeCost automatic;  ///< build_tree's default tree of the same samples
    CostPoses poses;     ///< B's poses in A's frame, as measured
    QString against;     ///< "itself" or the other object's file
    QString error;       ///< non-empty: the run failed (file and problem)
    QString tree;        ///< the edited tree's name
    /// On the loaded motion's recorded steps (measure_motion_cost), when one was loaded: the
    /// edited, automatic and motion-built (build_motion_tree) trees, in that order; else empty.
    std::vector<MotionCost> motion;
    QString motion_label; ///< the motion measured on ("walking.json / walker"), or empty
};

/// Runs and shows cost runs of an EditorDocument's edited tree.
class CostPanel : public QWidget {
    Q_OBJECT
public:
    /// A panel for `doc`, which must outlive it.
    explicit CostPanel(EditorDocument& doc, QWidget* parent = nullptr);
    ~CostPanel() override;
    /// Starts a run in the background (Run); false if one is running or no tree is open.
    bool run();
    /// Stops the running run (Cancel); its figures are dropped.
    void cancel();
    /// True while a run is in the background.
    bool running() const { return watcher_.isRunning(); }
    /// Measures against the first tree of this .spt file instead of the object itself; empty: itself.
    void set_other(const QString& spt_path);
    /// The motion the next runs also measure on (null: none), called `label`.
    void set_motion(std::shared_ptr<const MotionRecording> motion, const QString& label);
    /// Random and near-contact poses of the next run.
    void set_pose_counts(int random, int near);
    /// The last finished run (null before one).
    const CostReport* report() const { return report_.get(); }
    /// Writes the last run's poses as `spt query` pose files PREFIX-random.txt and PREFIX-near.txt;
    /// false with the file and problem in `error`.
    bool save_poses(const QString& prefix, QString* error) const;

signals:
    /// A run finished (or failed, or was cancelled: then report() is unchanged).
    void finished();
    /// A one-line message for the status bar.
    void message(const QString& text);

private:
    void show_report();
    EditorDocument& doc_;
    QString other_;
    QPushButton *run_ = nullptr, *cancel_ = nullptr, *other_button_ = nullptr, *save_ = nullptr;
    QLabel *against_ = nullptr, *chart_ = nullptr;
    QSpinBox *random_ = nullptr, *near_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QTableWidget* table_ = nullptr;
    QTableWidget* motion_table_ = nullptr; // the motion's rows: the three trees side by side
    QLabel* motion_label_ = nullptr;
    std::shared_ptr<const MotionRecording> motion_;
    QString motion_name_;
    QFutureWatcher<CostReport> watcher_;
    std::shared_ptr<std::atomic<bool>> cancel_flag_;
    std::unique_ptr<CostReport> report_;
};

} // namespace spt::editor
