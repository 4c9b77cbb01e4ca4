// Effect dynamics in scene files: its settings, per-object overrides, and what is refused.
#include "../scene/scene_fixture.hpp"
#include "dynamics/manifold_algorithm.hpp"
#include "spt/error.hpp"
#include "spt/scene.hpp"
#include "spt/simulation.hpp"
#include <gtest/gtest.h>

namespace {

using namespace spt;

std::string refusal(const std::string& text) { return test::parse_refusal(text); }

std::string scene_with(const std::string& top, const std::string& object = "") {
    return R"({"spt_scene": 1, "effects": ["motion", "gravity", "contacts", "dynamics"])" + top +
           R"(, "objects": [{"name": "a", "model": "a.obj")" + object + "}]}";
}

TEST(DynamicsSettings, DefaultsAreTheIssues) {
    const Scene s = parse_scene(scene_with(""), "s.json", ".");
    EXPECT_TRUE(s.effects.has(Effect::Dynamics));
    EXPECT_EQ(s.dynamics.friction, 0.5);
    EXPECT_EQ(s.dynamics.restitution, 0);
    EXPECT_EQ(s.dynamics.iterations, 10);
    EXPECT_EQ(s.dynamics.rolling_friction, 0);
    EXPECT_LT(s.objects[0].friction, 0); // not set: the scene's applies
    EXPECT_LT(s.objects[0].restitution, 0);
    EXPECT_EQ(s.objects[0].density, 1);
    EXPECT_EQ(s.objects[0].mass, 0);
}

TEST(DynamicsSettings, EverySettingIsReadAndCheckedAtItsPath) {
    const Scene s = parse_scene(scene_with(R"(, "dynamics": {"friction": 0.7, "restitution": 0.4, "iterations": 25, "rolling_friction": 0.02})",
                                           R"(, "mass": 3, "friction": 0.1, "restitution": 0.9, "rolling_friction": 0.5)"),
                                "s.json", ".");
    EXPECT_EQ(s.dynamics.friction, 0.7);
    EXPECT_EQ(s.dynamics.restitution, 0.4);
    EXPECT_EQ(s.dynamics.iterations, 25);
    EXPECT_EQ(s.objects[0].mass, 3);
    EXPECT_EQ(s.objects[0].friction, 0.1);
    EXPECT_EQ(s.objects[0].restitution, 0.9);
    EXPECT_EQ(s.objects[0].rolling_friction, 0.5);
    EXPECT_NE(refusal(scene_with(R"(, "dynamics": {"friction": -1})")).find("at /dynamics/friction"), std::string::npos);
    EXPECT_NE(refusal(scene_with(R"(, "dynamics": {"restitution": 1.5})")).find("at /dynamics/restitution"), std::string::npos);
    EXPECT_NE(refusal(scene_with(R"(, "dynamics": {"iterations": 0})")).find("at /dynamics/iterations"), std::string::npos);
    EXPECT_NE(refusal(scene_with(R"(, "dynamics": {"iterations": 2.5})")).find("at /dynamics/iterations"), std::string::npos);
    EXPECT_NE(refusal(scene_with(R"(, "dynamics": {"gravity": 1})")).find("at /dynamics/gravity: unknown field"), std::string::npos);
    EXPECT_NE(refusal(scene_with("", R"(, "mass": 0)")).find("at /objects/0/mass"), std::string::npos);
    EXPECT_NE(refusal(scene_with("", R"(, "density": -2)")).find("at /objects/0/density"), std::string::npos);
    EXPECT_NE(refusal(scene_with("", R"(, "restitution": 2)")).find("at /objects/0/restitution"), std::string::npos);
    EXPECT_NE(refusal(scene_with("", R"(, "friction": NaN)")).find("bad.json"), std::string::npos);
    EXPECT_NE(refusal(scene_with("", R"(, "mass": 1, "density": 1)")).find("a 'mass' or a 'density', not both"),
              std::string::npos);
}

TEST(DynamicsSettings, ResponseCcdExactAndAnotherLevelAreRefusedNamingBoth) {
    auto with_effects = [](const std::string& effects, const std::string& level = "") {
        return refusal(R"({"spt_scene": 1, "effects": [)" + effects + "]" + level +
                       R"(, "objects": [{"name": "a", "model": "a.obj"}]})");
    };
    const std::string response = with_effects(R"("motion", "contacts", "depth", "response", "dynamics")");
    EXPECT_NE(response.find("effects 'response' and 'dynamics' cannot run together"), std::string::npos) << response;
    EXPECT_NE(with_effects(R"("motion", "contacts", "ccd", "dynamics")").find("'ccd' and 'dynamics'"), std::string::npos);
    EXPECT_NE(with_effects(R"("motion", "contacts", "exact", "dynamics")").find("'exact' and 'dynamics'"), std::string::npos);
    EXPECT_NE(with_effects(R"("contacts", "dynamics")").find("effect 'dynamics' needs effect 'motion'"), std::string::npos);
    EXPECT_NE(with_effects(R"("motion", "dynamics")").find("effect 'dynamics' needs effect 'contacts'"), std::string::npos);
    EXPECT_NE(with_effects(R"("motion", "contacts", "dynamics")", R"(, "level": "exact")").find("at /level"), std::string::npos);
}

TEST(DynamicsSettings, APairUsesTheScenesValueUnlessAnObjectSetsOneAndBothCombineAsBulletDoes) {
    EXPECT_EQ(detail::combined_setting(-1, -1, 0.5, true), 0.5); // neither: the scene's, exactly
    EXPECT_EQ(detail::combined_setting(0.6, -1, 0.5, true), 0.6); // one: its own
    EXPECT_EQ(detail::combined_setting(-1, 0.2, 0.5, true), 0.2);
    EXPECT_DOUBLE_EQ(detail::combined_setting(0.6, 0.5, 0.5, true), 0.3); // both: the product
    EXPECT_EQ(detail::combined_setting(20, 30, 0.5, true), 10); // friction at most 10, as Bullet clamps it
    EXPECT_DOUBLE_EQ(detail::combined_setting(0.8, 0.5, 0, false), 0.4);
}

TEST(DynamicsSettings, AMovingOpenOrSptOnlyObjectWithoutMassIsRefusedNamingIt) {
    const test::SceneDir dir;
    const std::string path = dir.write("massless.json", R"({"spt_scene": 1, "effects": ["motion", "contacts", "dynamics"],
      "objects": [{"name": "floor", "model": "box.obj", "static": true},
                  {"name": "pebble", "model": "ball.spt", "position": [0, 2, 0]}]})");
    const Scene s = load_scene(path);
    try {
        Simulation sim(s, s.effects);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        EXPECT_NE(std::string(e.what()).find("object 'pebble'"), std::string::npos) << e.what();
    }
    Scene with_mass = s;
    with_mass.objects[1].mass = 2;
    Simulation sim(with_mass, with_mass.effects);
    EXPECT_EQ(sim.mass(1), 2);
    EXPECT_EQ(sim.mass(0), 1); // static: no mass of its own (1, as without dynamics)
}

TEST(DynamicsSettings, TheCommandLinesEffectsCannotAddDynamicsToAnotherLevel) {
    const test::SceneDir dir;
    const std::string path = dir.write("exact.json", R"({"spt_scene": 1, "level": "exact",
      "objects": [{"name": "floor", "model": "box.obj", "static": true}]})");
    const Scene s = load_scene(path);
    EXPECT_THROW(Simulation(s, parse_effect_list("motion,contacts,dynamics", "--effects")), Error);
}

} // namespace

namespace {

TEST(DynamicsKinematic, APathObjectPushesABoxAndNothingPushesIt) {
    const test::SceneDir dir;
    const std::string path = dir.write("push.json", R"({"spt_scene": 1, "dt": 0.01, "effects": ["motion", "gravity", "contacts", "dynamics"],
      "objects": [{"name": "plate", "model": "plate.obj", "static": true},
                  {"name": "box", "model": "box.obj", "position": [0, 0.511, 0]},
                  {"name": "paddle", "model": "box.obj",
                   "path": [{"t": 0, "position": [-1.2, 0.6, 0]}, {"t": 2, "position": [0.8, 0.6, 0]}]}]})");
    const Scene s = load_scene(path);
    Simulation sim(s, s.effects);
    for (int i = 0; i < 150; ++i) sim.step();
    const Pose paddle = path_pose(s.objects[2].path, 1.5);
    EXPECT_LT((sim.poses()[2].translation - paddle.translation).norm(), 1e-12); // on its path, whatever it meets
    // The paddle's face reached x = 0.3 at 1.5 s: the box, pushed, is beyond it (its centre past 0.8).
    EXPECT_GT(sim.poses()[1].translation.x(), 0.3 + 0.5 - 0.01);
    EXPECT_NEAR(sim.poses()[1].translation.y(), 0.51, 0.02); // still on the plate
}

} // namespace

namespace {

TEST(DynamicsSettings, WhatBulletsFloatCannotHoldIsRefusedBeforeAStepNotHungOn) {
    const test::SceneDir dir;
    const std::string path = dir.write("drop.json", R"({"spt_scene": 1, "effects": ["motion", "gravity", "contacts", "dynamics"],
      "objects": [{"name": "plate", "model": "plate.obj", "static": true},
                  {"name": "box", "model": "box.obj", "position": [0, 2, 0]}]})");
    const Scene s = load_scene(path);
    auto refused = [](const Scene& scene, const char* expected) {
        try {
            Simulation sim(scene, scene.effects);
            sim.step();
            ADD_FAILURE() << "not refused: " << expected;
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::BadInput);
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    };
    Scene heavy = s;
    heavy.gravity = Eigen::Vector3d(0, -1e300, 0);
    refused(heavy, "gravity of 1e+300");
    Scene tiny = s;
    tiny.objects[1].mass = 1e-30;
    refused(tiny, "object 'box' has a mass of 1e-30");
    Scene instant = s;
    instant.dt = 1e-9;
    refused(instant, "dt of 1e-09 s");
    Scene fast = s;
    fast.objects[1].velocity = Eigen::Vector3d(1e200, 0, 0);
    refused(fast, "object 'box' moves too fast");
    // Strong but representable gravity runs; the band it would ask for is capped, not a million pairs.
    Scene strong = s;
    strong.gravity = Eigen::Vector3d(0, -1e14, 0);
    Simulation sim(strong, strong.effects);
    for (int i = 0; i < 5; ++i) EXPECT_LT(sim.step().counters.sphere_tests, 10000000u);
}

} // namespace
