// Lasso, brush, select linked, invert, grow, shrink and hide / isolate / show driven by real
// mouse and key events on the views equal core's computation, at the scale factor the run sets
// (ctest runs it at QT_SCALE_FACTOR 1, 1.5 and 2); the stroke's outline shows over the view
// while it is drawn and leaves the framebuffer alone; a split made with them replays from its file.
#include "editor_support.hpp"
#include "mesh/shapes.hpp"
#include "spt/compact_tree.hpp"
#include "spt/convert.hpp"
#include "spt/recipe.hpp"
#include "spt/render/tree_overlay.hpp"
#include "spt/selection.hpp"
#include <QScreen>
#include <QTest>
#include <gtest/gtest.h>
#include <cmath>
#include <fstream>

using namespace spt;
using namespace spt::test;

namespace {

// Two tori side by side along x in one OBJ and its .spt (vertex samples, one root-only tree):
// two mesh parts for select linked.
QString write_two_tori(const TempDir& dir) {
    const std::string obj = dir.file("two_tori.obj"), spt_path = dir.file("two_tori.spt");
    const TriangleMesh t = make_torus(1.0, 0.3, 32, 12);
    std::ofstream out(obj);
    for (double cx : {-1.5, 1.5})
        for (const Eigen::Vector3d& p : t.positions) out << "v " << p.x() + cx << ' ' << p.y() << ' ' << p.z() << '\n';
    for (size_t part = 0; part < 2; ++part)
        for (const Triangle& f : t.triangles)
            out << "f " << f[0] + 1 + part * t.positions.size() << ' ' << f[1] + 1 + part * t.positions.size() << ' '
                << f[2] + 1 + part * t.positions.size() << '\n';
    out.close();
    ConvertOptions o;
    o.auto_tolerance = false;
    SptDocument doc = make_document(import_mesh(obj).mesh, o);
    doc.trees = {unsplit_tree("authored", doc.samples)};
    save_spt(doc, spt_path);
    return QString::fromStdString(spt_path);
}

std::vector<Eigen::Vector2f> to_window(const editor::ViewWidget& v, const std::vector<QPoint>& path) {
    const double dpr = v.devicePixelRatioF();
    const float h = float(qRound(v.height() * dpr));
    std::vector<Eigen::Vector2f> out;
    for (const QPoint& p : path) out.emplace_back(float(p.x() * dpr), h - float(p.y() * dpr));
    return out;
}

// A star of `n` points about the view's centre (logical pixels), its radii alternating.
std::vector<QPoint> star(const editor::ViewWidget& v, int n, double phase) {
    std::vector<QPoint> out;
    const QPointF c(v.width() * 0.5, v.height() * 0.5);
    const double r = 0.4 * std::min(v.width(), v.height());
    for (int k = 0; k < n; ++k) {
        const double a = phase + 2 * M_PI * k / n, rr = k % 2 ? r : 0.45 * r;
        out.push_back((c + QPointF(rr * std::cos(a), rr * std::sin(a))).toPoint());
    }
    return out;
}

void drag(editor::ViewWidget* v, const std::vector<QPoint>& path, Qt::KeyboardModifiers mods = Qt::NoModifier) {
    QTest::mousePress(v, Qt::LeftButton, mods, path.front());
    for (size_t k = 1; k < path.size(); ++k) QTest::mouseMove(v, path[k]);
    QTest::mouseRelease(v, Qt::LeftButton, mods, path.back());
}

Qt::KeyboardModifiers tools_modifiers(SelectionMode m) {
    return m == SelectionMode::Add ? Qt::ShiftModifier : m == SelectionMode::Subtract ? Qt::ControlModifier : Qt::NoModifier;
}

// Pixels of the stroke outline's exact colour in `image`.
int outline_pixels(const QImage& image) {
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    const QRgb want = editor::stroke_outline_color().rgb();
    int n = 0;
    for (int y = 0; y < rgb.height(); ++y)
        for (int x = 0; x < rgb.width(); ++x) n += rgb.pixel(x, y) == want;
    return n;
}

// The view as the screen shows it: the framebuffer with the widgets composed over it (QWidget::grab
// of a QOpenGLWidget composes the framebuffer's alpha wrongly under xcb).
QImage on_screen(editor::ViewWidget* v) {
    QTest::qWait(30); // the composition of the last paint reaches the X server
    const QPoint at = v->mapTo(v->window(), QPoint(0, 0));
    return v->window()->screen()->grabWindow(v->window()->winId(), at.x(), at.y(), v->width(), v->height()).toImage();
}

std::unique_ptr<editor::MainWindow> tools_editor(const TempDir& dir, const QString& file) {
    std::string error;
    auto w = open_editor(dir, file, &error);
    EXPECT_TRUE(w) << error;
    if (w) {
        EXPECT_NE(w->document().mesh(), nullptr) << "the mesh beside the .spt file was not found";
    }
    return w;
}

} // namespace

TEST(SelectionToolsUi, MouseLassoAndBrushOnEveryViewEqualTheCoreReference) {
    TempDir dir("editor-tools");
    const auto window = tools_editor(dir, write_editor_files(dir).spt);
    ASSERT_TRUE(window && window->document().mesh());
    editor::MainWindow& w = *window;
    size_t changed = 0, checked = 0;
    for (int vi = 0; vi < 4; ++vi) {
        editor::ViewWidget* v = w.grid().view(vi);
        for (int k = 0; k < 8; ++k) {
            const bool brush = k % 2 == 1;
            const SelectionMode mode = k < 2 ? SelectionMode::Replace : k < 4 ? SelectionMode::Add
                                              : k < 6 ? SelectionMode::Subtract : SelectionMode::Replace;
            const bool visible = k >= 6;
            QTest::keyClick(v, brush ? Qt::Key_C : Qt::Key_L); // the tool from its key
            ASSERT_EQ(w.view_options().tool, brush ? editor::SelectTool::Brush : editor::SelectTool::Lasso);
            w.view_options().visible_only = visible;
            const std::vector<QPoint> path = star(*v, brush ? 5 : 10, 0.3 * (k + vi));
            const editor::EditorDocument& d = w.document();
            RecipeStroke stroke{reference_projection(*v), {}, mode, visible};
            stroke.kind = brush ? StrokeKind::Brush : StrokeKind::Lasso;
            stroke.points = to_window(*v, path);
            stroke.radius = float(w.view_options().brush_radius * v->devicePixelRatioF());
            const std::vector<uint32_t> before = d.selection();
            const std::vector<uint32_t> expected =
                apply_stroke(d.samples(), d.tree(), d.current(), before, stroke, d.mesh());
            drag(v, path, tools_modifiers(mode));
            ASSERT_EQ(d.selection(), expected) << render::view_name(v->view()) << " stroke " << k;
            changed += expected != before;
            ++checked;
        }
    }
    EXPECT_GT(changed, checked / 2);
}

TEST(SelectionToolsUi, TheOutlineShowsWhileDraggingAndTheFramebufferStays) {
    TempDir dir("editor-tools-outline");
    const auto window = tools_editor(dir, write_editor_files(dir).spt);
    ASSERT_TRUE(window);
    editor::MainWindow& w = *window;
    editor::ViewWidget* v = w.grid().view(1);
    const QImage still = v->grabFramebuffer();
    ASSERT_EQ(outline_pixels(on_screen(v)), 0);
    for (Qt::Key key : {Qt::Key_R, Qt::Key_L, Qt::Key_C}) {
        QTest::keyClick(v, key);
        const std::vector<QPoint> path = star(*v, 8, 0.1);
        QTest::mousePress(v, Qt::LeftButton, Qt::NoModifier, path.front());
        for (size_t k = 1; k < path.size(); ++k) QTest::mouseMove(v, path[k]);
        const QImage dragging = on_screen(v);
        EXPECT_GT(outline_pixels(dragging), 40) << "tool key " << key << ": no outline while dragging";
        if (key == Qt::Key_L && v->devicePixelRatioF() == 1.0) // docs/editor.md shows it
            dragging.save(QString::fromStdString(editor_output_dir() + "/lasso.png"));
        EXPECT_TRUE(v->grabFramebuffer() == still) << "tool key " << key << ": the drag changed the framebuffer";
        QTest::keyClick(v, Qt::Key_Escape); // cancelled: nothing selected, the outline gone
        QTest::mouseRelease(v, Qt::LeftButton, Qt::NoModifier, path.back());
        EXPECT_TRUE(w.document().selection().empty());
        EXPECT_EQ(outline_pixels(on_screen(v)), 0) << "tool key " << key << ": the outline stayed";
    }
}

TEST(SelectionToolsUi, SelectLinkedUnderTheCursorTakesTheMeshPartThere) {
    TempDir dir("editor-tools-linked");
    const auto window = tools_editor(dir, write_two_tori(dir));
    ASSERT_TRUE(window && window->document().mesh());
    editor::MainWindow& w = *window;
    const editor::EditorDocument& d = w.document();
    const SampleAdjacency adj(*d.mesh(), d.samples());
    for (int vi : {0, 1, 3}) { // top, front and camera see both tori apart
        editor::ViewWidget* v = w.grid().view(vi);
        // The left torus's tube, a quarter of the width in: the pick of core at that point.
        for (int side = 0; side < 2; ++side) {
            w.document().set_selection({});
            int64_t seed = -1;
            QPoint at;
            for (int x = 1; x < v->width() && seed < 0; x += 3) { // the first column of the side's half with a sample
                at = QPoint(side ? v->width() - x : x, v->height() / 2);
                seed = pick_sample(d.samples(), d.tree(), d.current(), reference_projection(*v), to_window(*v, {at})[0], 12);
            }
            ASSERT_GE(seed, 0) << "view " << vi;
            QTest::mouseMove(v, at);
            QTest::keyClick(v, Qt::Key_L, Qt::ControlModifier);
            const std::vector<uint32_t> part = linked_samples(adj, d.tree(), d.current(), uint32_t(seed));
            ASSERT_EQ(d.selection(), part) << "view " << vi << " side " << side << ": " << w.last_message().toStdString();
            EXPECT_NEAR(double(part.size()), 0.5 * double(d.samples().size()), 1.0) << "one torus of two";
            // Ctrl+Shift+L at the same point takes it away again.
            QTest::keyClick(v, Qt::Key_L, Qt::ControlModifier | Qt::ShiftModifier);
            EXPECT_TRUE(d.selection().empty());
        }
    }
}

TEST(SelectionToolsUi, InvertGrowAndShrinkFromTheKeyboardEqualCore) {
    TempDir dir("editor-tools-grow");
    const auto window = tools_editor(dir, write_editor_files(dir).spt);
    ASSERT_TRUE(window && window->document().mesh());
    editor::MainWindow& w = *window;
    const editor::EditorDocument& d = w.document();
    const SampleAdjacency adj(*d.mesh(), d.samples());
    editor::ViewWidget* v = w.grid().view(1);
    QTest::keyClick(v, Qt::Key_C);
    const double radius = w.view_options().brush_radius;
    QTest::keyClick(v, Qt::Key_BracketRight); // ] and [ scale the brush by 1.25
    EXPECT_DOUBLE_EQ(w.view_options().brush_radius, radius * 1.25);
    QTest::keyClick(v, Qt::Key_BracketLeft);
    EXPECT_DOUBLE_EQ(w.view_options().brush_radius, radius);
    w.set_brush_radius(8);
    QPoint at;
    for (int x = 1; x < v->width(); x += 3) { // the first point left of the centre with a sample near
        at = QPoint(x, v->height() / 2);
        if (pick_sample(d.samples(), d.tree(), d.current(), reference_projection(*v), to_window(*v, {at})[0], 4) >= 0) break;
    }
    drag(v, {at + QPoint(4, 0), at + QPoint(8, 0)});
    std::vector<uint32_t> expected = d.selection();
    ASSERT_FALSE(expected.empty());
    for (int k = 0; k < 2; ++k) {
        QTest::keyClick(v, Qt::Key_Plus, Qt::ControlModifier | Qt::KeypadModifier);
        expected = grow_selection(adj, d.tree(), d.current(), expected);
        ASSERT_EQ(d.selection(), expected) << "grow " << k << ": " << w.last_message().toStdString();
    }
    QTest::keyClick(v, Qt::Key_Minus, Qt::ControlModifier | Qt::KeypadModifier);
    expected = shrink_selection(adj, d.tree(), d.current(), expected);
    ASSERT_EQ(d.selection(), expected);
    QTest::keyClick(v, Qt::Key_I, Qt::ControlModifier);
    expected = invert_selection(d.tree(), d.current(), expected);
    ASSERT_EQ(d.selection(), expected);
    // The strokes are the next split's recipe step: S, save, and the file replays to the same tree.
    QTest::keyClick(v, Qt::Key_S);
    ASSERT_EQ(w.undo_stack().count(), 1) << w.last_message().toStdString();
    const std::string saved = dir.file("tools.spt");
    ASSERT_TRUE(w.save_to(QString::fromStdString(saved)));
    const SptDocument file = load_spt(saved);
    const SamplingTree& t = *file.tree("authored");
    ASSERT_EQ(t.recipe().size(), 1u);
    std::vector<StrokeKind> kinds;
    for (const RecipeStroke& s : t.recipe().front().strokes) kinds.push_back(s.kind);
    EXPECT_EQ(kinds, (std::vector<StrokeKind>{StrokeKind::Brush, StrokeKind::Grow, StrokeKind::Grow, StrokeKind::Shrink,
                                              StrokeKind::Invert}));
    EXPECT_EQ(spt_version_for(file), 5u);
    const SamplingTree replayed = replay_recipe(t, file.samples, *d.mesh());
    SptDocument again = file;
    *std::find_if(again.trees.begin(), again.trees.end(), [](const SamplingTree& x) { return x.name() == "authored"; }) =
        replayed;
    EXPECT_EQ(encode_spt(again), encode_spt(file));
    // A selection made in code and inverted replays on nothing: the split records no step for it.
    const std::vector<uint32_t> node = samples_below(d.tree(), d.current());
    ASSERT_GT(node.size(), 2u);
    w.document().set_selection({node.front()});
    QTest::keyClick(v, Qt::Key_I, Qt::ControlModifier);
    ASSERT_EQ(d.selection().size(), node.size() - 1);
    QTest::keyClick(v, Qt::Key_S);
    ASSERT_EQ(w.undo_stack().count(), 2) << w.last_message().toStdString();
    EXPECT_EQ(d.tree().recipe().size(), 1u);
}

TEST(SelectionToolsUi, HideIsolateAndShowAllChangeWhatIsDrawnNotTheDocument) {
    TempDir dir("editor-tools-hide");
    const auto window = tools_editor(dir, write_editor_files(dir).spt);
    ASSERT_TRUE(window);
    editor::MainWindow& w = *window;
    editor::ViewWidget* v = w.grid().view(1);
    QTest::mousePress(v, Qt::LeftButton, Qt::NoModifier, QPoint(1, 1));
    QTest::mouseRelease(v, Qt::LeftButton, Qt::NoModifier, QPoint(v->width() / 2, v->height() - 1));
    QTest::keyClick(v, Qt::Key_S);
    ASSERT_EQ(w.document().current(), NodeId(3)) << w.last_message().toStdString();
    const int edits = w.undo_stack().count();
    const std::vector<uint8_t> bytes = w.document().encode();
    const CompactTree compact(w.document().tree(), w.document().samples());
    const render::SphereRange left = render::sphere_range(compact, w.document().tree(), 2);
    const render::SphereRange right = render::sphere_range(compact, w.document().tree(), 3);
    ASSERT_GT(left.count, 0u);
    ASSERT_GT(right.count, 0u);
    auto grab_all = [&] {
        std::vector<QImage> out;
        for (int i = 0; i < 4; ++i) out.push_back(w.grid().view(i)->grabFramebuffer());
        return out;
    };
    const std::vector<QImage> all = grab_all();
    auto shown = [&] {
        std::vector<std::pair<uint32_t, uint32_t>> out;
        for (const render::SphereRange& r : w.scene().data().shown) out.emplace_back(r.first, r.count);
        return out;
    };
    QTest::keyClick(v, Qt::Key_H); // hide node 3
    EXPECT_TRUE(w.scene().data().hiding);
    EXPECT_EQ(shown(), (std::vector<std::pair<uint32_t, uint32_t>>{{left.first, left.count}}));
    const std::vector<QImage> hidden = grab_all();
    for (int i = 0; i < 4; ++i) EXPECT_FALSE(hidden[size_t(i)] == all[size_t(i)]) << "view " << i << " still shows node 3";
    QTest::keyClick(v, Qt::Key_H, Qt::ShiftModifier); // isolate node 3: node 2 hidden instead
    EXPECT_EQ(shown(), (std::vector<std::pair<uint32_t, uint32_t>>{{right.first, right.count}}));
    QTest::keyClick(v, Qt::Key_H, Qt::AltModifier); // show all
    EXPECT_FALSE(w.scene().data().hiding);
    const std::vector<QImage> back = grab_all();
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(back[size_t(i)] == all[size_t(i)]) << "view " << i << " after Alt+H";
    // A view state: no edit, the document's bytes unchanged.
    EXPECT_EQ(w.undo_stack().count(), edits);
    EXPECT_EQ(w.document().encode(), bytes);
}
