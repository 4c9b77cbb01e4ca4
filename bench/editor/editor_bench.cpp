// spt-editor-bench: selection from mouse release to highlighted result on a 1,000,000-vertex
// mesh (through and visible only), and redrawing all four views of a 100k-triangle mesh with
// 50k sampling spheres in a 1280x800 window. Needs an X server: run under xvfb-run.
#include "spt/recipe.hpp"
#include "main_window.hpp"
#include "view_widget.hpp"
#include "mesh/shapes.hpp"
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QTest>
#include <QStatusBar>
#include <QWheelEvent>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>

using namespace spt;

namespace {

// A document over a mesh's vertices (vertex samples, unit spacing scaled to the mesh), root only.
SptDocument vertex_document(const TriangleMesh& mesh) {
    SptDocument doc;
    doc.mesh = {mesh.name, uint32_t(mesh.positions.size()), uint32_t(mesh.triangles.size()), mesh.content_hash(),
                mesh.diagonal()};
    const float spacing = float(mesh.diagonal() / std::sqrt(double(mesh.positions.size())));
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        doc.samples.add(mesh.positions[i].cast<float>(), mesh.normals[i].cast<float>(), uint32_t(i), spacing);
    doc.trees.push_back(unsplit_tree("default", doc.samples));
    return doc;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Waits for the GPU (llvmpipe) to finish every view's frame.
void finish_views(editor::MainWindow& w) {
    for (int i = 0; i < 4; ++i) {
        editor::ViewWidget* v = w.grid().view(i);
        v->makeCurrent();
        v->context()->functions()->glFinish();
        v->doneCurrent();
    }
}

// What the event loop does after views called update(): one paint of each dirty view and one flush
// of the window (QWidget::repaint of each view would paint every dirty view in the first call
// and flush the window four times), then waits for the GPU.
// Counts the runs in which a view that should have painted did not (Qt skipped the paint); the
// tables print it so that a figure timed over nothing cannot pass unnoticed.
int g_missed_paints = 0;

// `expected`: bit i set when view i must paint.
void sync_window(editor::MainWindow& w, unsigned expected = 0xF) {
    uint64_t before[4];
    for (int i = 0; i < 4; ++i) before[i] = w.grid().view(i)->frames_painted();
    QApplication::sendPostedEvents(&w, QEvent::UpdateRequest);
    finish_views(w);
    for (int i = 0; i < 4; ++i)
        if ((expected >> i & 1) && w.grid().view(i)->frames_painted() == before[i]) {
            ++g_missed_paints;
            break;
        }
}

// Asks every view to paint (nothing changed) and paints them.
void repaint_views(editor::MainWindow& w) {
    for (int i = 0; i < 4; ++i) w.grid().view(i)->update();
    sync_window(w);
}

// How the four views made their last frames, e.g. "recoloured x4" or "full, composited x3".
std::string draw_kinds(editor::MainWindow& w) {
    static const char* names[] = {"full", "recoloured", "composited"};
    std::string out;
    for (int i = 0; i < 4; ++i) out += std::string(i ? " " : "") + names[int(w.grid().view(i)->last_draw_kind())];
    return out;
}

// One wheel step (in when `in`, else out) at the centre of `v`: a camera change.
void wheel(editor::ViewWidget* v, bool in) {
    const QPointF c(v->width() / 2.0, v->height() / 2.0);
    QWheelEvent e(c, v->mapToGlobal(c), QPoint(), QPoint(0, in ? 120 : -120), Qt::NoButton, Qt::NoModifier,
                  Qt::NoScrollPhase, false);
    QApplication::sendEvent(v, &e);
}

bool open(editor::MainWindow& w, const TriangleMesh& mesh) {
    w.document().reset(vertex_document(mesh), mesh);
    w.show();
    if (!QTest::qWaitForWindowExposed(&w)) return false;
    return QTest::qWaitFor([&] {
        for (int i = 0; i < 4; ++i)
            if (!w.grid().view(i)->has_drawn()) return false;
        return true;
    }, 120000);
}

// Median ms from a mouse release to the selection drawn in all four views.
double selection_ms(editor::MainWindow& w, bool visible_only, int runs, size_t* selected) {
    w.view_options().visible_only = visible_only;
    editor::ViewWidget* v = w.grid().view(1);
    std::mt19937 rng(7);
    std::vector<double> times;
    for (int k = 0; k < runs; ++k) {
        const int x0 = 1 + int(rng() % uint32_t(v->width() / 3)), y0 = 1 + int(rng() % uint32_t(v->height() / 3));
        const QPoint a(x0, y0), b(x0 + v->width() / 2, y0 + v->height() / 2);
        QTest::mousePress(v, Qt::LeftButton, Qt::NoModifier, a);
        QTest::mouseMove(v, b);
        QElapsedTimer t;
        t.start();
        QTest::mouseRelease(v, Qt::LeftButton, Qt::NoModifier, b);
        sync_window(w);
        times.push_back(double(t.nsecsElapsed()) * 1e-6);
        *selected = w.document().selection().size();
    }
    std::printf("<!-- selection, %s: last run's views drew %s -->\n", visible_only ? "visible only" : "through",
                draw_kinds(w).c_str());
    return median(times);
}

// Median ms of `f` over `runs` calls.
template <class F> double median_ms(int runs, F&& f) {
    std::vector<double> times;
    for (int k = 0; k < runs; ++k) {
        QElapsedTimer t;
        t.start();
        f();
        times.push_back(double(t.nsecsElapsed()) * 1e-6);
    }
    return median(times);
}

// Times the parts of one selection in the front view (the bench's first rectangle there):
// core alone, the document (core + scene + panel), the front view's repaint with nothing changed
// and after a camera change.
void selection_parts(editor::MainWindow& w, const TriangleMesh& mesh, int runs) {
    editor::ViewWidget* v = w.grid().view(1);
    editor::EditorDocument& doc = w.document();
    const ViewProjection view = v->view_projection();
    const float fw = float(view.width), fh = float(view.height);
    const PixelRect rect{fw / 6, fh / 6, fw / 6 + fw / 2, fh / 6 + fh / 2};
    for (bool visible : {false, true}) {
        const RecipeStroke stroke{view, rect, SelectionMode::Replace, visible};
        std::vector<uint32_t> hits;
        const double core = median_ms(runs, [&] {
            hits = apply_stroke(doc.samples(), doc.tree(), doc.current(), {}, stroke, &mesh);
        });
        std::printf("| part: core apply_stroke, %s | %.1f ms | %zu samples hit |\n", visible ? "visible only" : "through",
                    core, hits.size());
    }
    {
        const RecipeStroke stroke{view, rect, SelectionMode::Replace, false};
        const std::vector<uint32_t> hits = apply_stroke(doc.samples(), doc.tree(), doc.current(), {}, stroke, &mesh);
        std::vector<uint32_t> half;
        for (uint32_t i = 0; i < doc.samples().size(); i += 2) half.push_back(i);
        std::vector<uint32_t> out;
        const double add = median_ms(runs, [&] { out = combine_selection(half, hits, SelectionMode::Add); });
        const double sub = median_ms(runs, [&] { out = combine_selection(half, hits, SelectionMode::Subtract); });
        std::printf("| part: core combine_selection, add / subtract | %.1f / %.1f ms | every other sample with the hits |\n",
                    add, sub);
    }
    const double select = median_ms(runs, [&] { doc.select_rect(view, rect, SelectionMode::Replace, false); });
    std::printf("| part: EditorDocument::select_rect, through (core, scene, panel; no draw) | %.1f ms | |\n", select);
    repaint_views(w);
    const auto repaint_one = [&] {
        v->update();
        sync_window(w, 1u << 1);
    };
    const double draw = median_ms(runs, repaint_one);
    bool k_in = false;
    const double moved = median_ms(runs, [&] {
        wheel(v, k_in = !k_in);
        repaint_one();
    });
    std::printf("| part: front view's repaint, nothing changed / camera changed | %.1f / %.1f ms | |\n", draw, moved);
}

// A shown 1280x800 window that has opened `mesh` and drawn every view; null on timeout.
std::unique_ptr<editor::MainWindow> open_window(const editor::StartOptions& start, const TriangleMesh& mesh) {
    auto w = std::make_unique<editor::MainWindow>(start);
    w->resize(1280, 800);
    if (!open(*w, mesh)) return nullptr;
    return w;
}

// Median ms of a flush of the window with no view changed (the status bar repainted): what Qt's
// composition of the window costs whatever the views do.
double flush_ms(editor::MainWindow& w, int runs) {
    int k = 0;
    return median_ms(runs, [&] {
        w.statusBar()->showMessage(QString::number(++k));
        w.statusBar()->repaint();
        finish_views(w);
    });
}

// Median ms of drawing all four views after each view's camera moved (a wheel step, in and out in turn).
double redraw_ms(editor::MainWindow& w, int runs) {
    int k = 0;
    return median_ms(runs, [&] {
        const bool in = ++k % 2 == 0;
        for (int i = 0; i < 4; ++i) wheel(w.grid().view(i), in);
        sync_window(w);
    });
}

// Median ms of drawing all four views after the selection changed (half the samples, then none), no core call.
double selection_drawn_ms(editor::MainWindow& w, int runs) {
    std::vector<uint32_t> half;
    for (uint32_t i = 0; i < w.document().samples().size(); i += 2) half.push_back(i);
    return median_ms(runs, [&] {
        w.document().set_selection(w.document().selection().empty() ? half : std::vector<uint32_t>{});
        sync_window(w);
    });
}

} // namespace

int main(int argc, char** argv) {
    spt::editor::use_render_gl_format();
    QApplication app(argc, argv);
    editor::StartOptions start;
    start.autosave_seconds = 0;
    start.recovery_dir = QDir::tempPath() + "/spt-editor-bench-recovery";
    const TriangleMesh big = make_torus(1.0, 0.3, 1000, 1000), mid = make_torus(1.0, 0.3, 250, 200);

    // --profile selection|redraw|flush N: only N runs of one measurement, for perf.
    if (argc == 4 && std::string(argv[1]) == "--profile") {
        const std::string what = argv[2];
        const int runs = std::atoi(argv[3]);
        const auto w = open_window(start, what == "redraw" ? mid : big);
        if (!w) return 1;
        const double ms = what == "redraw" ? redraw_ms(*w, runs)
                          : what == "flush" ? flush_ms(*w, runs)
                                            : selection_drawn_ms(*w, runs);
        std::printf("%s: %.1f ms median; views drew: %s\n", what.c_str(), ms, draw_kinds(*w).c_str());
        return 0;
    }

    std::printf("| measurement | median | what |\n|---|---|---|\n");
    {
        const auto w = open_window(start, big);
        if (!w) return 1;
        selection_parts(*w, big, 5);
        const double drawn = selection_drawn_ms(*w, 11);
        std::printf("| part: all four views drawn after a selection change (no core) | %.1f ms | half the samples, then none; "
                    "views drew: %s |\n",
                    drawn, draw_kinds(*w).c_str());
        std::printf("| part: a flush of the window with no view changed (status bar) | %.1f ms | Qt's composition |\n",
                    flush_ms(*w, 11));
        size_t through = 0, visible = 0;
        const double t_through = selection_ms(*w, false, 11, &through);
        const double t_visible = selection_ms(*w, true, 11, &visible);
        std::printf("| selection, through | %.1f ms | %zu vertices, %zu triangles; %zu samples selected in the front view |\n",
                    t_through, big.positions.size(), big.triangles.size(), through);
        std::printf("| selection, visible only | %.1f ms | same mesh; %zu samples selected |\n", t_visible, visible);
    }
    {
        const auto w = open_window(start, mid);
        if (!w) return 1;
        const double moved = redraw_ms(*w, 21);
        const std::string kinds = draw_kinds(*w);
        const double unchanged = median_ms(21, [&] { repaint_views(*w); });
        const QSize s = w->grid().view(0)->framebuffer_size();
        std::printf("| redraw of all four views, cameras moved | %.1f ms | %zu triangles, %zu sampling spheres, window "
                    "1280x800 (views %dx%d); views drew: %s |\n",
                    moved, mid.triangles.size(), w->document().samples().size(), s.width(), s.height(), kinds.c_str());
        std::printf("| repaint of all four views, nothing changed | %.1f ms | same; views drew: %s |\n", unchanged,
                    draw_kinds(*w).c_str());
    }
    std::printf("<!-- runs in which a view did not paint: %d -->\n", g_missed_paints);
    return 0;
}
