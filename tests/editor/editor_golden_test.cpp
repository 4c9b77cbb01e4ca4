// The four views after a scripted split against golden images (the render goldens' rules),
// and each view against `spt render` of the same view, size and overlays. The grabs are
// also written to BUILD/test-output/editor for docs/editor.md.
#include "editor_support.hpp"
#include "golden.hpp"
#include "qt_image.hpp"
#include "spt/render/image.hpp"
#include <QImage>
#include <QProcess>
#include <QScreen>
#include <QTest>
#include <gtest/gtest.h>

using namespace spt;
using namespace spt::test;

namespace {

// Opens the test document, splits the root by the left half of the front view, frames all.
std::unique_ptr<editor::MainWindow> split_scene(const TempDir& dir, std::string* error) {
    auto w = open_editor(dir, write_editor_files(dir).spt, error);
    if (!w) return nullptr;
    editor::ViewWidget* front = w->grid().view(1);
    QTest::mousePress(front, Qt::LeftButton, Qt::NoModifier, QPoint(1, 1));
    QTest::mouseMove(front, QPoint(front->width() / 2, front->height() - 1));
    QTest::mouseRelease(front, Qt::LeftButton, Qt::NoModifier, QPoint(front->width() / 2, front->height() - 1));
    QTest::keyClick(w.get(), Qt::Key_S);
    if (w->document().tree().node_count() != 3) {
        *error = "the split was not made: " + w->last_message().toStdString();
        return nullptr;
    }
    QTest::keyClick(w.get(), Qt::Key_Home);
    if (!wait_ready(*w)) {
        *error = "the views did not redraw after Home";
        return nullptr;
    }
    return w;
}

} // namespace

TEST(EditorGolden, FourViewsAfterAScriptedSplit) {
    TempDir dir("editor-golden");
    std::string error;
    const auto w = split_scene(dir, &error);
    ASSERT_TRUE(w) << error;
    EXPECT_EQ(w->document().current(), NodeId(3));
    const std::string out = editor_output_dir();
    for (int i = 0; i < 4; ++i) {
        editor::ViewWidget* v = w->grid().view(i);
        const render::Image image = to_image(v->grabFramebuffer());
        const std::string name = std::string("editor_") + render::view_name(v->view());
        render::write_png(image, out + "/" + name + ".png");
        EXPECT_GOLDEN(image, name);
    }
    // The whole window as the X server shows it, for the docs and the README.
    QTest::qWait(200);
    w->screen()->grabWindow(w->winId()).save(QString::fromStdString(out + "/editor_window.png"));
}

TEST(EditorGolden, EachViewMatchesSptRenderOfTheSameViewAndSize) {
    TempDir dir("editor-vs-render");
    std::string error;
    const auto w = split_scene(dir, &error);
    ASSERT_TRUE(w) << error;
    const QString saved = QString::fromStdString(dir.file("split.spt"));
    ASSERT_TRUE(w->save_to(saved));
    for (int i = 0; i < 4; ++i)
        expect_view_matches_spt_render(*w->grid().view(i),
                                       {QString::fromStdString(dir.file("torus.obj")), "--tree", saved, "--tree-name",
                                        "authored", "--overlay", "spheres,node,grid,axes", "--node", "3"},
                                       dir, "vs_render");
}
