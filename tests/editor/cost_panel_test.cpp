// The cost panel: a run in the background from the Run button, the edited tree next to the
// automatic one, and its figures equal to `spt query` at the poses it saves.
#include "cost_panel.hpp"
#include "editor_support.hpp"
#include <QDockWidget>
#include <QFile>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <gtest/gtest.h>

using namespace spt;
using namespace spt::test;

TEST(CostPanel, RunShowsTheEditedTreeNextToTheAutomaticOneAsSptQueryCountsIt) {
    TempDir dir("editor-cost");
    std::string error;
    const auto w = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(w) << error;
    // The edited tree is 'authored': every sample in the root, as an author starts.
    ASSERT_EQ(w->document().tree().name(), "authored");
    editor::CostPanel& panel = w->cost_panel();
    panel.set_pose_counts(30, 40);
    auto* run = panel.findChild<QPushButton*>("cost_run");
    ASSERT_TRUE(run);
    QSignalSpy finished(&panel, &editor::CostPanel::finished);
    QTest::mouseClick(run, Qt::LeftButton);
    EXPECT_TRUE(panel.running());
    ASSERT_TRUE(finished.wait(300000));
    ASSERT_TRUE(panel.report()) << w->last_message().toStdString();
    const editor::CostReport& r = *panel.report();
    ASSERT_EQ(r.poses.random.size(), 30u);
    ASSERT_EQ(r.poses.near.size(), 40u);
    // The paper's claim, measured: one leaf of every sample tests far more sphere pairs.
    EXPECT_GT(r.edited.near.mean_sphere_tests, 3 * r.automatic.near.mean_sphere_tests);
    auto* table = panel.findChild<QTableWidget*>("cost_table");
    ASSERT_TRUE(table && table->item(5, 0) && table->item(5, 1));
    EXPECT_EQ(table->item(5, 0)->text(), QString::number(r.edited.near.mean_sphere_tests, 'f', 1));
    // For docs/editor.md: the whole panel (the dock scrolls it when the window is short).
    w->findChild<QDockWidget*>("cost_dock")->raise();
    QTest::qWait(200);
    panel.grab().save(QString::fromStdString(editor_output_dir() + "/editor_cost_panel.png"));

    // The same numbers as spt query at the saved poses, on the saved document.
    const QString spt_file = QString::fromStdString(dir.file("saved.spt"));
    ASSERT_TRUE(w->save_to(spt_file));
    QString save_error;
    const QString prefix = QString::fromStdString(dir.file("cost"));
    ASSERT_TRUE(panel.save_poses(prefix, &save_error)) << save_error.toStdString();
    QProcess spt;
    spt.start(QString(SPT_BINARY_DIR) + "/cli/spt",
              {"query", spt_file, spt_file, "--tree", "authored", "--poses", prefix + "-near.txt"});
    ASSERT_TRUE(spt.waitForFinished(120000));
    ASSERT_EQ(spt.exitCode(), 0) << spt.readAllStandardError().toStdString();
    const QList<QByteArray> lines = spt.readAllStandardOutput().trimmed().split('\n');
    ASSERT_EQ(lines.size(), 41); // header + one row a pose
    for (int i = 0; i < 40; ++i) {
        const QList<QByteArray> f = lines[i + 1].split(','); // pose,collide,depth,backtrack,node_pairs,sphere_tests,ns
        EXPECT_EQ(f[4].toULongLong(), r.edited.near.counters[size_t(i)].node_pairs) << "pose " << i;
        EXPECT_EQ(f[5].toULongLong(), r.edited.near.counters[size_t(i)].sphere_tests) << "pose " << i;
    }
    EXPECT_FALSE(panel.save_poses("/proc/nope/cost", &save_error));
    EXPECT_TRUE(save_error.contains("/proc/nope/cost")) << save_error.toStdString();
}

TEST(CostPanel, CancelDropsTheRunAndABadOtherObjectIsReported) {
    TempDir dir("editor-cost-cancel");
    std::string error;
    const auto w = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(w) << error;
    editor::CostPanel& panel = w->cost_panel();
    panel.set_pose_counts(20000, 20000);
    QSignalSpy finished(&panel, &editor::CostPanel::finished);
    ASSERT_TRUE(panel.run());
    EXPECT_FALSE(panel.run()) << "a second run started while one was running";
    QTest::qWait(300);
    panel.cancel();
    ASSERT_TRUE(finished.wait(120000));
    EXPECT_EQ(panel.report(), nullptr);
    EXPECT_EQ(w->last_message(), "cost run cancelled");
    // Another object that is not a .spt file: the message names it, nothing is shown.
    const std::string bad = dir.file("not.spt");
    QFile f(QString::fromStdString(bad));
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("not a tree");
    f.close();
    panel.set_other(QString::fromStdString(bad));
    panel.set_pose_counts(5, 5);
    ASSERT_TRUE(panel.run());
    ASSERT_TRUE(finished.wait(120000));
    EXPECT_TRUE(w->last_message().contains("not.spt")) << w->last_message().toStdString();
    EXPECT_EQ(panel.report(), nullptr);
}
