// Editor test helpers and the one QApplication of the binary.
#include "editor_support.hpp"
#include "spt/convert.hpp"
#include "qt_image.hpp"
#include "spt/render/image.hpp"
#include <QProcess>
#include <QApplication>
#include <QStandardPaths>
#include <QTest>
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>

namespace spt::test {
namespace {

class EditorEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        // Settings and data go to the build tree, never the user's (set before any QSettings).
        const std::string home = std::string(SPT_BINARY_DIR) + "/test-tmp/editor-home-" + std::to_string(::getpid());
        std::filesystem::create_directories(home);
        // Test mode keeps settings in $HOME/.qttest whatever XDG_CONFIG_HOME says, so without a
        // home of its own each editor ctest running at once rewrote the others' recent files.
        ::setenv("HOME", home.c_str(), 1);
        ::setenv("XDG_CONFIG_HOME", (home + "/config").c_str(), 1);
        ::setenv("XDG_DATA_HOME", (home + "/data").c_str(), 1);
        ::setenv("QT_QPA_PLATFORM", "xcb", 1);
        QStandardPaths::setTestModeEnabled(true);
        spt::editor::use_render_gl_format();
        app_ = std::make_unique<QApplication>(argc_, argv_);
        QApplication::setApplicationName("spt-editor-test");
    }
    void TearDown() override { app_.reset(); }

private:
    int argc_ = 1;
    char name_[16] = "editor_tests";
    char* argv_[2] = {name_, nullptr};
    std::unique_ptr<QApplication> app_;
};

[[maybe_unused]] ::testing::Environment* const g_env = ::testing::AddGlobalTestEnvironment(new EditorEnvironment);

} // namespace

EditorFiles write_editor_files(const TempDir& dir) {
    EditorFiles f;
    f.mesh = QString::fromStdString(dir.file("torus.obj"));
    f.spt = QString::fromStdString(dir.file("torus.spt"));
    std::filesystem::copy_file(project_meshes() + "/torus.obj", f.mesh.toStdString());
    ConvertOptions o;
    o.auto_tolerance = false;
    SptDocument doc = make_document(import_mesh(f.mesh.toStdString()).mesh, o);
    // First the tree an author starts from (the root holds every sample), then the automatic one.
    SamplingTree authored("authored", uint32_t(doc.samples.size()));
    authored.assign_radii(doc.samples, RadiusRule{});
    authored.compute_bounds(doc.samples, BoundsMethod::Tight);
    doc.trees.insert(doc.trees.begin(), std::move(authored));
    save_spt(doc, f.spt.toStdString());
    return f;
}

ViewProjection reference_projection(const editor::ViewWidget& v) {
    const double dpr = v.devicePixelRatioF();
    const int w = qRound(v.width() * dpr), h = qRound(v.height() * dpr);
    const render::Camera& c = v.camera();
    ViewProjection p;
    p.view = c.view_matrix();
    p.projection = c.projection_matrix(float(w) / float(h));
    p.perspective = c.perspective();
    p.width = w;
    p.height = h;
    return p;
}

editor::StartOptions test_start(const TempDir& dir) {
    editor::StartOptions o;
    o.autosave_seconds = 0;
    o.recovery_dir = QString::fromStdString(dir.file("recovery"));
    return o;
}

bool wait_ready(editor::MainWindow& window) {
    if (!QTest::qWaitFor([&] { return !window.loading() && window.document().has_tree(); }, 120000)) return false;
    if (!window.isVisible()) window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return false;
    // Shortcuts (Ctrl+S, S) reach only the active window.
    window.activateWindow();
    if (!QTest::qWaitForWindowActive(&window)) return false;
    return wait_drawn(window);
}

bool wait_drawn(editor::MainWindow& window) {
    return QTest::qWaitFor(
        [&] {
            for (int i = 0; i < 4; ++i)
                if (!window.grid().view(i)->has_drawn()) return false;
            return true;
        },
        60000);
}

std::unique_ptr<editor::MainWindow> open_editor(const TempDir& dir, const QString& file, std::string* error) {
    editor::StartOptions start = test_start(dir);
    start.file = file;
    auto w = std::make_unique<editor::MainWindow>(start);
    w->show();
    if (!wait_ready(*w)) {
        *error = "the editor did not open " + file.toStdString() + ": " + w->last_error().toStdString();
        return nullptr;
    }
    return w;
}

void expect_view_matches_spt_render(editor::ViewWidget& v, const QStringList& input_args, const TempDir& dir,
                                    const std::string& name) {
    const render::Image view = to_image(v.grabFramebuffer());
    const std::string view_name = render::view_name(v.view());
    const QString png = QString::fromStdString(dir.file(name + "_" + view_name + ".png"));
    QProcess spt;
    spt.start(QString(SPT_BINARY_DIR) + "/cli/spt",
              QStringList{"render"} + input_args +
                  QStringList{"--view", QString::fromStdString(view_name), "--size",
                              QString("%1x%2").arg(view.width).arg(view.height), "-o", png});
    ASSERT_TRUE(spt.waitForFinished(120000));
    ASSERT_EQ(spt.exitCode(), 0) << spt.readAllStandardError().toStdString();
    // A window shows colour only: the off-screen image keeps the alpha blending left in its
    // framebuffer, the widget's grab is opaque. Compare what is seen.
    render::Image expected = render::read_png(png.toStdString());
    for (size_t k = 3; k < expected.rgba.size(); k += 4) expected.rgba[k] = 255;
    const render::CompareResult r = render::compare_images(view, expected);
    EXPECT_TRUE(r.passed) << view_name << ": " << r.summary();
    if (!r.passed) render::write_png(r.diff, editor_output_dir() + "/" + name + "_" + view_name + ".diff.png");
}

std::string editor_output_dir() {
    const std::string dir = std::string(SPT_BINARY_DIR) + "/test-output/editor";
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace spt::test
