// The bundled dynamics scenes (resources/scenes/) meet the targets: a ball bounces as high
// as its restitution says, friction holds a box on a slope or lets it slide at g (sin - mu cos),
// a stack stands, balls stay in their box, energy never rises, and any thread count gives the
// same states.
#include "spt/scene.hpp"
#include "spt/simulation.hpp"
#include <cmath>
#include <gtest/gtest.h>

namespace {

using namespace spt;

Scene bundled(const std::string& name) { return load_scene(std::string(SPT_SOURCE_DIR) + "/resources/scenes/" + name); }

TEST(DynamicsScenes, ABallDroppedOnAFloorReboundsToTheSquareOfItsRestitutionTimesTheDrop) {
    const Scene s = bundled("bounce.json");
    const double e = s.dynamics.restitution, radius = 0.5;
    const double drop = s.objects[1].pose.translation.y() - radius; // the floor's top is y = 0
    Simulation sim(s, s.effects);
    bool bounced = false;
    double apex = 0;
    for (int i = 0; i < s.steps; ++i) {
        sim.step();
        const double vy = sim.velocities()[1].y(), height = sim.poses()[1].translation.y() - radius;
        if (!bounced && vy > 0) bounced = true;
        if (bounced && vy > 0) apex = std::max(apex, height);
        if (bounced && vy < 0 && apex > 0) break; // past the first apex
    }
    ASSERT_TRUE(bounced);
    EXPECT_NEAR(apex, e * e * drop, 0.1 * e * e * drop);
}

TEST(DynamicsScenes, FrictionHoldsABoxOnASlopeOrLetsItSlideAtGTimesSinMinusMuCos) {
    const Scene s = bundled("slope.json");
    ASSERT_EQ(s.objects[1].name, "holds");
    ASSERT_EQ(s.objects[2].name, "slides");
    const double theta = 20 * M_PI / 180, size = 0.5;
    const Eigen::Vector3d down_slope(-std::cos(theta), -std::sin(theta), 0);
    Simulation sim(s, s.effects);
    const Pose held0 = sim.poses()[1];
    double v_half = 0;
    for (int i = 0; i < 200; ++i) { // 2 s
        sim.step();
        if (i + 1 == 50) v_half = sim.velocities()[2].dot(down_slope);
    }
    EXPECT_LT((sim.poses()[1].translation - held0.translation).norm(), 0.01 * size);
    const double mu = s.objects[2].friction, a = (sim.velocities()[2].dot(down_slope) - v_half) / 1.5;
    const double expected = 9.81 * (std::sin(theta) - mu * std::cos(theta));
    EXPECT_NEAR(a, expected, 0.1 * expected);
}

TEST(DynamicsScenes, AStackOfFiveBoxesStandsFor5Seconds) {
    const Scene s = bundled("stack.json");
    ASSERT_EQ(s.objects.size(), 6u);
    Simulation sim(s, s.effects);
    const Pose top0 = sim.poses()[5];
    for (int i = 0; i < 500; ++i) sim.step();
    EXPECT_LT((sim.poses()[5].translation - top0.translation).norm(), 0.02 * 1.0); // 2% of the unit box
    EXPECT_LT(sim.poses()[5].rotation.angularDistance(top0.rotation), 0.02);
}

TEST(DynamicsScenes, ThreeHundredBallsDroppedIntoABoxStayInItAndEnergyNeverRises) {
    const Scene s = bundled("balls_in_box.json");
    Simulation sim(s, s.effects);
    double energy = sim.mechanical_energy();
    double worst_rise = 0;
    for (int i = 0; i < 300; ++i) { // 3 s
        sim.step();
        const double now = sim.mechanical_energy();
        worst_rise = std::max(worst_rise, (now - energy) / std::abs(energy));
        energy = now;
    }
    EXPECT_LE(worst_rise, 0.01);
    const double inside = 1.5, radius = 0.1;
    size_t balls = 0;
    for (size_t i = 0; i < s.objects.size(); ++i) {
        if (s.objects[i].name.rfind("ball", 0) != 0) continue;
        ++balls;
        const Eigen::Vector3d p = sim.poses()[i].translation;
        EXPECT_LT(std::abs(p.x()), inside - radius + 0.01) << s.objects[i].name;
        EXPECT_LT(std::abs(p.z()), inside - radius + 0.01) << s.objects[i].name;
        EXPECT_GT(p.y(), radius - 0.01) << s.objects[i].name; // above the floor's top (y = 0)
    }
    EXPECT_EQ(balls, 300u);
}

TEST(DynamicsScenes, WithRestitution0EnergyNeverRisesByMoreThanAPercentAStep) {
    for (const char* name : {"stack.json", "slope.json"}) {
        const Scene s = bundled(name);
        ASSERT_EQ(s.dynamics.restitution, 0);
        Simulation sim(s, s.effects);
        double energy = sim.mechanical_energy();
        for (int i = 0; i < s.steps; ++i) {
            sim.step();
            const double now = sim.mechanical_energy();
            ASSERT_LE(now - energy, 0.01 * std::abs(energy)) << name << " step " << i + 1;
            energy = now;
        }
    }
}

TEST(DynamicsScenes, TheSameStatesForAnyThreadCountAndRun) {
    const Scene s = bundled("balls_in_box.json");
    std::vector<uint64_t> reference;
    for (int threads : {1, 2, 3, 1}) {
        Simulation sim(s, s.effects, threads);
        std::vector<uint64_t> hashes;
        for (int i = 0; i < 80; ++i) hashes.push_back(sim.step().state_hash);
        if (reference.empty()) reference = hashes;
        EXPECT_EQ(hashes, reference) << threads << " threads";
    }
}

TEST(DynamicsScenes, ThePileHeapsOnItsFloorAndStaysThere) {
    const Scene s = bundled("pile_dynamics.json");
    ASSERT_EQ(s.objects.size(), 1001u);
    Simulation sim(s, s.effects, 2);
    for (int i = 0; i < 400; ++i) sim.step(); // 4 s: fallen, heaped and come to rest
    const double half_floor = 12;
    std::vector<double> speeds;
    for (size_t i = 1; i < s.objects.size(); ++i) {
        const Eigen::Vector3d p = sim.poses()[i].translation;
        EXPECT_GT(p.y(), 0.0) << s.objects[i].name; // on the floor's top or on others
        EXPECT_LT(std::max(std::abs(p.x()), std::abs(p.z())), half_floor) << s.objects[i].name;
        speeds.push_back(sim.velocities()[i].norm());
    }
    std::nth_element(speeds.begin(), speeds.begin() + 500, speeds.end());
    EXPECT_LT(speeds[500], 0.1); // the heap is at rest, its median pebble slower than 0.1 units/s
}

} // namespace
