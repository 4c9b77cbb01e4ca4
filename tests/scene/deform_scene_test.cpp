// Animated objects in scenes: objects[].animation and the effect deform (docs/deforming.md).
#include "scene_fixture.hpp"
#include "spt/error.hpp"
#include "spt/simulation.hpp"
#include <gtest/gtest.h>

namespace {

using namespace spt;

const std::string kBar = std::string(SPT_SOURCE_DIR) + "/tests/data/anim/bending_bar.gltf";

// The bar (2 long on x, its tip half turning up about z at x = 1 over the clip's first second)
// under a 0.3 box at (1, 0.8, 0): apart at rest, crossed by the tip once it has turned.
std::string bar_scene(const std::string& animation, const std::string& effects) {
    return R"({"spt_scene": 1, "dt": 0.25, "steps": 8, "effects": [)" + effects + R"(], "objects": [
        {"name": "bar", "model": ")" + kBar + R"(", "static": true, "animation": )" + animation + R"(},
        {"name": "box", "model": "box.obj", "scale": 0.3, "static": true, "position": [1, 0.8, 0]}]})";
}

std::vector<uint64_t> colliding_per_step(const Scene& s, EffectSet fx, int threads = 1) {
    Simulation sim(s, fx, threads);
    std::vector<uint64_t> out;
    for (int i = 0; i < 8; ++i) out.push_back(sim.step().counters.colliding_pairs);
    return out;
}

TEST(DeformScene, AnAnimatedObjectTakesItsClipsPoseOnlyWithTheEffectDeform) {
    const test::SceneDir dir;
    const Scene s = load_scene(dir.write("s.json", bar_scene(R"({"clip": "step"})", R"("contacts", "deform")")));
    ASSERT_TRUE(s.objects[0].animated);
    // Steps end at 0.25, 0.5, ... 2 s: the tip is up (90 degrees) at 1 s and down again at 2 s.
    const std::vector<uint64_t> with = colliding_per_step(s, parse_effect_list("contacts,deform", "t"));
    EXPECT_EQ(with[3], 1u) << "t = 1 s";
    EXPECT_EQ(with[7], 0u) << "t = 2 s";
    const std::vector<uint64_t> without = colliding_per_step(s, parse_effect_list("contacts", "t"));
    for (uint64_t c : without) EXPECT_EQ(c, 0u); // the bind pose: never up
    Simulation sim(s, parse_effect_list("contacts", "t"));
    EXPECT_EQ(sim.step().counters.ns_deform, 0);
    Simulation deforming(s, parse_effect_list("contacts,deform", "t"));
    EXPECT_GT(deforming.step().counters.ns_deform, 0);
}

TEST(DeformScene, SpeedOffsetAndLoopSetTheClipsTime) {
    const test::SceneDir dir;
    // Offset 0.75 s: up at the first step's end (clip time 1 s); held at the clip's end (down) without a loop.
    const Scene held = load_scene(dir.write("h.json", bar_scene(R"({"clip": "step", "offset": 0.75, "loop": false})",
                                                                R"("contacts", "deform")")));
    const std::vector<uint64_t> h = colliding_per_step(held, held.effects);
    EXPECT_EQ(h[0], 1u);
    EXPECT_EQ(h[7], 0u); // clip time 2.75 s, held at its end (2 s): down
    // Speed 2: clip time 1 s at scene time 0.5 s; looping, up again at scene time 1.5 s.
    const Scene fast = load_scene(dir.write("f.json", bar_scene(R"({"clip": 1, "speed": 2})", R"("contacts", "deform")")));
    const std::vector<uint64_t> f = colliding_per_step(fast, fast.effects);
    EXPECT_EQ(f[1], 1u) << "scene 0.5 s";
    EXPECT_EQ(f[3], 0u) << "scene 1 s: clip 2 s, wrapped to 0";
    EXPECT_EQ(f[5], 1u) << "scene 1.5 s";
}

TEST(DeformScene, ResultsAreTheSameOnAnyNumberOfThreads) {
    const test::SceneDir dir;
    // Depth poses in full each object that collided (the tip meets the box from 0.75 s).
    const Scene s = load_scene(dir.write("s.json", bar_scene(R"({"clip": "step"})", R"("contacts", "depth", "deform")")));
    Simulation one(s, s.effects, 1), two(s, s.effects, 2);
    for (int i = 0; i < 8; ++i) {
        const StepResult a = one.step();
        const StepResult& b = two.step();
        ASSERT_EQ(a.counters.node_pairs, b.counters.node_pairs) << i;
        ASSERT_EQ(a.contacts.size(), b.contacts.size()) << i;
        for (size_t k = 0; k < a.contacts.size(); ++k) ASSERT_EQ(a.contacts[k].depth, b.contacts[k].depth);
        ASSERT_EQ(a.state_hash, b.state_hash);
    }
}

// A scene of the bar with `effects` (which pose it lazily), stepped on one thread and on two, and
// with `whole` (which pose it whole): the same colliding pairs at every step.
void expect_lazy_steps_as_whole(const char* effects, const char* whole) {
    const test::SceneDir dir;
    const Scene s = load_scene(dir.write("s.json", bar_scene(R"({"clip": "step"})", effects)));
    Simulation one(s, s.effects, 1), two(s, s.effects, 2);
    Simulation posed_whole(s, parse_effect_list(whole, "t"), 1);
    uint64_t colliding = 0;
    for (int i = 0; i < 8; ++i) {
        const StepResult a = one.step();
        const StepResult b = two.step();
        const StepResult& c = posed_whole.step();
        ASSERT_EQ(a.counters.node_pairs, b.counters.node_pairs) << i;
        ASSERT_EQ(a.counters.triangle_tests, b.counters.triangle_tests) << i;
        ASSERT_EQ(a.counters.colliding_pairs, b.counters.colliding_pairs) << i;
        ASSERT_EQ(a.counters.colliding_pairs, c.counters.colliding_pairs) << i;
        ASSERT_EQ(a.state_hash, b.state_hash);
        colliding += a.counters.colliding_pairs;
    }
    EXPECT_GT(colliding, 0u);
}

TEST(DeformScene, ContactsAlonePoseLazilyWithTheSameAnswersOnAnyNumberOfThreads) {
    // contacts alone: the walks pose what they read, on whichever thread meets it first; depth
    // makes the scene pose whole objects, and finds the same colliding pairs.
    expect_lazy_steps_as_whole(R"("contacts", "deform")", "contacts,depth,deform");
}

TEST(DeformScene, ContactsConfirmedByTheTrianglesPoseLazilyWithTheSameAnswers) {
    // contacts with the exact effect: the triangles confirm each sphere contact, refit once a pose
    // for the first walk that asks them.
    expect_lazy_steps_as_whole(R"("contacts", "exact", "deform")", "contacts,exact,depth,deform");
}

TEST(DeformScene, AClipTheModelLacksIsRefusedNamingTheClipsItHas) {
    const test::SceneDir dir;
    try {
        load_scene(dir.write("s.json", bar_scene(R"({"clip": "run"})", R"("deform")")));
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        const std::string m = e.what();
        EXPECT_NE(m.find("/objects/0/animation/clip"), std::string::npos) << m;
        EXPECT_NE(m.find("0 'linear', 1 'step', 2 'cubic'"), std::string::npos) << m;
    }
    EXPECT_THROW(load_scene(dir.write("n.json", bar_scene(R"({"clip": 3})", R"("deform")"))), Error);
}

TEST(DeformScene, BadAnimationFieldsAreRefusedWithTheirPath) {
    const test::SceneDir dir;
    for (const char* a : {R"({"clip": -1})", R"({"clip": ""})", R"({"speed": "fast"})", R"({"loop": 1})",
                          R"({"clips": "walk"})", R"("walk")"}) {
        try {
            parse_scene(bar_scene(a, R"("deform")"), "s.json", dir.file(""));
            FAIL() << a;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("/objects/0/animation"), std::string::npos) << e.what();
        }
    }
}

TEST(DeformScene, AnAnimatedSptFileIsRefusedForWantOfItsSkin) {
    const test::SceneDir dir;
    const std::string json = R"({"spt_scene": 1, "objects": [
        {"name": "b", "model": "ball.spt", "animation": {"clip": 0}}]})";
    try {
        load_scene(dir.write("s.json", json));
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("needs its mesh file"), std::string::npos) << e.what();
    }
}

} // namespace

namespace {

// Two bars turning up: one under the box, one far from everything. Only the one a query needs is
// posed (the other's broad-phase sphere, from its joints, meets nothing): its layout stays at bind.
TEST(DeformScene, OnlyObjectsAQueryNeedsArePosed) {
    const test::SceneDir dir;
    const std::string json = R"({"spt_scene": 1, "dt": 0.25, "effects": ["contacts", "deform"], "objects": [
        {"name": "near", "model": ")" + kBar + R"(", "static": true, "animation": {"clip": "step"}},
        {"name": "far", "model": ")" + kBar + R"(", "static": true, "position": [50, 0, 0], "animation": {"clip": "step"}},
        {"name": "box", "model": "box.obj", "scale": 0.3, "static": true, "position": [1, 0.8, 0]}]})";
    const Scene s = load_scene(dir.write("s.json", json));
    Simulation sim(s, s.effects);
    for (int i = 0; i < 4; ++i) sim.step(); // 1 s: both clips have turned their tips up
    const CompactTree& bind = s.objects[1].model->tree(); // the scene as loaded: the bind pose
    auto same_spheres = [&](const CompactTree& t) {
        for (size_t n = 0; n < t.nodes().size(); ++n) {
            const CompactNode& a = t.nodes()[n];
            for (uint32_t k = a.first; a.is_active() && k < a.first + a.count; ++k)
                if (t.sphere_center(a, k) != bind.sphere_center(bind.nodes()[n], k)) return false;
        }
        return true;
    };
    EXPECT_FALSE(same_spheres(sim.scene().objects[0].model->tree())); // posed for its query with the box
    EXPECT_TRUE(same_spheres(sim.scene().objects[1].model->tree()));  // never needed
    EXPECT_EQ(sim.step().counters.colliding_pairs, 1u);
}

} // namespace
