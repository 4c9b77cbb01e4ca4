// A step of two 480-triangle balls (default conversion) crossing by half their radius: depth and
// response work of the order of a graze's, the answers of the deepest pair, and parted after.
#include "meshgen.hpp"
#include "spt/simulation.hpp"
#include "test_support.hpp"
#include "query/query_run.hpp"
#include <gtest/gtest.h>
#include <fstream>
#include <sstream>

namespace {

using namespace spt;

// Two balls of radius 0.5 whose centres are `gap` apart along a tilted line, moving together.
Scene two_balls(const test::TempDir& dir, double gap) {
    meshgen::write_obj(meshgen::uv_sphere(0.5, 16, 16), dir.file("ball.obj"));
    const Eigen::Vector3d c = gap * Eigen::Vector3d(1, 0.3, -0.2).normalized();
    std::ostringstream j;
    j.precision(17);
    j << R"({"spt_scene": 1, "dt": 0.01, "effects": ["motion", "contacts", "depth", "response"], "objects": [
        {"name": "a", "model": "ball.obj", "velocity": [1, 0.5, 0]},
        {"name": "b", "model": "ball.obj", "velocity": [1, 0.5, 0], "position": [)"
      << c.x() << ", " << c.y() << ", " << c.z() << "]}]}";
    std::ofstream(dir.file("s.json")) << j.str();
    return load_scene(dir.file("s.json"));
}

TEST(DeepOverlapScene, HalfRadiusOverlapStepCostsAboutWhatAGrazeCosts) {
    const test::TempDir dir("deep");
    auto work = [&](double gap, bool deep) {
        const Scene s = two_balls(dir, gap);
        Simulation sim(s, s.effects, 1);
        const StepResult& r = sim.step();
        EXPECT_EQ(r.counters.colliding_pairs, 1u);
        EXPECT_EQ(r.contacts.at(0).deep, deep) << "gap " << gap;
        return r.counters.node_pairs + r.counters.sphere_tests;
    };
    // Before deep overlaps took the deepest pair's route, depth listed every pair: 2,457,077 node
    // pairs and sphere tests at half a radius, 27 times the graze's 90,063 (now 55,378).
    const uint64_t graze = work(0.98, false), half = work(0.75, true);
    EXPECT_LT(half, 2 * graze) << "graze " << graze << ", half a radius " << half;
}

TEST(DeepOverlapScene, HalfRadiusOverlapGetsTheDeepestPairTheCentreLineAndParts) {
    const test::TempDir dir("deep");
    const Scene s = two_balls(dir, 0.75);
    Simulation sim(s, s.effects, 1);
    const StepResult& r = sim.step();
    ASSERT_EQ(r.contacts.size(), 1u);
    const PairContact& c = r.contacts[0];
    const Pose &pa = sim.ghost_poses()[0], &pb = sim.ghost_poses()[1];
    QueryScratch scratch;
    QueryOptions q;
    q.mode = QueryMode::Deepest;
    const QueryResult d = collide(*s.objects[0].model, pa, *s.objects[1].model, pb, q, scratch);
    // A deep pair within the allowance of the deepest, never deeper, its point inside both balls.
    const double allowance = detail::deep_allowance(*s.objects[0].model, *s.objects[1].model);
    EXPECT_GT(allowance, 0);
    EXPECT_LE(c.depth, d.deepest.depth);
    EXPECT_GE(c.depth, d.deepest.depth - allowance);
    EXPECT_LT((c.point - pa.translation).norm(), 0.5);
    EXPECT_LT((c.point - pb.translation).norm(), 0.5);
    // Two balls: the normal of the crossing is the line between their centres, within the
    // sampling's resolution.
    const Eigen::Vector3d line = (pb.translation - pa.translation).normalized();
    EXPECT_GT(c.normal.dot(line), 0.95) << c.normal.transpose();
    // Moved apart along the normal (no relative motion), the balls no longer collide.
    EXPECT_FALSE(collide(*s.objects[0].model, sim.poses()[0], *s.objects[1].model, sim.poses()[1], QueryOptions{},
                         scratch)
                     .collide);
}

} // namespace
