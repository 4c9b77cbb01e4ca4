// The simulation: effect gating, determinism across threads, response depth, continuous detection.
#include "host_task_system.hpp"
#include "scene_fixture.hpp"
#include "spt/error.hpp"
#include "spt/simulation.hpp"
#include <gtest/gtest.h>
#include <random>

namespace {

using namespace spt;

// Ball b moves into the static ball a, overlapping from the start.
const char* kTwoBalls = R"({"spt_scene": 1, "objects": [
    {"name": "a", "model": "ball.obj", "static": true},
    {"name": "b", "model": "ball.obj", "position": [0.9, 0.05, 0], "velocity": [-1, 0, 0]}]})";

Scene scene(const spt::test::SceneDir& dir, const std::string& json) {
    return load_scene(dir.write("s.json", json));
}

TEST(Simulation, EachEffectRunsItsCodeOnlyWhenListed) {
    const spt::test::SceneDir dir;
    const Scene s = scene(dir, kTwoBalls);
    const char* lists[] = {"",
                           "motion",
                           "contacts",
                           "motion,contacts",
                           "motion,contacts,depth",
                           "motion,contacts,pairs",
                           "motion,contacts,depth,response",
                           "motion,contacts,ccd",
                           "contacts,exact",
                           "motion,gravity,contacts,depth,pairs,response,ccd,exact"};
    for (const char* list : lists) {
        const EffectSet fx = parse_effect_list(list, "test");
        Simulation sim(s, fx);
        const StepResult& r = sim.step();
        const StepCounters& c = r.counters;
        SCOPED_TRACE(list);
        const bool contacts = fx.has(Effect::Contacts);
        EXPECT_EQ(c.candidate_pairs > 0, contacts);
        EXPECT_EQ(c.colliding_pairs > 0, contacts);
        EXPECT_EQ(c.node_pairs > 0, contacts);
        EXPECT_EQ(c.sphere_tests > 0, contacts);
        EXPECT_EQ(c.ns_broad > 0, contacts);
        EXPECT_EQ(c.ns_narrow > 0, contacts);
        EXPECT_EQ(c.triangle_tests > 0, fx.has(Effect::Exact));
        EXPECT_EQ(c.depth_queries > 0, fx.has(Effect::Depth));
        EXPECT_EQ(c.ns_depth > 0, fx.has(Effect::Depth));
        EXPECT_EQ(c.ccd_queries > 0, fx.has(Effect::Ccd));
        EXPECT_EQ(c.ns_ccd > 0, fx.has(Effect::Ccd));
        EXPECT_EQ(c.responses > 0, fx.has(Effect::Response));
        EXPECT_EQ(c.ns_response > 0, fx.has(Effect::Response));
        EXPECT_EQ(r.contacts.size(), c.colliding_pairs);
        for (const PairContact& pc : r.contacts) {
            EXPECT_EQ(pc.has_depth, fx.has(Effect::Depth));
            EXPECT_EQ(pc.has_toi, fx.has(Effect::Ccd));
            EXPECT_EQ(!pc.pairs.empty(), fx.has(Effect::Pairs));
        }
        // ccd stops b where it starts (touching at time 0); a response moves it out.
        const bool moved = sim.poses()[1].translation != s.objects[1].pose.translation;
        EXPECT_EQ(moved, (fx.has(Effect::Motion) && !fx.has(Effect::Ccd)) || fx.has(Effect::Response));
    }
}

TEST(Simulation, GravityAcceleratesDynamicObjectsOnly) {
    const spt::test::SceneDir dir;
    const Scene s = scene(dir, R"({"spt_scene": 1, "dt": 0.1, "objects": [
        {"name": "a", "model": "ball.obj", "static": true},
        {"name": "b", "model": "ball.obj", "position": [5, 0, 0]},
        {"name": "c", "model": "ball.obj", "path": [{"t": 0, "position": [0, 5, 0]}, {"t": 1, "position": [1, 5, 0]}]}]})");
    Simulation sim(s, parse_effect_list("motion,gravity", "test"));
    for (int i = 0; i < 10; ++i) sim.step();
    EXPECT_EQ(sim.poses()[0].translation, Eigen::Vector3d::Zero());
    // Semi-implicit Euler: y = -g dt^2 (1 + 2 + ... + 10).
    EXPECT_NEAR(sim.poses()[1].translation.y(), -9.81 * 0.01 * 55, 1e-9);
    EXPECT_NEAR((sim.poses()[2].translation - Eigen::Vector3d(1, 5, 0)).norm(), 0, 1e-12);
}

TEST(Simulation, MotionBeyondTheRepresentableRangeIsRefusedAndTheStateKept) {
    const spt::test::SceneDir dir;
    // Finite everywhere in the file, yet one step carries b to 1e300 (and gravity c to infinity).
    const Scene s = scene(dir, R"({"spt_scene": 1, "dt": 1e150, "objects": [
        {"name": "a", "model": "ball.obj", "static": true},
        {"name": "b", "model": "ball.obj", "position": [5, 0, 0], "velocity": [1e150, 0, 0]}]})");
    Simulation sim(s, parse_effect_list("motion,contacts", "test"));
    try {
        sim.step();
        FAIL() << "a step to x = 1e300 was taken";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        EXPECT_NE(std::string(e.what()).find("'b'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("step 1"), std::string::npos) << e.what();
    }
    EXPECT_EQ(sim.steps_done(), 0);
    EXPECT_EQ(sim.poses()[1].translation, Eigen::Vector3d(5, 0, 0));
    const Scene g = scene(dir, R"({"spt_scene": 1, "dt": 1, "gravity": [0, -1e308, 0], "objects": [
        {"name": "c", "model": "ball.obj"}]})");
    Simulation fall(g, parse_effect_list("motion,gravity", "test"));
    EXPECT_THROW(fall.step(), Error);
    EXPECT_TRUE(fall.poses()[0].translation.allFinite());
}

TEST(Simulation, AStepWhoseTimeOverflowsIsRefusedAndNoInfinityWritten) {
    const spt::test::SceneDir dir;
    // dt is finite, and so is step 1's time; step 2's, 2 dt, is not.
    const Scene s = scene(dir, R"({"spt_scene": 1, "dt": 1e308, "objects": [{"name": "a", "model": "ball.obj"}]})");
    Simulation sim(s, parse_effect_list("motion", "test"));
    EXPECT_EQ(sim.step().time, 1e308);
    try {
        sim.step();
        FAIL() << "a step at time 2e308 was taken";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        EXPECT_NE(std::string(e.what()).find("step 2"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("dt"), std::string::npos) << e.what();
    }
    EXPECT_EQ(sim.steps_done(), 1);
}

// Balls on a jittered 3 x 3 x 3 lattice, 1.1 apart, over a floor, thrown at each other.
std::string ball_cloud(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> p(-0.04, 0.04), v(-3, 3);
    std::string objects = R"({"name": "floor", "model": "plate.obj", "static": true, "position": [0, -2, 0]})";
    for (int i = 0; i < n; ++i)
        objects += ",{\"name\": \"b" + std::to_string(i) + "\", \"model\": \"ball.spt\", \"position\": [" +
                   std::to_string(1.1 * (i % 3 - 1) + p(rng)) + "," + std::to_string(1.1 * (i / 3 % 3 - 1) + p(rng)) +
                   "," + std::to_string(1.1 * (i / 9 - 1) + p(rng)) + "], \"velocity\": [" + std::to_string(v(rng)) +
                   "," + std::to_string(v(rng)) + "," +
                   std::to_string(v(rng)) + "], \"angular_velocity\": [0, 1, 0.5]}";
    return R"({"spt_scene": 1, "dt": 0.01, "response": {"restitution": 0.5}, "objects": [)" + objects + "]}";
}

std::vector<uint64_t> hashes(const Scene& s, const EffectSet& fx, int threads, int steps, uint64_t* collisions,
                             TaskSystem* tasks = nullptr) {
    Simulation sim(s, fx, threads, tasks);
    std::vector<uint64_t> h;
    for (int i = 0; i < steps; ++i) {
        const StepResult& r = sim.step();
        h.push_back(r.state_hash);
        *collisions += r.counters.colliding_pairs;
    }
    return h;
}

// Also on a host's own threads (its jobs on them and on the stepping thread).
TEST(Simulation, SameStateHashesOnEveryRunForEveryThreadCountAndOnAHostsTaskSystem) {
    const spt::test::SceneDir dir;
    const Scene s = scene(dir, ball_cloud(27, 3));
    const EffectSet fx = parse_effect_list("motion,gravity,contacts,depth,pairs,response,ccd", "test");
    uint64_t collisions = 0;
    const std::vector<uint64_t> one = hashes(s, fx, 1, 60, &collisions);
    EXPECT_GT(collisions, 20u) << "the cloud should collide";
    EXPECT_EQ(hashes(s, fx, 1, 60, &collisions), one);
    EXPECT_EQ(hashes(s, fx, 2, 60, &collisions), one);
    EXPECT_EQ(hashes(s, fx, 4, 60, &collisions), one);
    spt::test::HostTaskSystem host(3);
    EXPECT_EQ(hashes(s, fx, 4, 60, &collisions, &host), one);
    EXPECT_EQ(hashes(s, fx, 2, 60, &collisions, &host), one);
    EXPECT_GT(host.runs.load(), 0) << "the host's task system was not used";
}

// With pairs and depth both on, depth takes its contact from the pairs effect's `all` query
// (the same query) instead of running it again: the same contacts and states, and the work of
// depth alone but its probe for a deep pair. A deep overlap is an exception to the work: depth
// alone stops listing its pairs at the first deep one, while the pairs effect lists them all.
TEST(Simulation, DepthWithPairsOnTakesItsContactFromThePairsQuery) {
    const spt::test::SceneDir dir;
    const Scene s = scene(dir, ball_cloud(27, 3));
    Simulation with(s, parse_effect_list("motion,gravity,contacts,depth,pairs,response", "test"));
    Simulation without(s, parse_effect_list("motion,gravity,contacts,depth,response", "test"));
    uint64_t contacts = 0;
    for (int step = 0; step < 40; ++step) {
        const StepResult& a = with.step();
        const StepResult& b = without.step();
        ASSERT_EQ(a.contacts.size(), b.contacts.size()) << "step " << step;
        bool deep = false;
        for (size_t k = 0; k < a.contacts.size(); ++k) {
            EXPECT_EQ(a.contacts[k].deep, b.contacts[k].deep) << "step " << step;
            deep |= b.contacts[k].deep;
            EXPECT_EQ(a.contacts[k].depth, b.contacts[k].depth) << "step " << step;
            EXPECT_EQ(a.contacts[k].point, b.contacts[k].point) << "step " << step;
            EXPECT_EQ(a.contacts[k].normal, b.contacts[k].normal) << "step " << step;
            EXPECT_FALSE(a.contacts[k].pairs.empty());
        }
        if (!deep) { // depth alone first probes for a deep pair: one descent a contact (docs/scenes.md)
            EXPECT_GE(b.counters.node_pairs, a.counters.node_pairs) << "step " << step;
            EXPECT_LE(b.counters.node_pairs, a.counters.node_pairs + 64 * b.contacts.size()) << "step " << step;
        }
        EXPECT_EQ(a.counters.depth_queries, b.counters.depth_queries) << "step " << step;
        EXPECT_EQ(a.state_hash, b.state_hash) << "step " << step;
        contacts += a.contacts.size();
    }
    EXPECT_GT(contacts, 20u);
}

TEST(Simulation, StateHashIsFnv1aOverThePoseDoubles) {
    std::vector<Pose> poses(2);
    poses[1].translation = {1, 2, 3};
    uint64_t h = 0xcbf29ce484222325ull;
    for (const Pose& p : poses) {
        const double v[7] = {p.translation.x(), p.translation.y(), p.translation.z(), p.rotation.w(),
                             p.rotation.x(), p.rotation.y(), p.rotation.z()};
        const auto* bytes = reinterpret_cast<const unsigned char*>(v);
        for (size_t i = 0; i < sizeof v; ++i) h = (h ^ bytes[i]) * 0x100000001b3ull;
    }
    EXPECT_EQ(state_hash(poses), h);
}

TEST(Simulation, ColliedPairsAreThoseTheQueryFindsAtTheSamePoses) {
    const spt::test::SceneDir dir;
    const Scene s = scene(dir, ball_cloud(27, 5));
    Simulation sim(s, parse_effect_list("motion,gravity,contacts,depth", "test"));
    QueryScratch scratch;
    size_t seen = 0;
    for (int step = 0; step < 40; ++step) {
        const StepResult& r = sim.step();
        size_t k = 0;
        for (uint32_t a = 0; a < s.objects.size(); ++a)
            for (uint32_t b = a + 1; b < s.objects.size(); ++b) {
                QueryOptions q;
                q.mode = QueryMode::Deepest;
                const QueryResult res =
                    collide(*s.objects[a].model, sim.poses()[a], *s.objects[b].model, sim.poses()[b], q, scratch);
                const bool listed = k < r.contacts.size() && r.contacts[k].a == a && r.contacts[k].b == b;
                ASSERT_EQ(res.collide, listed) << "step " << step << " pair " << a << "," << b;
                if (listed) {
                    EXPECT_EQ(r.contacts[k++].depth, res.deepest.depth);
                    ++seen;
                }
            }
    }
    EXPECT_GT(seen, 10u);
}

TEST(Simulation, BacktrackResponseLeavesNoPairDeeperThanItsTolerance) {
    const spt::test::SceneDir dir;
    // Two balls given motion towards each other at an angle (the paper's Fig. 8 in miniature).
    const Scene s = scene(dir, R"({"spt_scene": 1, "objects": [
        {"name": "a", "model": "ball.obj", "position": [-1, 0, 0], "velocity": [20, 3, 0]},
        {"name": "b", "model": "box.obj", "position": [1, 0.3, 0], "velocity": [-20, 0, 1], "angular_velocity": [0, 0, 3]}]})");
    Simulation sim(s, parse_effect_list("motion,contacts,depth,response", "test"));
    QueryScratch scratch;
    uint64_t responses = 0;
    for (int step = 0; step < 30; ++step) {
        responses += sim.step().counters.responses;
        QueryOptions q;
        q.mode = QueryMode::Deepest;
        const QueryResult res = collide(*s.objects[0].model, sim.poses()[0], *s.objects[1].model, sim.poses()[1], q, scratch);
        // backtrack rounds up by 1e-6 of the pair's reach: nothing may be deeper than that.
        const double tolerance = 1e-6 * (s.objects[0].model->reach() + s.objects[1].model->reach());
        EXPECT_TRUE(!res.collide || res.deepest.depth <= tolerance) << step << ": " << res.deepest.depth;
    }
    EXPECT_GT(responses, 0u);
}

// The response runs pairs sharing no dynamic object in parallel and reuses depth's sphere pairs;
// the outcome must be that of the documented rule: pairs one after the other in (a, b) order,
// each seeing the moves of those before it, each backtracked by core `backtrack` from scratch.
TEST(Simulation, ResponseEqualsPairsOneAfterTheOtherInPairOrderOnEveryThreadCount) {
    const spt::test::SceneDir dir;
    const Scene s = scene(dir, ball_cloud(27, 7));
    for (int threads : {1, 2, 4}) {
        Simulation sim(s, parse_effect_list("motion,gravity,contacts,depth,response", "test"), threads);
        QueryScratch scratch;
        size_t shared = 0; // contacts whose dynamic object an earlier contact of the step also has
        size_t carried = 0; // contacts that left along the normal: overlapping where the step began
        for (int step = 0; step < 60; ++step) {
            const std::vector<Pose> before = sim.poses();
            std::vector<Eigen::Vector3d> v = sim.velocities();
            const StepResult& r = sim.step();
            std::vector<Pose> p = sim.ghost_poses();
            std::vector<int> seen(p.size(), 0);
            for (size_t i = 0; i < v.size(); ++i)
                if (s.objects[i].motion == MotionKind::Velocity) v[i] += s.gravity * s.dt;
            for (const PairContact& c : r.contacts) {
                const bool da = s.objects[c.a].motion == MotionKind::Velocity;
                const bool db = s.objects[c.b].motion == MotionKind::Velocity;
                if (!da && !db) continue;
                shared += (da && seen[c.a]++) || (db && seen[c.b]++);
                const double wa = da ? (db ? 0.5 : 1.0) : 0.0, wb = db ? (da ? 0.5 : 1.0) : 0.0;
                Eigen::Vector3d motion = (p[c.b].translation - before[c.b].translation) -
                                         (p[c.a].translation - before[c.a].translation);
                const CollisionModel &ma = *s.objects[c.a].model, &mb = *s.objects[c.b].model;
                const double size = ma.extent() + mb.extent();
                const bool still = !(motion.norm() > 1e-12 * size);
                if (still) motion = -c.normal;
                double d = backtrack(ma, p[c.a], mb, p[c.b], motion, {}, BacktrackRule::Exact, scratch).distance;
                if (!still && d > motion.norm() + 1e-4 * size) { // overlapping where the step began
                    motion = -c.normal;
                    d = backtrack(ma, p[c.a], mb, p[c.b], motion, {}, BacktrackRule::Exact, scratch).distance;
                    ++carried;
                }
                if (d > 0) {
                    const Eigen::Vector3d away = motion.normalized() * d;
                    p[c.b].translation -= wb * away;
                    p[c.a].translation += wa * away;
                }
                const Eigen::Vector3d va = da ? v[c.a] : Eigen::Vector3d::Zero(), vb = db ? v[c.b] : Eigen::Vector3d::Zero();
                const double vn = (vb - va).dot(c.normal);
                if (vn < 0) {
                    const Eigen::Vector3d impulse = -(1 + s.response.restitution) * vn * c.normal;
                    if (db) v[c.b] += wb * impulse;
                    if (da) v[c.a] -= wa * impulse;
                }
            }
            for (size_t i = 0; i < p.size(); ++i) {
                ASSERT_EQ(sim.poses()[i].translation, p[i].translation) << "threads " << threads << " step " << step << " object " << i;
                ASSERT_EQ(sim.velocities()[i], v[i]) << "threads " << threads << " step " << step << " object " << i;
            }
        }
        EXPECT_GT(shared, 10u) << "the cloud should give pairs that wait for earlier ones";
        EXPECT_GT(carried, 0u) << "the cloud should give pairs pushed into each other by earlier ones";
    }
}

// A ball sunk into a static floor (as a later pair's response can leave it) and moving
// up, or sideways, slower than it is sunk: undoing its motion does not part them, and moving it
// back along its motion until they part would take it out of the floor's underside or far side.
// It leaves upwards, along the contact normal, whichever way it was moving.
TEST(Simulation, AnObjectAlreadySunkIntoAFloorLeavesAlongTheNormalNotThroughTheFloor) {
    const spt::test::SceneDir dir;
    for (const char* velocity : {"[0, 1, 0]", "[1, 0, 0]", "[0.7, 0.2, -0.7]", "[0, -1, 0]"}) {
        SCOPED_TRACE(velocity);
        // box.obj scaled to a 4-unit cube, its top at y = 0; the ball's radius is 0.5 and its
        // centre 0.2 above that top: 0.3 deep. A step moves it 0.01.
        const Scene s = scene(dir, std::string(R"({"spt_scene": 1, "objects": [
            {"name": "floor", "model": "box.obj", "static": true, "position": [0, -2, 0], "scale": 4},
            {"name": "ball", "model": "ball.obj", "position": [0, 0.2, 0], "velocity": )") + velocity + "}]}");
        Simulation sim(s, parse_effect_list("motion,contacts,depth,response", "test"));
        const StepResult& r = sim.step();
        ASSERT_EQ(r.contacts.size(), 1u);
        EXPECT_GT(r.contacts[0].normal.y(), 0.9); // the floor's top faces the ball
        const Eigen::Vector3d& c = sim.poses()[1].translation;
        // Out on top: the ball's lowest point (its mesh's radius, a little less at the facets)
        // at or above the top, having moved up from where the step left it (the normal, a
        // weighted sum of the floor's sphere normals near the contact, leans by a degree or so).
        EXPECT_GT(c.y(), 0.45);
        EXPECT_LT(c.y(), 0.55);
        const Eigen::Vector3d moved = c - sim.ghost_poses()[1].translation;
        EXPECT_LT(std::hypot(moved.x(), moved.z()), 0.05 * moved.y());
    }
}

// A small fast ball falls onto a thin plate; between two steps it moves 1 unit, 50 plate thicknesses.
const char* kThinWall = R"({"spt_scene": 1, "dt": 0.01, "objects": [
    {"name": "wall", "model": "plate.obj", "static": true},
    {"name": "bullet", "model": "ball.obj", "scale": 0.1, "position": [0.3, 0.7, 0.2], "velocity": [0, -100, 0]}]})";

TEST(Simulation, FastObjectPassesAThinWallWithoutCcdAndStopsAtItWithCcd) {
    const spt::test::SceneDir dir;
    const Scene s = scene(dir, kThinWall);
    Simulation without(s, parse_effect_list("motion,contacts", "test"));
    Simulation with(s, parse_effect_list("motion,contacts,ccd", "test"));
    uint64_t seen_without = 0, seen_with = 0;
    for (int i = 0; i < 10; ++i) {
        seen_without += without.step().counters.colliding_pairs;
        seen_with += with.step().counters.colliding_pairs;
    }
    EXPECT_EQ(seen_without, 0u);
    EXPECT_LT(without.poses()[1].translation.y(), -5.0);
    EXPECT_GT(seen_with, 0u);
    // Resting on the plate: the ball's bottom (radius 0.05) at the plate's top (0.01), within the ccd tolerance.
    EXPECT_GT(with.poses()[1].translation.y(), 0.05);
    EXPECT_LT(with.poses()[1].translation.y(), 0.07);
}

TEST(Simulation, ExactNeedsMeshes) {
    const spt::test::SceneDir dir;
    Scene s = scene(dir, kTwoBalls);
    s.objects[0].model = std::make_shared<CollisionModel>(make_document(import_mesh(dir.file("ball.obj")).mesh));
    EXPECT_THROW(Simulation(s, parse_effect_list("contacts,exact", "test")), Error);
}

} // namespace
