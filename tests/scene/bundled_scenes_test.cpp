// The bundled scenes (resources/scenes/) do what they are there to show.
#include "spt/scene.hpp"
#include "spt/simulation.hpp"
#include <cmath>
#include <gtest/gtest.h>

namespace {

using namespace spt;

Scene bundled(const std::string& name) { return load_scene(std::string(SPT_SOURCE_DIR) + "/resources/scenes/" + name); }

TEST(BundledScenes, BoxSettlesOnTheFloorWithoutDriftJitterOrExplosionFor10000Steps) {
    const Scene s = bundled("box_settle.json");
    ASSERT_EQ(s.steps, 10000);
    Simulation sim(s, s.effects);
    std::vector<Pose> poses;
    uint64_t colliding = 0;
    for (int i = 0; i < s.steps; ++i) {
        colliding += sim.step().counters.colliding_pairs;
        poses.push_back(sim.poses()[1]);
    }
    EXPECT_GT(colliding, 9000u); // resting on the floor, touching every step
    const Pose rest = poses.back();
    const double diagonal = s.objects[1].model->diagonal();
    // Rest: the unit box's bottom on the floor's top (y = 0), raised by how far the spheres poke out
    // (tolerance / 8: 0.025 for the floor, 0.004 for the box, as the generator samples them).
    EXPECT_GT(rest.translation.y(), 0.5);
    EXPECT_LT(rest.translation.y(), 0.5 + 0.025 + 0.004);
    EXPECT_NEAR(rest.translation.x(), 0.1, 1e-12); // no sideways push from a flat contact
    EXPECT_NEAR(rest.translation.z(), -0.2, 1e-12);
    EXPECT_NEAR(rest.rotation.angularDistance(Eigen::Quaterniond::Identity()), 0, 1e-12);
    // From the first second on, every step within 0.1% of the diagonal of the rest pose.
    double worst = 0;
    for (size_t i = 100; i < poses.size(); ++i) worst = std::max(worst, (poses[i].translation - rest.translation).norm());
    EXPECT_LE(worst, 1e-3 * diagonal);
}

TEST(BundledScenes, ThinWallStopsTheFastBallWithCcdAndNotWithout) {
    const Scene s = bundled("thin_wall.json");
    Simulation with(s, s.effects);
    Simulation without(s, parse_effect_list("motion,contacts", "test"));
    for (int i = 0; i < s.steps; ++i) with.step(), without.step();
    const double wall_face = -0.01, ball_radius = 0.05;
    EXPECT_LT(with.poses()[1].translation.x(), wall_face - ball_radius + 1e-3);
    EXPECT_GT(with.poses()[1].translation.x(), wall_face - ball_radius - 0.01);
    EXPECT_GT(without.poses()[1].translation.x(), 10.0); // passed through between two steps
}

TEST(BundledScenes, Fig8ObjectsCollideAndAreMovedBack) {
    const Scene s = bundled("fig8.json");
    Simulation sim(s, s.effects);
    QueryScratch scratch;
    uint64_t responses = 0;
    for (int i = 0; i < s.steps; ++i) {
        responses += sim.step().counters.responses;
        QueryOptions q;
        q.mode = QueryMode::Deepest;
        const QueryResult r = collide(*s.objects[0].model, sim.poses()[0], *s.objects[1].model, sim.poses()[1], q, scratch);
        const double tolerance = 1e-6 * (s.objects[0].model->reach() + s.objects[1].model->reach());
        EXPECT_TRUE(!r.collide || r.deepest.depth <= tolerance) << "step " << i + 1;
    }
    EXPECT_GT(responses, 0u);
}

// The skinned figure walks: the deepest contact moves from one foot to the other (x < 0 and
// x > 0, the figure facing +z), where a rigid figure would stand on both feet alike.
TEST(BundledScenes, WalkingFeetStrikeTheFloorAndOnlyTheFeet) {
    const Scene s = bundled("walking.json");
    EXPECT_EQ(s.objects[1].tree, "walk");
    EXPECT_TRUE(s.objects[1].animated);
    ASSERT_TRUE(s.effects.has(Effect::Deform));
    Simulation sim(s, s.effects);
    int strikes = 0, left = 0, right = 0;
    for (int i = 0; i < s.steps; ++i) {
        const StepResult& r = sim.step();
        for (const PairContact& c : r.contacts) {
            ++strikes;
            EXPECT_LT(c.point.y(), 0.05) << "step " << r.step; // at the floor: the soles, nothing higher
            EXPECT_FALSE(c.pairs.empty());
            (c.point.x() < 0 ? left : right) += 1;
        }
    }
    EXPECT_GT(strikes, 20);
    EXPECT_GT(left, 20);
    EXPECT_GT(right, 20);
}

// The arm reaches into the bin four times: its gripper meets the bin's floor at each reach (tips 1 cm
// in), and nothing of the arm above the gripper meets anything.
TEST(BundledScenes, RobotArmReachesIntoTheBinFourTimesWithItsGripperOnly) {
    const Scene s = bundled("robot_arm.json");
    ASSERT_EQ(s.objects.size(), 6u);
    ASSERT_EQ(s.objects[5].name, "arm");
    Simulation sim(s, s.effects);
    int reaches = 0;
    bool touching = false;
    for (int i = 0; i < s.steps; ++i) {
        const StepResult& r = sim.step();
        bool floor = false;
        for (const PairContact& c : r.contacts) {
            EXPECT_EQ(c.b, 5u) << "only the arm moves";
            floor = floor || c.a == 0;
        }
        // The gripper's lowest point: the arm's frame puts it 0.3 below the origin.
        if (!r.contacts.empty()) {
            QueryScratch scratch;
            QueryOptions deepest;
            deepest.mode = QueryMode::Deepest;
            for (const PairContact& c : r.contacts) {
                const QueryResult q = collide(*s.objects[5].model, sim.poses()[5], *s.objects[c.a].model,
                                              sim.poses()[c.a], deepest, scratch);
                ASSERT_TRUE(q.collide);
                const Eigen::Vector3d in_arm = sim.poses()[5].inverse().apply(q.deepest.point);
                EXPECT_LT(in_arm.y(), -0.1) << "step " << r.step << ": the gripper, not the arm above it";
            }
        }
        if (floor && !touching) ++reaches;
        touching = floor;
    }
    EXPECT_EQ(reaches, 4);
}

TEST(BundledScenes, PileHasAThousandMovingObjectsAndItsBroadPhaseIsExact) {
    const Scene s = bundled("pile.json");
    ASSERT_EQ(s.objects.size(), 1001u);
    Simulation sim(s, s.effects);
    for (int i = 0; i < 3; ++i) {
        const StepResult& r = sim.step();
        EXPECT_EQ(r.counters.candidate_pairs, all_overlapping_pairs(sim.broad_spheres()).size());
        EXPECT_GT(r.counters.candidate_pairs, 500u); // the lattice's neighbours and the floor
    }
}

// The pebbles heap up on the floor; none sinks into it. Before pairs already overlapping where a
// step began left along the contact normal, a pebble pressed into the floor by another's
// response and then rising was moved back along its motion, down through the floor: by step 100
// many were under it or had their centres inside it.
TEST(BundledScenes, PileStaysOnItsFloor) {
    const Scene s = bundled("pile.json");
    // floor.obj is 8 x 0.5 x 8 about its centre, scaled 2 and centred at y = -0.5: its top at
    // y = 0 and its sides at x, z = +-8.
    ASSERT_EQ(s.objects[0].name, "floor");
    const double top = 0.0, side = 8.0;
    Simulation sim(s, s.effects, 2);
    for (int i = 0; i < 100; ++i) sim.step();
    int over_the_floor = 0;
    for (size_t i = 1; i < s.objects.size(); ++i) {
        const Eigen::Vector3d& c = sim.poses()[i].translation;
        if (std::abs(c.x()) > side || std::abs(c.z()) > side) continue; // slid off its edge
        ++over_the_floor;
        EXPECT_GT(c.y(), top) << s.objects[i].name; // a pebble's centre above the top
    }
    EXPECT_GT(over_the_floor, 900);
}

} // namespace
