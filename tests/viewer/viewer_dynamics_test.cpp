// The viewer on a scene with effect dynamics: the manifold overlay in the frame (which equals
// `spt render` of the same step, view, size and overlays), and the energy plot under the
// counters, one point a state up to the one shown, each Simulation::mechanical_energy of it.
#include "render/pixel_colours.hpp"
#include "viewer_support.hpp"
#include <QTest>
#include <gtest/gtest.h>

using namespace spt;
using namespace spt::test;

namespace {

// The energy plot shows states 0..k of `sim`'s run: k + 1 points at k dt seconds, each the
// simulation's mechanical energy after that many steps (stepped on here as needed).
void expect_energy_of_steps(const editor::EnergyPlot& plot, Simulation& sim, std::vector<double>& energies, int k) {
    while (int(energies.size()) <= k) {
        if (!energies.empty()) sim.step();
        energies.push_back(sim.mechanical_energy());
    }
    ASSERT_EQ(plot.points().size(), size_t(k + 1));
    for (int s = 0; s <= k; ++s) {
        EXPECT_DOUBLE_EQ(plot.points()[size_t(s)].x(), double(s) * sim.scene().dt) << "state " << s;
        EXPECT_EQ(plot.points()[size_t(s)].y(), energies[size_t(s)]) << "state " << s;
    }
}

} // namespace

TEST(ViewerDynamics, ManifoldOverlayIsDrawnAsSptRenderDrawsIt) {
    TempDir dir("viewer-dynamics");
    const QString scene = QString(SPT_SOURCE_DIR) + "/resources/scenes/stack.json";
    editor::ViewerOverlays o;
    o.scene.manifold = o.scene.contacts = o.scene.normals = true;
    auto w = show_viewer(scene, o, render::View::Front, 120);
    ASSERT_TRUE(wait_recorded(*w, 120)) << w->last_error().toStdString();
    ASSERT_TRUE(wait_idle(*w));
    ASSERT_EQ(w->step(), 120);
    EXPECT_TRUE(w->history()->effects().has(Effect::Dynamics));
    EXPECT_TRUE(w->history()->effects().has(Effect::Depth)) << "contacts and normals add depth to dynamics";
    const QString overlays = "manifold,contacts,normals,grid,axes";
    for (render::View v : {render::View::Front, render::View::Camera}) {
        const std::string view = render::view_name(v);
        for (int step : {1, 120}) {
            render::Image shown;
            std::string error;
            const render::CompareResult r = compare_with_spt_render(*w, dir, scene, step, v, overlays, shown, error);
            ASSERT_TRUE(error.empty()) << error;
            EXPECT_TRUE(r.passed) << view << " step " << step << ": " << r.summary();
            // Five boxes resting on each other: their kept (warm-started) points are drawn.
            if (step == 120) {
                EXPECT_GT(pixels_of_color(shown, render::manifold_point_color(1)), 0u) << view;
            }
            render::write_png(shown, viewer_output_dir() + "/viewer_stack_" + view + "_" + std::to_string(step) + ".png");
        }
    }
    // Off, the points go.
    editor::ViewerOverlays off = o;
    off.scene.manifold = false;
    w->set_overlays(off);
    ASSERT_TRUE(wait_idle(*w));
    EXPECT_EQ(pixels_of_color(to_image(w->view()->grabFramebuffer()), render::manifold_point_color(1)), 0u);
}

TEST(ViewerDynamics, EnergyPlotGetsAPointAStepAndFollowsThePlayhead) {
    const QString scene = QString(SPT_SOURCE_DIR) + "/resources/scenes/bounce.json";
    editor::ViewerOverlays o;
    o.scene.manifold = true;
    auto w = show_viewer(scene, o, render::View::Front, 0);
    ASSERT_TRUE(wait_recorded(*w, 0)) << w->last_error().toStdString();
    ASSERT_TRUE(wait_idle(*w));
    const editor::EnergyPlot& plot = *w->energy();
    // The same scene simulated here: the plot must show its energies exactly (a thin client).
    Simulation sim(load_scene(scene.toStdString()), w->history()->effects(), 1);
    std::vector<double> energies;
    expect_energy_of_steps(plot, sim, energies, 0);
    // Steps as they run: one more point each.
    for (int k = 1; k <= 5; ++k) {
        ASSERT_TRUE(wait_recorded(*w, k));
        QTest::keyClick(w->view(), Qt::Key_Right);
        ASSERT_EQ(w->step(), k);
        expect_energy_of_steps(plot, sim, energies, k);
    }
    // Playing: the curve grows with the playhead; the ball falls, trading potential for kinetic energy.
    w->set_speed(4);
    w->set_playing(true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return w->step() >= 100; }, 120000));
    w->set_playing(false);
    const int played = w->step();
    expect_energy_of_steps(plot, sim, energies, played);
    w->grab().save(QString::fromStdString(viewer_output_dir() + "/viewer_bounce_window.png"));
    // The rebound at step 90 (restitution 0.8) loses energy: the curve ends below where it started.
    EXPECT_LT(plot.points().back().y(), plot.points().front().y());
    // Seeking back and restarting shorten the curve, as the history is shown.
    w->set_step(40);
    expect_energy_of_steps(plot, sim, energies, 40);
    QTest::keyClick(w->view(), Qt::Key_Home);
    expect_energy_of_steps(plot, sim, energies, 0);
    EXPECT_TRUE(w->energy()->isVisible());
}

TEST(ViewerDynamics, EnergyIsPlottedWithoutDynamicsAndManifoldSaysWhyItIsEmpty) {
    TempDir dir("viewer-energy-response");
    const QString scene = write_drop_scene(dir, 30, R"(["motion","gravity","contacts","depth","response"])");
    auto w = show_viewer(scene, {}, render::View::Camera, 30);
    ASSERT_TRUE(wait_recorded(*w, 30)) << w->last_error().toStdString();
    ASSERT_TRUE(wait_idle(*w));
    Simulation sim(load_scene(scene.toStdString()), w->history()->effects(), 1);
    std::vector<double> energies;
    expect_energy_of_steps(*w->energy(), sim, energies, 30);
    // Manifolds come only from dynamics: the overlay stays on, draws nothing, and the status bar says why.
    editor::ViewerOverlays o;
    o.scene.manifold = true;
    w->set_overlays(o);
    EXPECT_TRUE(w->last_message().contains("'manifold'")) << w->last_message().toStdString();
    EXPECT_TRUE(w->last_message().contains("'dynamics'")) << w->last_message().toStdString();
    EXPECT_FALSE(w->history()->effects().has(Effect::Dynamics)) << "an overlay never adds dynamics";
}
