// Cost runs (spt/tree_cost.hpp): the poses they choose and the figures they report.
#include "query_fixtures.hpp"
#include "spt/query_scratch.hpp"
#include "spt/error.hpp"
#include "spt/tree_cost.hpp"
#include <gtest/gtest.h>

using namespace spt;
using namespace spt::test;

namespace {

// The torus with two trees: the automatic one first, then one leaf holding every sample (what
// an author starts from).
std::unique_ptr<Object> torus_with_flat_tree() {
    auto o = make_object(make_torus(1.0, 0.35, 24, 12));
    SamplingTree flat("flat", uint32_t(o->doc.samples.size()));
    flat.assign_radii(o->doc.samples, RadiusRule{});
    flat.compute_bounds(o->doc.samples, BoundsMethod::Tight);
    o->doc.trees.push_back(std::move(flat));
    return o;
}

} // namespace

TEST(TreeCost, NearContactPosesSitWithinOnePercentOfTheDiagonalOfAContact) {
    const auto o = make_object(make_torus(1.0, 0.35, 24, 12));
    CostOptions opt;
    opt.random_poses = 50, opt.near_poses = 60;
    const CostPoses p = cost_poses(o->model, o->model, opt);
    ASSERT_EQ(p.random.size(), 50u);
    ASSERT_EQ(p.near.size(), 60u);
    QueryScratch s;
    const double step = 0.011 * o->model.diagonal();
    int colliding = 0;
    for (const Pose& pose : p.near) {
        const bool here = collide_relative(o->model, o->model, pose, {}, s).collide;
        colliding += here;
        // Within 1% of the diagonal along its direction the answer changes.
        const Eigen::Vector3d u = pose.translation.normalized();
        bool flips = false;
        for (double d : {-step, step}) {
            Pose moved = pose;
            moved.translation += d * u;
            flips |= collide_relative(o->model, o->model, moved, {}, s).collide != here;
        }
        EXPECT_TRUE(flips) << "a near pose " << pose.translation.transpose() << " is not near a contact";
    }
    EXPECT_GT(colliding, 10);
    EXPECT_LT(colliding, 50);
}

TEST(TreeCost, SameSeedSamePosesAnotherSeedOthers) {
    const auto o = make_object(make_torus(1.0, 0.35, 12, 6));
    CostOptions opt;
    opt.random_poses = opt.near_poses = 10;
    const CostPoses a = cost_poses(o->model, o->model, opt), b = cost_poses(o->model, o->model, opt);
    for (size_t i = 0; i < a.near.size(); ++i) EXPECT_EQ(a.near[i].translation, b.near[i].translation);
    opt.seed = 2;
    const CostPoses c = cost_poses(o->model, o->model, opt);
    EXPECT_NE(a.random[0].translation, c.random[0].translation);
}

TEST(TreeCost, CountersAreThoseOfTheQueryAtEachPose) {
    const auto o = make_object(make_torus(1.0, 0.35, 24, 12));
    CostOptions opt;
    opt.random_poses = opt.near_poses = 20;
    opt.repeats = 1;
    const CostPoses p = cost_poses(o->model, o->model, opt);
    const TreeCost c = measure_cost(o->model, o->model, p, opt);
    ASSERT_EQ(c.near.counters.size(), 20u);
    QueryScratch s;
    double node_pairs = 0;
    for (size_t i = 0; i < p.near.size(); ++i) {
        const QueryResult r = collide_relative(o->model, o->model, p.near[i], {}, s);
        EXPECT_EQ(c.near.counters[i].node_pairs, r.counters.node_pairs);
        EXPECT_EQ(c.near.counters[i].sphere_tests, r.counters.sphere_tests);
        node_pairs += double(r.counters.node_pairs);
    }
    EXPECT_DOUBLE_EQ(c.near.mean_node_pairs, node_pairs / 20);
    EXPECT_GT(c.near.median_ns, 0);
    EXPECT_EQ(c.memory_bytes, o->model.memory_bytes());
    EXPECT_FALSE(c.cancelled);
}

TEST(TreeCost, OneLeafHoldingEverySampleCostsFarMoreSphereTestsThanTheAutomaticTree) {
    const auto o = torus_with_flat_tree();
    const CollisionModel automatic(o->doc, o->doc.trees[0].name()), flat(o->doc, "flat");
    CostOptions opt;
    opt.random_poses = opt.near_poses = 30;
    opt.repeats = 1;
    const CostPoses p = cost_poses(automatic, automatic, opt);
    const TreeCost ca = measure_cost(automatic, automatic, p, opt), cf = measure_cost(flat, flat, p, opt);
    // Same samples, same spheres: the same answers; only the hierarchy differs.
    EXPECT_DOUBLE_EQ(ca.near.collide_share, cf.near.collide_share);
    EXPECT_GT(cf.near.mean_sphere_tests, 5 * ca.near.mean_sphere_tests);
}

TEST(TreeCost, CancelStopsTheRunAndSaysSo) {
    const auto o = make_object(make_torus(1.0, 0.35, 12, 6));
    CostOptions opt;
    opt.random_poses = opt.near_poses = 50;
    const CostPoses p = cost_poses(o->model, o->model, opt);
    std::atomic<bool> cancel{false};
    int calls = 0;
    const TreeCost c = measure_cost(o->model, o->model, p, opt, &cancel, [&](double share) {
        ++calls;
        EXPECT_GT(share, 0);
        if (share >= 0.3) cancel = true;
    });
    EXPECT_TRUE(c.cancelled);
    EXPECT_LT(c.random.counters.size() + c.near.counters.size(), 100u);
    EXPECT_GT(calls, 0);
}

TEST(TreeCost, AbsurdPoseCountsAreRefused) {
    const auto o = make_object(make_torus(1.0, 0.35, 12, 6));
    CostOptions opt;
    opt.near_poses = -1;
    EXPECT_THROW(cost_poses(o->model, o->model, opt), Error);
}

// A seed's poses are the same from every build: each draw is its own statement (the order of
// a call's arguments, or of an operator's operands, is the compiler's to choose; GCC and clang
// choose differently). The first random and near poses of the default seed, as first made.
TEST(TreeCost, SameSeedGivesTheSamePosesFromEveryCompiler) {
    const auto o = make_object(make_torus(1.0, 0.35, 24, 12));
    CostOptions opt;
    opt.random_poses = 20, opt.near_poses = 1;
    const CostPoses p = cost_poses(o->model, o->model, opt);
    ASSERT_EQ(p.near.size(), 1u);
    auto wxyz = [](const Pose& pose) {
        const Eigen::Quaterniond& q = pose.rotation;
        return Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
    };
    EXPECT_EQ(p.random[0].translation, Eigen::Vector3d(-0x1.df4afc263569cp-4, -0x1.096326c85f8ep+1, -0x1.1cdde68a8c706p-2));
    EXPECT_EQ(wxyz(p.random[0]),
              Eigen::Vector4d(0x1.c350fb6254269p-3, -0x1.5689541fafaaep-1, -0x1.66a21f71812c2p-1, 0x1.d6e21a0a9b267p-4));
    EXPECT_EQ(p.near[0].translation, Eigen::Vector3d(0x1.9b89894b29049p+0, -0x1.2761d1d5e0f68p-3, -0x1.052be17ab303bp+0));
    EXPECT_EQ(wxyz(p.near[0]),
              Eigen::Vector4d(0x1.1ce9da6706112p-4, -0x1.0ba9232e30806p-1, -0x1.9e536553b53e8p-1, -0x1.0915d117b80afp-2));
}
