// Selection driven by real mouse events on each view equals core's reference computation,
// in replace, add, subtract and visible-only modes, at the scale factor the run sets
// (ctest runs it at QT_SCALE_FACTOR 1, 1.5 and 2).
#include "editor_support.hpp"
#include "spt/selection.hpp"
#include <QTest>
#include <gtest/gtest.h>
#include <random>

using namespace spt;
using namespace spt::test;

namespace {

struct Stroke {
    QPoint from, to;
    SelectionMode mode;
    bool visible_only;
};

// What the selection must be after `s`, computed from core alone.
std::vector<uint32_t> expected_after(const editor::MainWindow& w, const editor::ViewWidget& v, const Stroke& s,
                                     const std::vector<uint32_t>& before) {
    const double dpr = v.devicePixelRatioF();
    const ViewProjection p = reference_projection(v);
    const PixelRect rect{float(s.from.x() * dpr), float(p.height) - float(s.from.y() * dpr), float(s.to.x() * dpr),
                         float(p.height) - float(s.to.y() * dpr)};
    const editor::EditorDocument& d = const_cast<editor::MainWindow&>(w).document();
    std::vector<uint32_t> hits;
    if (s.visible_only) {
        const float tolerance = float(0.005 * d.mesh()->diagonal());
        hits = visible_samples_in_rect(d.samples(), d.tree(), d.current(), p, rect, render_depth(*d.mesh(), p), tolerance);
    } else {
        hits = samples_in_rect(d.samples(), d.tree(), d.current(), p, rect);
    }
    return combine_selection(before, hits, s.mode);
}

Qt::KeyboardModifiers modifiers_for(SelectionMode m) {
    return m == SelectionMode::Add ? Qt::ShiftModifier : m == SelectionMode::Subtract ? Qt::ControlModifier : Qt::NoModifier;
}

} // namespace

TEST(SelectionUi, MouseRectanglesOnEveryViewEqualTheCoreReference) {
    TempDir dir("editor-select");
    std::string error;
    const auto window = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(window) << error;
    editor::MainWindow& w = *window;
    ASSERT_NE(w.document().mesh(), nullptr) << "the mesh beside the .spt file was not found";
    std::mt19937 rng(20261201);
    size_t nonempty = 0, checked = 0;
    for (NodeId node : {NodeId(1), NodeId(0)}) {
        if (node == 0) {
            // A second pass inside a child: split the root by a left half, then select in the right child.
            editor::ViewWidget* front = w.grid().view(1);
            QTest::mousePress(front, Qt::LeftButton, Qt::NoModifier, QPoint(1, 1));
            QTest::mouseRelease(front, Qt::LeftButton, Qt::NoModifier, QPoint(front->width() / 2, front->height() - 1));
            ASSERT_TRUE(w.split()) << w.last_message().toStdString();
            ASSERT_EQ(w.document().current(), NodeId(3));
        }
        for (int vi = 0; vi < 4; ++vi) {
            editor::ViewWidget* v = w.grid().view(vi);
            // From 1: QTest reads the point (0, 0) as "the widget's centre".
            std::uniform_int_distribution<int> ux(1, v->width() - 1), uy(1, v->height() - 1);
            for (int k = 0; k < 100; ++k) {
                // Each block of 25 uses one mode; visible-only strokes replace.
                const int block = k / 25;
                Stroke s{QPoint(ux(rng), uy(rng)), QPoint(ux(rng), uy(rng)),
                         block == 1 ? SelectionMode::Add : block == 2 ? SelectionMode::Subtract : SelectionMode::Replace,
                         block == 3};
                w.view_options().visible_only = s.visible_only;
                const std::vector<uint32_t> before = w.document().selection();
                const std::vector<uint32_t> expected = expected_after(w, *v, s, before);
                const Qt::KeyboardModifiers mods = modifiers_for(s.mode);
                QTest::mousePress(v, Qt::LeftButton, mods, s.from);
                QTest::mouseMove(v, (s.from + s.to) / 2);
                QTest::mouseMove(v, s.to);
                QTest::mouseRelease(v, Qt::LeftButton, mods, s.to);
                ASSERT_EQ(w.document().selection(), expected)
                    << render::view_name(v->view()) << " stroke " << k << " node " << w.document().current();
                nonempty += !expected.empty() && expected != before;
                ++checked;
            }
        }
    }
    // The strokes must have selected something often, or the comparison proves little.
    EXPECT_GT(nonempty, checked / 3);
}

TEST(SelectionUi, EscapeCancelsADrag) {
    TempDir dir("editor-escape");
    std::string error;
    const auto window = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(window) << error;
    editor::MainWindow& w = *window;
    editor::ViewWidget* v = w.grid().view(0);
    QTest::mousePress(v, Qt::LeftButton, Qt::NoModifier, QPoint(1, 1));
    QTest::mouseMove(v, QPoint(v->width() - 2, v->height() - 2));
    QTest::keyClick(v, Qt::Key_Escape);
    QTest::mouseRelease(v, Qt::LeftButton, Qt::NoModifier, QPoint(v->width() - 2, v->height() - 2));
    EXPECT_TRUE(w.document().selection().empty());
    // The same stroke without Escape selects the whole node.
    // (QTest reads the point (0, 0) as "the widget's centre".)
    QTest::mousePress(v, Qt::LeftButton, Qt::NoModifier, QPoint(1, 1));
    QTest::mouseRelease(v, Qt::LeftButton, Qt::NoModifier, QPoint(v->width() - 1, v->height() - 1));
    EXPECT_EQ(w.document().selection().size(), w.document().samples().size()) << w.last_message().toStdString();
}

TEST(SelectionUi, SelectionChangeShowsInEveryViewAsAFullRedrawWould) {
    TempDir dir("editor-select-redraw");
    std::string error;
    const auto window = open_editor(dir, write_editor_files(dir).spt, &error);
    ASSERT_TRUE(window) << error;
    editor::MainWindow& w = *window;
    editor::ViewWidget* front = w.grid().view(1);
    QTest::mousePress(front, Qt::LeftButton, Qt::NoModifier, QPoint(1, 1));
    QTest::mouseRelease(front, Qt::LeftButton, Qt::NoModifier, QPoint(front->width() / 2, front->height() / 2));
    ASSERT_FALSE(w.document().selection().empty());
    std::vector<QImage> recoloured;
    for (int i = 0; i < 4; ++i) {
        recoloured.push_back(w.grid().view(i)->grabFramebuffer());
        EXPECT_EQ(w.grid().view(i)->last_draw_kind(), render::DrawKind::Recoloured) << "view " << i;
    }
    // Another size and back: every view draws everything again, through the same camera.
    const QSize size = w.size();
    w.resize(size + QSize(40, 30));
    QTest::qWait(50);
    for (int i = 0; i < 4; ++i) w.grid().view(i)->grabFramebuffer();
    w.resize(size);
    QTest::qWait(50);
    for (int i = 0; i < 4; ++i) {
        // The paint after the resize drew everything; the grab composites those layers again.
        EXPECT_EQ(w.grid().view(i)->last_draw_kind(), render::DrawKind::Full) << "view " << i;
        const QImage full = w.grid().view(i)->grabFramebuffer();
        EXPECT_TRUE(full == recoloured[size_t(i)]) << "view " << i << " differs from its full redraw";
    }
}
