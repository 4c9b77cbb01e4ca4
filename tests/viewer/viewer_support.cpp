// Viewer test helpers and the one QApplication of the binary.
#include "viewer_support.hpp"
#include <QApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QTest>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

namespace spt::test {
namespace {

class ViewerEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        ::setenv("QT_QPA_PLATFORM", "xcb", 1);
        spt::editor::use_render_gl_format();
        app_ = std::make_unique<QApplication>(argc_, argv_);
        QApplication::setApplicationName("spt-viewer-test");
    }
    void TearDown() override { app_.reset(); }

private:
    int argc_ = 1;
    char name_[16] = "viewer_tests";
    char* argv_[2] = {name_, nullptr};
    std::unique_ptr<QApplication> app_;
};

[[maybe_unused]] ::testing::Environment* const g_env = ::testing::AddGlobalTestEnvironment(new ViewerEnvironment);

bool wait_for(const std::function<bool()>& done, int timeout_ms) {
    QElapsedTimer t;
    t.start();
    while (!done()) {
        if (t.elapsed() > timeout_ms) return false;
        QTest::qWait(10);
    }
    return true;
}

} // namespace

QString write_drop_scene(const TempDir& dir, int steps, const char* effects_json) {
    const std::string scenes = std::string(SPT_SOURCE_DIR) + "/resources/scenes";
    const std::string path = dir.file("drop.json");
    std::ofstream(path) << "{\n  \"spt_scene\": 1, \"dt\": 0.01, \"steps\": " << steps << ",\n  \"effects\": "
                        << effects_json << ",\n  \"response\": {\"rule\": \"backtrack\", \"restitution\": 0.4},\n"
                        << "  \"objects\": [\n    {\"name\": \"floor\", \"model\": \"" << scenes
                        << "/slab.spt\", \"static\": true, \"position\": [0, -0.25, 0]},\n"
                        << "    {\"name\": \"box\", \"model\": \"" << scenes
                        << "/crate.spt\", \"position\": [0.1, 0.6, -0.2], \"velocity\": [0.5, 0, 0],"
                        << " \"angular_velocity\": [0.3, 0, 0.8]}\n  ]\n}\n";
    return QString::fromStdString(path);
}

std::unique_ptr<editor::ViewerWindow> show_viewer(const QString& scene, const editor::ViewerOverlays& overlays,
                                                  render::View view, int step) {
    editor::ViewerStart start;
    start.file = scene;
    start.overlays = overlays;
    start.view = view;
    start.step = step;
    auto w = std::make_unique<editor::ViewerWindow>(start);
    w->view()->setFixedSize(320, 240);
    w->show();
    return w;
}

bool wait_recorded(editor::ViewerWindow& w, int k, int timeout_ms) {
    return wait_for(
        [&] {
            const editor::SceneHistory* h = w.history();
            return !w.busy() && h && (h->recorded() >= k || h->finished());
        },
        timeout_ms);
}

bool wait_idle(editor::ViewerWindow& w, int timeout_ms) {
    if (!QTest::qWaitForWindowExposed(&w)) return false;
    // Shortcuts (Space, Left, Right) reach only the active window.
    w.activateWindow();
    if (!QTest::qWaitForWindowActive(&w)) return false;
    return wait_for([&] { return !w.busy() && w.view()->has_drawn(); }, timeout_ms);
}

render::Image spt_render_frame(const TempDir& dir, const QString& scene, int frame, const char* view, QSize size,
                               const QString& overlays, std::string* error) {
    const QString png = QString::fromStdString(dir.file("render_" + std::to_string(frame) + "_" + view + ".png"));
    QProcess spt;
    spt.start(QString(SPT_BINARY_DIR) + "/cli/spt",
              {"render", scene, "--frame", QString::number(frame), "--view", view, "--size",
               QString("%1x%2").arg(size.width()).arg(size.height()), "--overlay", overlays, "-o", png});
    if (!spt.waitForFinished(300000) || spt.exitCode() != 0) {
        *error = "spt render failed: " + spt.readAllStandardError().toStdString();
        return {};
    }
    render::Image image = render::read_png(png.toStdString());
    for (size_t k = 3; k < image.rgba.size(); k += 4) image.rgba[k] = 255;
    return image;
}

render::CompareResult compare_with_spt_render(editor::ViewerWindow& w, const TempDir& dir, const QString& scene, int step,
                                              render::View view, const QString& overlays, render::Image& shown,
                                              std::string& error) {
    w.view()->set_view(view);
    w.set_step(step);
    shown = to_image(w.view()->grabFramebuffer());
    const render::Image expected = spt_render_frame(dir, scene, step, render::view_name(view),
                                                    QSize(shown.width, shown.height), overlays, &error);
    if (!error.empty()) return {};
    return render::compare_images(shown, expected);
}

std::string viewer_output_dir() {
    const std::string d = std::string(SPT_BINARY_DIR) + "/test-output/viewer";
    std::filesystem::create_directories(d);
    return d;
}

} // namespace spt::test
