// Overlay `manifold` of a scene with effect dynamics: every manifold point of the step becomes one
// mark with its normal, coloured new or kept by its age, drawn on top; the contacts and normals
// overlays still work with dynamics (they add effect depth); and a scene without dynamics is
// told apart rather than drawn empty.
#include "pixel_colours.hpp"
#include "scenes.hpp"
#include "spt/render/camera.hpp"
#include "spt/render/image.hpp"
#include "spt/render/scene_drawing.hpp"
#include <gtest/gtest.h>

using namespace spt::render;
using spt::Effect;
using spt::EffectSet;

namespace {

spt::Scene bundled_scene(const char* name) { return spt::load_scene(std::string(SPT_SOURCE_DIR) + "/resources/scenes/" + name); }

bool same_color(const Color& a, const Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }

} // namespace

TEST(SceneManifold, EveryManifoldPointIsOneMarkColouredByItsAge) {
    const spt::Scene scene = bundled_scene("stack.json");
    ASSERT_TRUE(scene.effects.has(Effect::Dynamics));
    spt::Simulation sim(scene, scene.effects, 1);
    spt::test::OffscreenRenderer r("osmesa", 64, 64);
    SceneDrawing drawing(*r.renderer, sim.scene());
    SceneOverlays on;
    on.manifold = true;
    size_t new_points = 0, kept_points = 0;
    for (int k = 1; k <= 40; ++k) {
        const spt::StepResult& step = sim.step();
        const Frame f = drawing.frame(sim.poses(), &step, {}, {}, {}, on);
        std::vector<spt::ContactPoint> points;
        for (const spt::PairContact& c : step.contacts) points.insert(points.end(), c.manifold.begin(), c.manifold.end());
        ASSERT_EQ(f.collision.marks.size(), points.size()) << "step " << k;
        for (size_t i = 0; i < points.size(); ++i) {
            const ContactMark& m = f.collision.marks[i];
            EXPECT_EQ(m.point, points[i].point.cast<float>());
            EXPECT_EQ(m.normal, points[i].normal.cast<float>());
            EXPECT_TRUE(same_color(m.color, manifold_point_color(points[i].age)));
            (points[i].age == 0 ? new_points : kept_points)++;
        }
        EXPECT_TRUE(f.collision.pairs.empty()) << "manifold alone draws no contacts";
        EXPECT_TRUE(drawing.frame(sim.poses(), &step, {}, {}, {}, {}).collision.marks.empty()) << "overlay off";
    }
    // Five boxes settling on the floor and on each other: points appear and are kept.
    EXPECT_GT(new_points, 0u);
    EXPECT_GT(kept_points, new_points) << "resting contacts keep their points";
    EXPECT_FALSE(same_color(manifold_point_color(0), manifold_point_color(1)));
}

TEST(SceneManifold, MarksAreDrawnOnTopInTheirColoursAndAChangedMarkDrawsAgain) {
    const spt::Scene scene = bundled_scene("stack.json");
    spt::Simulation sim(scene, scene.effects, 1);
    for (int k = 0; k < 40; ++k) sim.step();
    const spt::StepResult& step = sim.step();
    spt::test::OffscreenRenderer r("osmesa", 128, 128);
    SceneDrawing drawing(*r.renderer, sim.scene());
    const Camera cam = fit_camera(View::Front, drawing.initial_bounds(*r.renderer));
    SceneOverlays on;
    on.manifold = true;
    Frame f = drawing.frame(sim.poses(), &step, {}, {}, {}, on);
    ASSERT_FALSE(f.collision.marks.empty());
    const Image with = r.view(f, cam);
    const Image without = r.view(drawing.frame(sim.poses(), &step, {}, {}, {}, {}), cam);
    EXPECT_GT(spt::test::pixels_of_color(with, manifold_point_color(1)), 0u) << "kept points, drawn over the boxes that hide them";
    EXPECT_EQ(spt::test::pixels_of_color(without, manifold_point_color(1)), 0u);
    // A mark that only changes colour (a point kept instead of new) is a new picture, not the cached one.
    r.view(f, cam);
    for (ContactMark& m : f.collision.marks) m.color = manifold_point_color(0);
    const Image recoloured = r.view(f, cam);
    EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Full);
    EXPECT_GT(spt::test::pixels_of_color(recoloured, manifold_point_color(0)), 0u);
}

TEST(SceneManifold, ContactsAndNormalsStillWorkWithDynamics) {
    const spt::Scene scene = bundled_scene("bounce.json");
    SceneOverlays o;
    o.contacts = o.normals = true;
    const EffectSet effects = effects_for_overlays(scene.effects, o);
    EXPECT_TRUE(effects.has(Effect::Depth) && effects.has(Effect::Dynamics));
    spt::Simulation sim(scene, effects, 1);
    spt::test::OffscreenRenderer r("osmesa", 32, 32);
    SceneDrawing drawing(*r.renderer, sim.scene());
    size_t contacts = 0;
    for (int k = 0; k < scene.steps; ++k) {
        const spt::StepResult& step = sim.step();
        const Frame f = drawing.frame(sim.poses(), &step, {}, {}, {}, o);
        ASSERT_EQ(f.collision.pairs.size(), step.contacts.size());
        for (size_t i = 0; i < step.contacts.size(); ++i) {
            EXPECT_TRUE(step.contacts[i].has_depth);
            EXPECT_EQ(f.collision.pairs[i].normal, step.contacts[i].normal.cast<float>());
        }
        contacts += step.contacts.size();
    }
    EXPECT_GT(contacts, 0u) << "the ball never touched the floor";
}

TEST(SceneManifold, ManifoldWithoutDynamicsIsAProblemNamingTheOverlayAndTheEffects) {
    SceneOverlays o;
    o.manifold = true;
    const std::string problem = scene_overlays_problem(bundled_scene("fig8.json").effects, o);
    EXPECT_NE(problem.find("manifold"), std::string::npos) << problem;
    EXPECT_NE(problem.find("dynamics"), std::string::npos) << problem;
    EXPECT_NE(problem.find("response"), std::string::npos) << "the scene's effects are listed: " << problem;
    EXPECT_EQ(scene_overlays_problem(bundled_scene("bounce.json").effects, o), "");
    EXPECT_EQ(scene_overlays_problem(bundled_scene("fig8.json").effects, {}), "");
    ASSERT_NE(scene_overlay_flag(o, "manifold"), nullptr);
    EXPECT_EQ(scene_overlay_flag(o, "manifold"), &o.manifold);
}
