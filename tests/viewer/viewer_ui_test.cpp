// The viewer as a user plays a scene: play, pause, step back and forth, overlays that need
// effects, the counters against `spt simulate`, and every frame against `spt render` of the
// same scene, step, view and size.
#include "viewer_support.hpp"
#include <QAction>
#include <QFile>
#include <QProcess>
#include <QSlider>
#include <QTest>
#include <gtest/gtest.h>

using namespace spt;
using namespace spt::test;

namespace {

const char* kResponseEffects = R"(["motion","gravity","contacts","depth","response"])";

// `spt simulate SCENE` as CSV rows, header first.
std::vector<QStringList> simulate_rows(const QString& scene) {
    QProcess spt;
    spt.start(QString(SPT_BINARY_DIR) + "/cli/spt", {"simulate", scene});
    if (!spt.waitForFinished(300000) || spt.exitCode() != 0) return {};
    std::vector<QStringList> rows;
    for (const QByteArray& line : spt.readAllStandardOutput().split('\n'))
        if (!line.isEmpty()) rows.push_back(QString::fromUtf8(line).split(','));
    return rows;
}

} // namespace

TEST(ViewerUi, FrameEqualsSptRenderOfTheSameSceneStepViewAndSize) {
    TempDir dir("viewer-vs-render");
    const QString scene = write_drop_scene(dir, 60, kResponseEffects);
    editor::ViewerOverlays o;
    o.scene.contacts = o.scene.normals = o.scene.trails = o.scene.bounds = o.scene.broad = o.scene.ghost = true;
    auto w = show_viewer(scene, o, render::View::Camera, 45);
    ASSERT_TRUE(wait_recorded(*w, 45)) << w->last_error().toStdString();
    ASSERT_TRUE(wait_idle(*w));
    ASSERT_EQ(w->step(), 45);
    const QString overlays = "contacts,normals,trails,bounds,broad,ghost,grid,axes";
    for (render::View v : {render::View::Camera, render::View::Front}) {
        const std::string view = render::view_name(v);
        for (int step : {0, 45}) {
            render::Image shown;
            std::string error;
            const render::CompareResult r = compare_with_spt_render(*w, dir, scene, step, v, overlays, shown, error);
            ASSERT_TRUE(error.empty()) << error;
            ASSERT_EQ(shown.width, 320 * int(w->view()->devicePixelRatioF()));
            EXPECT_TRUE(r.passed) << view << " step " << step << ": " << r.summary();
            render::write_png(shown, viewer_output_dir() + "/viewer_" + view + "_" + std::to_string(step) + ".png");
        }
    }
}

TEST(ViewerUi, SpacePlaysAndPausesArrowsStepBackAndForth) {
    TempDir dir("viewer-play");
    auto w = show_viewer(write_drop_scene(dir, 400, kResponseEffects), {}, render::View::Camera, 0);
    ASSERT_TRUE(wait_recorded(*w, 0));
    ASSERT_TRUE(wait_idle(*w));
    w->set_speed(4);
    QTest::keyClick(w->view(), Qt::Key_Space);
    EXPECT_TRUE(w->playing());
    EXPECT_TRUE(QTest::qWaitFor([&] { return w->step() >= 12; }, 60000));
    QTest::keyClick(w->view(), Qt::Key_Space);
    EXPECT_FALSE(w->playing());
    const int paused = w->step();
    EXPECT_GE(paused, 12);
    QTest::qWait(200);
    EXPECT_EQ(w->step(), paused) << "paused playback moved on";
    QTest::keyClick(w->view(), Qt::Key_Left);
    EXPECT_EQ(w->step(), paused - 1);
    QTest::keyClick(w->view(), Qt::Key_Left);
    EXPECT_EQ(w->step(), paused - 2);
    QTest::keyClick(w->view(), Qt::Key_Right);
    EXPECT_EQ(w->step(), paused - 1);
    QTest::keyClick(w->view(), Qt::Key_Home);
    EXPECT_EQ(w->step(), 0);
    QTest::keyClick(w->view(), Qt::Key_Left);
    EXPECT_EQ(w->step(), 0) << "stepped back past the initial state";
    ASSERT_TRUE(wait_recorded(*w, 400));
    QTest::keyClick(w->view(), Qt::Key_End);
    EXPECT_EQ(w->step(), 400);
    QTest::keyClick(w->view(), Qt::Key_Right);
    EXPECT_EQ(w->step(), 400) << "stepped past the last step";
    // The timeline scrubs.
    auto* timeline = w->findChild<QSlider*>("timeline");
    ASSERT_TRUE(timeline);
    timeline->setValue(123);
    EXPECT_EQ(w->step(), 123);
}

TEST(ViewerUi, CountersShowTheNumbersOfSptSimulate) {
    TempDir dir("viewer-counters");
    const QString scene = write_drop_scene(dir, 60, kResponseEffects);
    const std::vector<QStringList> rows = simulate_rows(scene);
    ASSERT_EQ(rows.size(), 61u);
    ASSERT_EQ(rows[0], editor::steps_csv_columns());
    auto w = show_viewer(scene, {}, render::View::Camera, 60);
    ASSERT_TRUE(wait_recorded(*w, 60));
    int colliding_steps = 0;
    for (int k = 1; k <= 60; ++k) {
        w->set_step(k);
        for (int c = 0; c < rows[0].size(); ++c) {
            if (rows[0][c].startsWith("ns_")) continue; // times of another run
            const QString shown = w->counters()->value(rows[0][c]);
            if (rows[0][c] == "time") EXPECT_DOUBLE_EQ(shown.toDouble(), rows[size_t(k)][c].toDouble());
            else EXPECT_EQ(shown, rows[size_t(k)][c]) << "step " << k << " column " << rows[0][c].toStdString();
        }
        colliding_steps += w->counters()->value("colliding_pairs").toInt() > 0;
        // A stage that ran took time; one that is off shows 0.
        EXPECT_EQ(w->counters()->value("ns_ccd"), "0");
        EXPECT_NE(w->counters()->value("ns_broad"), "0");
    }
    EXPECT_GT(colliding_steps, 0) << "the box never reached the floor: the test scene does not test contacts";
}

TEST(ViewerUi, OverlayThatNeedsAnEffectRecordsAgainAndKeepsTheStep) {
    TempDir dir("viewer-effects");
    auto w = show_viewer(write_drop_scene(dir, 60, R"(["motion","gravity","contacts"])"), {}, render::View::Camera,
                         50);
    ASSERT_TRUE(wait_recorded(*w, 50));
    ASSERT_TRUE(wait_idle(*w));
    ASSERT_EQ(w->step(), 50);
    EXPECT_FALSE(w->history()->effects().has(Effect::Depth));
    EXPECT_EQ(w->counters()->value("depth_queries"), "0");
    auto* contacts = w->findChild<QAction*>("overlay_contacts");
    ASSERT_TRUE(contacts);
    contacts->trigger();
    ASSERT_TRUE(wait_recorded(*w, 50));
    EXPECT_TRUE(w->history()->effects().has(Effect::Depth)) << "the contacts overlay needs depth";
    EXPECT_EQ(w->step(), 50) << "recording again moved the playhead";
    int depth_queries = 0;
    for (int k = 1; k <= 50; ++k) w->set_step(k), depth_queries += w->counters()->value("depth_queries").toInt();
    EXPECT_GT(depth_queries, 0);
    // Off again, while playing: only what the scene asks for is simulated, and the new
    // recording takes over without sending the playhead back.
    w->set_step(10);
    w->set_speed(0.25);
    w->set_playing(true);
    const editor::SceneHistory* before = w->history();
    contacts->trigger();
    const int at_toggle = w->step();
    ASSERT_TRUE(QTest::qWaitFor([&] { return w->history() != before && !w->busy(); }, 60000));
    EXPECT_FALSE(w->history()->effects().has(Effect::Depth));
    EXPECT_GE(w->step(), at_toggle) << "re-recording sent the playhead back";
    w->set_playing(false);
}

TEST(ViewerUi, ExportRangeWritesOnePngAStepEqualToSptRender) {
    TempDir dir("viewer-export");
    const QString scene = write_drop_scene(dir, 40, kResponseEffects);
    auto w = show_viewer(scene, {}, render::View::Side, 0);
    ASSERT_TRUE(wait_recorded(*w, 0));
    ASSERT_TRUE(wait_idle(*w));
    QString error;
    const QString pattern = QString::fromStdString(dir.file("out_{frame}.png"));
    ASSERT_TRUE(w->export_frames(30, 32, pattern, &error)) << error.toStdString();
    for (int k = 30; k <= 32; ++k)
        EXPECT_TRUE(QFile::exists(QString::fromStdString(dir.file("out_" + std::to_string(k) + ".png"))));
    const render::Image exported = render::read_png(dir.file("out_31.png"));
    std::string render_error;
    const render::Image expected =
        spt_render_frame(dir, scene, 31, "side", QSize(exported.width, exported.height), "grid,axes", &render_error);
    ASSERT_TRUE(render_error.empty()) << render_error;
    render::Image opaque = exported;
    for (size_t k = 3; k < opaque.rgba.size(); k += 4) opaque.rgba[k] = 255;
    const render::CompareResult r = render::compare_images(opaque, expected);
    EXPECT_TRUE(r.passed) << r.summary();
    // Refused, with the reason: a range without {frame}, a step past the scene, no write access.
    EXPECT_FALSE(w->export_frames(1, 2, QString::fromStdString(dir.file("one.png")), &error));
    EXPECT_TRUE(error.contains("{frame}")) << error.toStdString();
    EXPECT_FALSE(w->export_frames(0, 41, pattern, &error));
    EXPECT_FALSE(w->export_frames(3, 3, "/proc/nope/frame.png", &error));
    EXPECT_TRUE(error.contains("/proc/nope/frame.png")) << error.toStdString();
}

TEST(ViewerUi, BundledFig8SceneShowsItsCollisionAtStep30) {
    // The paper's Fig. 8: two objects on random motions collide and are moved back. The
    // window is saved for docs/viewer.md and the README.
    editor::ViewerOverlays o;
    o.scene.contacts = o.scene.normals = o.scene.ghost = o.scene.trails = true;
    auto w = show_viewer(QString(SPT_SOURCE_DIR) + "/resources/scenes/fig8.json", o, render::View::Camera, 30);
    w->view()->setMinimumSize(0, 0);
    w->view()->setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
    w->resize(1100, 640);
    ASSERT_TRUE(wait_recorded(*w, 30)) << w->last_error().toStdString();
    ASSERT_TRUE(wait_idle(*w));
    ASSERT_EQ(w->step(), 30);
    EXPECT_EQ(w->counters()->value("colliding_pairs"), "1");
    EXPECT_EQ(w->counters()->value("responses"), "1");
    QTest::qWait(300);
    w->grab().save(QString::fromStdString(viewer_output_dir() + "/viewer_window.png"));
}
