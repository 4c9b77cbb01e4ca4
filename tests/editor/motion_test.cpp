// Authoring from motion (issue 40) in the editor: a scene's motion loaded in the background through
// the path File > Load motion takes, its heat map in every view, a build from motion as one undo
// command recorded in the tree, and the cost panel's column for the motion.
#include "cost_panel.hpp"
#include "editor_support.hpp"
#include "tree_panel.hpp"
#include <QAction>
#include <QApplication>
#include <QWheelEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <gtest/gtest.h>

using namespace spt;
using namespace spt::test;

namespace {

const QString kResources = QString(SPT_SOURCE_DIR) + "/resources/";
const QString kWalking = kResources + "scenes/walking.json";

// The bundled walking figure's document with its skinned mesh (the scene's object `walker`).
std::unique_ptr<editor::MainWindow> open_figure(const TempDir& dir, std::string* error) {
    editor::StartOptions start = test_start(dir);
    start.file = kResources + "scenes/figure_walk.spt";
    start.mesh = kResources + "models/walking_figure.gltf";
    start.output = QString::fromStdString(dir.file("out.spt"));
    auto w = std::make_unique<editor::MainWindow>(start);
    w->show();
    if (!wait_ready(*w)) return *error = "the editor did not open the figure: " + w->last_error().toStdString(), nullptr;
    return w;
}

// Loads the motion of `object` in `scene` as the menu does once the object is chosen; true when it is in.
bool load(editor::MainWindow& w, const QString& scene, const QString& object, int steps, QString* failure = nullptr) {
    QSignalSpy loaded(&w.motion(), &editor::MotionSession::loaded);
    QSignalSpy failed(&w.motion(), &editor::MotionSession::failed);
    if (!w.load_motion(scene, object, steps)) return false;
    if (!QTest::qWaitFor([&] { return loaded.count() + failed.count() > 0; }, 300000)) return false;
    if (failure && failed.count()) *failure = failed.front().front().toString();
    return loaded.count() == 1;
}

// Pixels of a heat colour from the upper half of the ramp (green to yellow): neither the grey of 0
// steps, the mesh and the grid, nor the highlight's orange-yellow (the axis gizmo's Y is green too).
int heat_pixels(const QImage& image) {
    int n = 0;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < rgb.height(); ++y)
        for (int x = 0; x < rgb.width(); ++x) {
            const QColor c(rgb.pixel(x, y));
            if (c.green() > c.red() + 25 && c.green() > c.blue() + 25 && c.green() > 120) ++n;
        }
    return n;
}

} // namespace

TEST(MotionUi, LoadingAMotionColoursEveryViewByContactsAndBadInputKeepsTheDocument) {
    TempDir dir("editor-motion-load");
    std::string error;
    const auto w = open_figure(dir, &error);
    ASSERT_TRUE(w) << error;
    const std::vector<uint8_t> bytes = w->document().encode();
    // Coloured by level (colour by node, the default, has hues the heat map's count would take for heat).
    w->tree_panel().findChild<QComboBox*>("color_by")->setCurrentIndex(0);
    QCoreApplication::processEvents();
    std::vector<int> before;
    std::vector<QImage> level_pictures;
    for (int i = 0; i < 4; ++i) {
        level_pictures.push_back(w->grid().view(i)->grabFramebuffer());
        before.push_back(heat_pixels(level_pictures.back()));
    }

    // Bad input: a message naming the file; the document and the views stay.
    QString failure;
    EXPECT_FALSE(load(*w, QString::fromStdString(dir.file("no_such_scene.json")), "walker", 0, &failure));
    EXPECT_TRUE(failure.contains("no_such_scene.json")) << failure.toStdString();
    EXPECT_TRUE(w->last_error().contains("no_such_scene.json")) << w->last_error().toStdString();
    EXPECT_FALSE(load(*w, kWalking, "nobody", 0, &failure));
    EXPECT_TRUE(failure.contains("walking.json") && failure.contains("'nobody'")) << failure.toStdString();
    // The floor is another mesh than the figure's.
    EXPECT_FALSE(load(*w, kWalking, "floor", 0, &failure));
    EXPECT_TRUE(failure.contains("walking.json") && failure.contains("not made from")) << failure.toStdString();
    EXPECT_FALSE(w->motion().recording());
    EXPECT_EQ(w->document().encode(), bytes);

    // The menu's object list offers the walker first: its mesh is the document's.
    const editor::SceneObjects objects = editor::read_scene_objects(kWalking);
    ASSERT_EQ(objects.names, QStringList({"floor", "walker"}));
    EXPECT_EQ(editor::matching_object(objects, QString::fromStdString(w->document().document().mesh.name), {}), 1);

    ASSERT_TRUE(load(*w, kWalking, "walker", 0));
    const auto rec = w->motion().recording();
    ASSERT_TRUE(rec);
    EXPECT_EQ(rec->steps.size(), 200u);
    EXPECT_GT(rec->most_contact_steps, 10u);
    EXPECT_EQ(w->document().encode(), bytes) << "a motion is not an edit";
    EXPECT_EQ(w->undo_stack().count(), 0);
    // The views switch to the heat map: the combo says so, every view has its legend and draws it.
    EXPECT_EQ(w->tree_panel().findChild<QComboBox*>("color_by")->currentIndex(), 2);
    int views_with_heat = 0;
    for (int i = 0; i < 4; ++i) {
        editor::ViewWidget* v = w->grid().view(i);
        ASSERT_TRUE(v->legend()->isVisible()) << i;
        EXPECT_TRUE(v->legend()->text().contains("steps in contact")) << i;
        EXPECT_TRUE(v->legend()->text().contains(QString("%1 samples").arg(std::count(rec->contact_steps.begin(),
                                                                                        rec->contact_steps.end(), 0u))))
            << v->legend()->text().toStdString();
        const QImage heat = v->grabFramebuffer();
        EXPECT_NE(heat, level_pictures[size_t(i)]) << "view " << i << " still coloured by level";
        if (heat_pixels(heat) > before[size_t(i)] + 20) ++views_with_heat;
    }
    // Every sphere of a sample in contact has a heat colour, the others grey; at a pose of the walk
    // clip too (the spheres follow the surface, their colours their samples).
    const auto coloured = [&] {
        size_t n = 0;
        for (const render::SphereInstance& sphere : w->scene().data().spheres)
            if (sphere.color.r != render::heat_zero_color().r || sphere.color.g != render::heat_zero_color().g) ++n;
        return n;
    };
    const size_t in_contact = size_t(std::count_if(rec->contact_steps.begin(), rec->contact_steps.end(), [](uint32_t c) { return c > 0; }));
    EXPECT_EQ(coloured(), in_contact);
    ASSERT_TRUE(w->document().animation());
    w->document().set_pose(0, 0.5);
    ASSERT_TRUE(w->document().posed());
    EXPECT_EQ(coloured(), in_contact);
    w->document().set_pose(-1, 0);
    // The soles (the samples most in contact) are under the figure in the top view and a few
    // pixels in the front view: the side and camera views show them large enough to count.
    EXPECT_GE(views_with_heat, 2);

    // Back to levels: the legend goes, the heat colours too.
    w->tree_panel().findChild<QComboBox*>("color_by")->setCurrentIndex(0);
    for (int i = 0; i < 4; ++i) {
        EXPECT_FALSE(w->grid().view(i)->legend()->isVisible());
        EXPECT_EQ(w->grid().view(i)->grabFramebuffer(), level_pictures[size_t(i)]) << "view " << i;
    }

    // For docs/editor.md: the heat map again, the front and side views zoomed 3x about the soles (the
    // camera view zooms towards its target).
    w->tree_panel().findChild<QComboBox*>("color_by")->setCurrentIndex(2);
    Eigen::Vector3d soles = Eigen::Vector3d::Zero();
    double weight = 0;
    for (size_t k = 0; k < rec->contact_steps.size(); ++k)
        if (rec->contact_steps[k] > 0) soles += rec->contact_steps[k] * w->document().samples().position(k), weight += rec->contact_steps[k];
    soles /= weight;
    for (editor::ViewWidget* v : {w->grid().view(1), w->grid().view(2)}) {
        const ViewProjection vp = v->view_projection();
        const Eigen::Vector4f clip = vp.projection * vp.view * Eigen::Vector4f(float(soles.x()), float(soles.y()), float(soles.z()), 1);
        const QPointF at((clip.x() / clip.w() + 1) * 0.5 * v->width(), (1 - clip.y() / clip.w()) * 0.5 * v->height());
        QWheelEvent wheel(at, v->mapToGlobal(at), QPoint(), QPoint(0, 120 * 8), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(v, &wheel);
    }
    w->findChild<QDockWidget*>("history_dock")->raise();
    for (QMessageBox* box : w->findChildren<QMessageBox*>()) box->close(); // the bad input's messages
    QTest::qWait(300);
    w->screen()->grabWindow(w->winId()).save(QString::fromStdString(editor_output_dir() + "/motion_heat_map.png"));
}

TEST(MotionUi, BuildFromMotionWithShiftBIsOneUndoableEditRecordedInTheTree) {
    TempDir dir("editor-motion-build");
    std::string error;
    const auto w = open_figure(dir, &error);
    ASSERT_TRUE(w) << error;
    QAction* action = w->build_motion_action();
    ASSERT_TRUE(action);
    EXPECT_FALSE(action->isEnabled()) << "no motion yet";
    ASSERT_TRUE(load(*w, kWalking, "walker", 80));
    // 'walk' is built already: its root is inner. A new tree's root holds every sample.
    EXPECT_FALSE(action->isEnabled());
    ASSERT_TRUE(w->add_tree("from motion"));
    EXPECT_TRUE(action->isEnabled());
    const std::vector<uint8_t> before = w->document().encode();
    const int index = w->undo_stack().index();

    QTest::keyClick(w.get(), Qt::Key_B, Qt::ShiftModifier);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !w->building(); }, 300000));
    ASSERT_EQ(w->undo_stack().index(), index + 1) << w->last_message().toStdString();
    EXPECT_TRUE(w->undo_stack().text(index).startsWith("Build from motion under node 1 (walking.json / walker"))
        << w->undo_stack().text(index).toStdString();
    const SamplingTree& tree = w->document().tree();
    EXPECT_EQ(tree.name(), "from motion");
    EXPECT_GT(tree.node_count(), 100u);
    ASSERT_EQ(tree.motion_builds().size(), 1u);
    const MotionBuildStep& step = tree.motion_builds().front();
    EXPECT_EQ(step.node, root_id());
    EXPECT_EQ(step.object, "walker");
    EXPECT_EQ(step.steps, 80);
    EXPECT_EQ(step.leaf_size, w->tree_panel().build_options().leaf_size);
    // Relative to the folder of the file it is saved to (-o).
    EXPECT_EQ(QString::fromStdString(step.scene),
              QDir(QString::fromStdString(dir.path().string())).relativeFilePath(kWalking));
    EXPECT_TRUE(w->tree_panel().findChild<QComboBox*>("tree_list")->currentText().contains("motion: walking.json / walker"));
    EXPECT_FALSE(action->isEnabled()) << "the root is inner now";
    const std::vector<uint8_t> after = w->document().encode();

    QTest::keyClick(w.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(w->document().encode(), before);
    EXPECT_TRUE(action->isEnabled());
    QTest::keyClick(w.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_EQ(w->document().encode(), after);
}

TEST(MotionUi, CostPanelMeasuresTheEditedAutomaticAndMotionBuiltTreesOnTheMotion) {
    TempDir dir("editor-motion-cost");
    std::string error;
    const auto w = open_figure(dir, &error);
    ASSERT_TRUE(w) << error;
    ASSERT_TRUE(load(*w, kWalking, "walker", 60));
    editor::CostPanel& panel = w->cost_panel();
    panel.set_pose_counts(10, 10);
    QSignalSpy finished(&panel, &editor::CostPanel::finished);
    ASSERT_TRUE(panel.run());
    ASSERT_TRUE(finished.wait(300000));
    ASSERT_TRUE(panel.report()) << w->last_message().toStdString();
    const editor::CostReport& r = *panel.report();
    ASSERT_EQ(r.motion.size(), 3u);
    for (const MotionCost& c : r.motion) {
        EXPECT_FALSE(c.cancelled);
        EXPECT_GT(c.queries, 0u);
        EXPECT_GT(c.median_ns, 0);
        EXPECT_GT(c.mean_node_pairs, 0);
    }
    EXPECT_EQ(r.motion_label, "walking.json / walker");
    auto* table = panel.findChild<QTableWidget*>("cost_motion_table");
    ASSERT_TRUE(table);
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row) ASSERT_TRUE(table->item(row, col)) << row << "," << col;
    EXPECT_EQ(table->item(2, 2)->text(), QString::number(r.motion[2].mean_sphere_tests, 'f', 1));
    // The tree box says which motion the tree was measured on.
    EXPECT_TRUE(w->tree_panel().findChild<QComboBox*>("tree_list")->currentText().contains("measured: walking.json / walker"))
        << w->tree_panel().findChild<QComboBox*>("tree_list")->currentText().toStdString();
    w->findChild<QDockWidget*>("cost_dock")->raise();
    QTest::qWait(200);
    panel.grab().save(QString::fromStdString(editor_output_dir() + "/motion_cost_panel.png"));
}

TEST(MotionUi, CancelMotionDropsTheRunAndKeepsTheMotionLoadedBefore) {
    TempDir dir("editor-motion-cancel");
    std::string error;
    const auto w = open_figure(dir, &error);
    ASSERT_TRUE(w) << error;
    ASSERT_TRUE(load(*w, kWalking, "walker", 30));
    const auto first = w->motion().recording();
    QSignalSpy failed(&w->motion(), &editor::MotionSession::failed);
    ASSERT_TRUE(w->load_motion(kWalking, "walker", 0));
    EXPECT_TRUE(w->windowTitle().endsWith("(loading motion)")) << w->windowTitle().toStdString();
    EXPECT_FALSE(w->load_motion(kWalking, "walker", 0)) << "a second load started while one was running";
    auto* cancel = w->findChild<QPushButton*>("cancel_motion");
    ASSERT_TRUE(cancel && cancel->isVisible());
    QTest::mouseClick(cancel, Qt::LeftButton);
    ASSERT_TRUE(QTest::qWaitFor([&] { return failed.count() == 1; }, 300000));
    EXPECT_TRUE(failed.front().at(1).toBool()) << "not reported as cancelled: " << failed.front().at(0).toString().toStdString();
    EXPECT_EQ(w->motion().recording(), first);
    EXPECT_EQ(w->motion().steps(), 30);
    EXPECT_FALSE(w->windowTitle().contains("loading motion"));
    EXPECT_FALSE(cancel->isVisible());
    // Another document forgets the motion: its counts are per sample of this one.
    w->open_file(kResources + "meshes/torus.obj");
    ASSERT_TRUE(wait_ready(*w));
    EXPECT_FALSE(w->motion().recording());
    EXPECT_FALSE(w->build_motion_action()->isEnabled());
}

// One code path for the heat map: each view equals `spt render --color-by contacts` of the same
// view and size (the legend is a label over the view, not in its framebuffer).
TEST(MotionUi, EachHeatMapViewMatchesSptRenderColorByContacts) {
    TempDir dir("editor-motion-vs-render");
    std::string error;
    const auto w = open_figure(dir, &error);
    ASSERT_TRUE(w) << error;
    ASSERT_TRUE(load(*w, kWalking, "walker", 0));
    for (int i = 0; i < 4; ++i)
        expect_view_matches_spt_render(*w->grid().view(i),
                                       {kResources + "models/walking_figure.gltf", "--tree",
                                        kResources + "scenes/figure_walk.spt", "--tree-name", "walk", "--color-by",
                                        "contacts", "--scene", kWalking, "--object", "walker", "--overlay",
                                        "spheres,node,grid,axes", "--node", "1"},
                                       dir, "contacts_vs_render");
}
