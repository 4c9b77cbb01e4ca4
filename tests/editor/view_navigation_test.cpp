// View navigation: zoom keeps the point under the cursor, pan follows the mouse, orbit
// changes only the perspective camera, Ctrl+Space maximises the view under the cursor.
#include "editor_support.hpp"
#include "view_navigation.hpp"
#include <QCursor>
#include <QTest>
#include <gtest/gtest.h>

using namespace spt;
using namespace spt::test;

namespace {

// Where world point p shows in a w x h view, logical pixels from the top left.
Eigen::Vector2f on_screen(const render::Camera& c, const Eigen::Vector3f& p, int w, int h) {
    const Eigen::Vector3f win = c.project(p, w, h);
    return {win.x(), float(h) - win.y()};
}

} // namespace

TEST(ViewNavigation, ZoomKeepsThePointUnderTheCursorInOrthographicViews) {
    for (render::View view : {render::View::Top, render::View::Front, render::View::Side}) {
        render::Camera c;
        c.view = view;
        c.target = {1, 2, 3};
        c.radius = 5;
        const int w = 400, h = 300;
        const Eigen::Vector3f p(2.5f, 1.0f, 4.0f);
        const Eigen::Vector2f before = on_screen(c, p, w, h);
        editor::zoom_about(c, 1.7f, before.x(), before.y(), w, h);
        EXPECT_GT(c.zoom, 1.69f);
        const Eigen::Vector2f after = on_screen(c, p, w, h);
        EXPECT_NEAR(after.x(), before.x(), 1e-2f) << render::view_name(view);
        EXPECT_NEAR(after.y(), before.y(), 1e-2f) << render::view_name(view);
    }
}

TEST(ViewNavigation, PanMovesTheSceneWithTheMouse) {
    for (render::View view : {render::View::Top, render::View::Front, render::View::Side, render::View::Camera}) {
        render::Camera c;
        c.view = view;
        c.radius = 2;
        const int w = 300, h = 300;
        const Eigen::Vector2f before = on_screen(c, c.target, w, h);
        editor::pan(c, 30, -20, w, h);
        // The old target moved 30 pixels right and 20 up (screen y grows downwards).
        const Eigen::Vector2f after = on_screen(c, Eigen::Vector3f::Zero(), w, h);
        EXPECT_NEAR(after.x() - before.x(), 30.0f, 0.05f) << render::view_name(view);
        EXPECT_NEAR(after.y() - before.y(), -20.0f, 0.05f) << render::view_name(view);
    }
}

TEST(ViewNavigation, OrbitTurnsOnlyThePerspectiveCamera) {
    render::Camera top;
    top.view = render::View::Top;
    editor::orbit(top, 50, 50);
    EXPECT_EQ(top.yaw, render::Camera{}.yaw);
    render::Camera cam;
    editor::orbit(cam, 50, 500);
    EXPECT_NE(cam.yaw, render::Camera{}.yaw);
    EXPECT_LE(cam.pitch, 89.0f);
}

TEST(ViewNavigation, CtrlSpaceMaximisesTheViewUnderTheCursorAndRestores) {
    TempDir dir("editor-maximise");
    std::string error;
    const auto window = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(window) << error;
    editor::MainWindow& w = *window;
    editor::ViewWidget* side = w.grid().view(2);
    QCursor::setPos(side->mapToGlobal(side->rect().center()));
    QTest::keyClick(&w, Qt::Key_Space, Qt::ControlModifier);
    ASSERT_TRUE(w.grid().maximised());
    EXPECT_TRUE(side->isVisible());
    for (int i : {0, 1, 3}) EXPECT_FALSE(w.grid().view(i)->isVisible()) << i;
    QTest::keyClick(&w, Qt::Key_Space, Qt::ControlModifier);
    EXPECT_FALSE(w.grid().maximised());
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(w.grid().view(i)->isVisible()) << i;
}
