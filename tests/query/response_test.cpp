// Backtrack: exact for the sphere model, the paper's rule, the exact level by bisection.
#include "query_fixtures.hpp"
#include "spt/response.hpp"
#include <gtest/gtest.h>

namespace spt {
namespace {

const test::Object& torus() {
    static auto o = test::make_object(make_torus(1.0, 0.35, 20, 10));
    return *o;
}

Pose moved(const Pose& p, const Eigen::Vector3d& by) { return Pose::from(p.translation + by, p.rotation); }

TEST(Backtrack, AfterBacktrackNoCollisionAndOnePercentLessStillCollides) {
    std::mt19937 rng(17);
    QueryScratch s;
    int checked[3] = {0, 0, 0};
    for (int it = 0; it < 80; ++it) {
        const Pose p = test::random_pose(rng, 0.8 + 0.02 * it);
        const Eigen::Vector3d d = test::random_unit(rng) * 0.3;
        for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact}) {
            QueryOptions o;
            o.level = level;
            if (!collide_relative(torus().model, torus().model, p, o, s).collide) continue;
            const BacktrackResult r = backtrack_relative(torus().model, torus().model, p, d, o, BacktrackRule::Exact, s);
            ASSERT_TRUE(r.converged);
            ASSERT_GT(r.distance, 0);
            const Eigen::Vector3d back = -d.normalized();
            EXPECT_FALSE(collide_relative(torus().model, torus().model, moved(p, r.distance * back), o, s).collide)
                << "level " << int(level) << " pose " << it;
            if (r.distance > 1e-3) {
                EXPECT_TRUE(collide_relative(torus().model, torus().model, moved(p, 0.99 * r.distance * back), o, s).collide)
                    << "level " << int(level) << " pose " << it;
                ++checked[int(level)];
            }
        }
    }
    for (int c : checked) EXPECT_GT(c, 10);
}

TEST(Backtrack, ZeroMotionDirectionMovesNothing) {
    QueryScratch s;
    const BacktrackResult r =
        backtrack_relative(torus().model, torus().model, Pose{}, Eigen::Vector3d::Zero(), {}, BacktrackRule::Exact, s);
    EXPECT_EQ(r.distance, 0);
    EXPECT_EQ(r.queries, 0);
}

TEST(Backtrack, NoCollisionMeansZeroDistance) {
    QueryScratch s;
    const Pose far = Pose::from(Eigen::Vector3d(5, 0, 0), Eigen::Quaterniond::Identity());
    const BacktrackResult r = backtrack_relative(torus().model, torus().model, far, Eigen::Vector3d::UnitX(), {},
                                                 BacktrackRule::Exact, s);
    EXPECT_EQ(r.distance, 0);
}

TEST(Backtrack, PaperRuleIsTheDeepestPenetration) {
    std::mt19937 rng(2);
    QueryScratch s;
    for (int it = 0; it < 20; ++it) {
        const Pose p = test::random_pose(rng, 1.0 + 0.02 * it);
        QueryOptions o;
        o.mode = QueryMode::Deepest;
        const QueryResult q = collide_relative(torus().model, torus().model, p, o, s);
        const BacktrackResult r = backtrack_relative(torus().model, torus().model, p, Eigen::Vector3d::UnitZ(), o,
                                                     BacktrackRule::Paper, s);
        EXPECT_DOUBLE_EQ(r.distance, q.collide ? q.deepest.depth : 0.0);
    }
}

TEST(Backtrack, AlongTheContactNormalBothRulesAgreeForTwoSpheres) {
    // One sphere each: moving back along the line of centres by the depth separates them exactly.
    SptDocument a, b;
    for (auto* doc : {&a, &b}) {
        doc->samples.add(Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(1, 0, 0), 0, 1.0f);
        BuildOptions bo;
        bo.radius.fixed = 0.5f;
        doc->trees.push_back(build_tree("t", doc->samples, bo));
        doc->mesh.diagonal = 1;
    }
    const CollisionModel ma(a), mb(b);
    QueryScratch s;
    const Pose p = Pose::from(Eigen::Vector3d(-0.7, 0, 0), Eigen::Quaterniond::Identity()); // depth 0.3
    const Eigen::Vector3d motion(1, 0, 0); // B, on the -x side, moved towards A
    const double exact = backtrack_relative(ma, mb, p, motion, {}, BacktrackRule::Exact, s).distance;
    const double paper = backtrack_relative(ma, mb, p, motion, {}, BacktrackRule::Paper, s).distance;
    EXPECT_NEAR(exact, 0.3, 1e-5);
    EXPECT_NEAR(paper, 0.3, 1e-5);
    // Sideways motion: the paper's rule is wrong, the exact rule is not.
    const Pose side = Pose::from(Eigen::Vector3d(-0.7, 0, 0), Eigen::Quaterniond::Identity());
    const double sideways = backtrack_relative(ma, mb, side, Eigen::Vector3d(0, 1, 0), {}, BacktrackRule::Exact, s).distance;
    EXPECT_NEAR(sideways, std::sqrt(1.0 - 0.7 * 0.7), 1e-5); // |(-0.7, -s, 0)| = 1
}

} // namespace
} // namespace spt
