// The viewer and scene files: reload when the file changes on disk, and bad files refused
// with a message naming the file while the scene shown stays.
#include "viewer_support.hpp"
#include <QTest>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <gtest/gtest.h>

using namespace spt;
using namespace spt::test;

namespace {

const char* kEffects = R"(["motion","gravity","contacts","depth","response"])";

std::unique_ptr<editor::ViewerWindow> open_viewer(const QString& scene) {
    editor::ViewerStart start;
    start.file = scene;
    auto w = std::make_unique<editor::ViewerWindow>(start);
    w->show();
    return w;
}

} // namespace

TEST(ViewerFiles, ReloadsWhenTheSceneFileChangesOnDiskAndKeepsTheStep) {
    TempDir dir("viewer-reload");
    const QString scene = write_drop_scene(dir, 40, kEffects);
    auto w = open_viewer(scene);
    ASSERT_TRUE(wait_recorded(*w, 40));
    w->set_step(25);
    const editor::SceneHistory* before = w->history();
    // Written over in place, as an editor saves: more steps.
    QTest::qWait(1100); // a new modification time on file systems with one-second stamps
    write_drop_scene(dir, 90, kEffects);
    ASSERT_TRUE(QTest::qWaitFor([&] { return w->history() != before && !w->busy(); }, 60000))
        << "no reload: " << w->last_message().toStdString();
    EXPECT_EQ(w->history()->target(), 90);
    EXPECT_EQ(w->step(), 25);
    // Replaced by rename, as many editors save: still followed.
    const editor::SceneHistory* second = w->history();
    const QString other = QString::fromStdString(dir.file("other.json"));
    // Written aside (the watched file itself is not touched), then renamed over it.
    std::ifstream in(scene.toStdString());
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string ninety = "\"steps\": 90";
    text.replace(text.find(ninety), ninety.size(), "\"steps\": 7");
    std::ofstream(other.toStdString()) << text;
    std::filesystem::rename(other.toStdString(), scene.toStdString());
    ASSERT_TRUE(QTest::qWaitFor([&] { return w->history() != second && !w->busy() && w->history()->target() == 7; },
                                60000))
        << "a file replaced by rename was not reloaded: " << w->last_message().toStdString();
}

TEST(ViewerFiles, BrokenSceneOnDiskIsReportedAndTheSceneShownStays) {
    TempDir dir("viewer-broken");
    const QString scene = write_drop_scene(dir, 30, kEffects);
    auto w = open_viewer(scene);
    ASSERT_TRUE(wait_recorded(*w, 30));
    w->set_step(12);
    const editor::SceneHistory* good = w->history();
    QTest::qWait(1100);
    std::ofstream(scene.toStdString()) << "{\"spt_scene\": 1, \"dt\": -0.01, \"objects\": []}";
    ASSERT_TRUE(QTest::qWaitFor([&] { return !w->last_error().isEmpty(); }, 60000));
    EXPECT_TRUE(w->last_error().contains(scene)) << w->last_error().toStdString();
    EXPECT_TRUE(w->last_error().contains("dt")) << w->last_error().toStdString();
    EXPECT_EQ(w->history(), good);
    EXPECT_EQ(w->step(), 12);
}

TEST(ViewerFiles, BadSceneFilesAreRefusedWithTheFileAndTheProblem) {
    TempDir dir("viewer-bad");
    const QString scene = write_drop_scene(dir, 20, kEffects);
    auto w = open_viewer(scene);
    ASSERT_TRUE(wait_recorded(*w, 20));
    const editor::SceneHistory* good = w->history();
    struct Case {
        const char* name;
        const char* text;
        const char* expect; // in the message besides the file name
    };
    const Case cases[] = {
        {"not_json.json", "{\"spt_scene\": 1, ", ""},
        {"missing_model.json", "{\"spt_scene\": 1, \"objects\": [{\"name\": \"a\", \"model\": \"nowhere.spt\"}]}",
         "nowhere.spt"},
        {"unknown_field.json", "{\"spt_scene\": 1, \"colour\": 3, \"objects\": []}", "colour"},
        {"unknown_effect.json", "{\"spt_scene\": 1, \"effects\": [\"magic\"], \"objects\": []}", "magic"},
    };
    for (const Case& c : cases) {
        const std::string path = dir.file(c.name);
        std::ofstream(path) << c.text;
        w->open(QString::fromStdString(path));
        ASSERT_TRUE(QTest::qWaitFor([&] { return !w->busy(); }, 60000)) << c.name;
        EXPECT_TRUE(w->last_error().contains(QString::fromStdString(path))) << w->last_error().toStdString();
        EXPECT_TRUE(w->last_error().contains(c.expect)) << w->last_error().toStdString();
        EXPECT_EQ(w->history(), good) << c.name << " replaced the scene shown";
    }
    w->open(QString::fromStdString(dir.file("does_not_exist.json")));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !w->busy(); }, 60000));
    EXPECT_TRUE(w->last_error().contains("does_not_exist.json")) << w->last_error().toStdString();
    EXPECT_EQ(w->history(), good);
}

TEST(ViewerFiles, ASceneThatFailsMidwayKeepsWhatWasRecordedAndPlaybackStopsThere) {
    TempDir dir("viewer-midway");
    const std::string scenes = std::string(SPT_SOURCE_DIR) + "/resources/scenes";
    // 2.5e15 a step: the fifth step would carry the box past 1e16, which is refused.
    const std::string path = dir.file("runaway.json");
    std::ofstream(path) << R"({"spt_scene": 1, "dt": 0.01, "steps": 50, "effects": ["motion"], "objects": [
        {"name": "box", "model": ")" << scenes << R"(/crate.spt", "velocity": [2.5e17, 0, 0]}]})";
    auto w = open_viewer(QString::fromStdString(path));
    ASSERT_TRUE(QTest::qWaitFor([&] { return w->history() && w->history()->finished() && !w->busy(); }, 60000));
    EXPECT_EQ(w->history()->recorded(), 4);
    EXPECT_TRUE(w->last_error().contains("leaves the representable range")) << w->last_error().toStdString();
    EXPECT_TRUE(w->last_error().contains("'box'")) << w->last_error().toStdString();
    w->set_speed(10);
    w->set_playing(true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !w->playing(); }, 30000)) << "playback never stopped";
    EXPECT_EQ(w->step(), 4);
}
