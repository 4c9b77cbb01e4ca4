// Backtrack: exact for the sphere model, the paper's rule, the exact level by bisection.
#include "query_fixtures.hpp"
#include "spt/response.hpp"
#include "query/query_run.hpp"
#include "query/backtrack_from.hpp"
#include <cmath>
#include <gtest/gtest.h>

namespace spt {
namespace {

using test::torus;

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

TEST(Backtrack, PrunedExitSearchFindsTheLargestRootOfEveryOverlappingPair) {
    // The backtrack's look at one shift walks the trees keeping only the largest exit root and
    // skipping node pairs that part sooner. Against every pair an `all` query records, the
    // roots computed one by one: the same root and reach, bit for bit, with fewer node pairs.
    static auto box = test::make_object(make_box({0.4, 0.25, 0.3}, 6));
    std::mt19937 rng(23);
    QueryScratch s;
    uint64_t walked_all = 0, walked_exit = 0;
    int compared = 0;
    for (int it = 0; it < 120; ++it) {
        const bool same = it % 2 == 0;
        const CollisionModel& a = torus().model;
        const CollisionModel& b = same ? torus().model : box->model;
        const Pose p = test::random_pose(rng, 0.1 + 0.01 * it);
        const Eigen::Vector3d back = test::random_unit(rng);
        for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres}) {
            QueryOptions o;
            o.level = level;
            o.mode = QueryMode::All;
            const QueryResult all = collide_relative(a, b, p, o, s);
            walked_all += all.counters.node_pairs;
            const bool bounds = level == QueryLevel::Bounds;
            auto centre = [&](const CompactTree& t, uint32_t node, uint32_t k) -> Eigen::Vector3d {
                const CompactNode& n = t.nodes()[bounds ? k : node];
                return bounds ? Eigen::Vector3f(n.center[0], n.center[1], n.center[2]).cast<double>()
                              : t.sphere_center(n, k).cast<double>();
            };
            const Eigen::Matrix3d rot = unit_rotation(p.rotation).toRotationMatrix();
            const Eigen::Vector3d t = local_translation(a, b, rot, p.translation);
            double root = -INFINITY, reach = 0;
            for (const SpherePair& q : s.pairs()) {
                const Eigen::Vector3d w = rot * centre(b.tree(), q.node_b, q.b) + t - centre(a.tree(), q.node_a, q.a);
                const double r = detail::exit_root(w, double(q.reach), back);
                if (r > root) root = r, reach = q.reach;
                else if (r == root) reach = std::max(reach, double(q.reach));
            }
            detail::ExitSearch exit;
            exit.back = back;
            const QueryResult e = collide_exit(a, b, p, o, exit, s);
            walked_exit += e.counters.node_pairs;
            EXPECT_EQ(e.collide, all.collide) << it;
            EXPECT_TRUE(s.pairs().empty());
            ASSERT_EQ(exit.found, root > -INFINITY) << it;
            if (!exit.found) continue;
            EXPECT_EQ(exit.root, root) << it << " level " << int(level);
            EXPECT_EQ(exit.reach, reach) << it << " level " << int(level);
            ++compared;
        }
    }
    EXPECT_GT(compared, 150);
    EXPECT_LT(walked_exit, walked_all / 2) << "the search prunes";
}

TEST(Backtrack, StartingFromTheDepthQuerysPairsGivesTheSameDistanceBitForBit) {
    // A scene's response starts the backtrack from the sphere pairs its depth query found at
    // the same poses, skipping pairs that part before the best root without solving them: the
    // distance must be the one the backtrack finds on its own, with one query fewer. Far from
    // the origin too, where the world poses' translations are large against the models.
    static auto box = test::make_object(make_box({0.4, 0.25, 0.3}, 6));
    std::mt19937 rng(41);
    QueryScratch s, t;
    int compared = 0;
    for (int it = 0; it < 160; ++it) {
        const bool same = it % 2 == 0;
        const CollisionModel& a = torus().model;
        const CollisionModel& b = same ? torus().model : box->model;
        const Eigen::Vector3d offset = (it % 4 < 2 ? 0.0 : 1e4) * test::random_unit(rng);
        const Pose pa = Pose::from(offset, test::random_rotation(rng));
        const Pose rel = test::random_pose(rng, 0.1 + 0.01 * it);
        const Pose pb = pa * rel;
        const Eigen::Vector3d motion = test::random_unit(rng) * 0.2;
        for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres}) {
            QueryOptions o;
            o.level = level;
            o.mode = QueryMode::All;
            if (!collide(a, pa, b, pb, o, s).collide || s.pairs().empty()) continue;
            const std::vector<SpherePair> pairs = s.pairs();
            o.mode = QueryMode::Any;
            const BacktrackResult alone = backtrack(a, pa, b, pb, motion, o, BacktrackRule::Exact, t);
            const BacktrackResult from = detail::backtrack_from_pairs(a, pa, b, pb, motion, o, pairs, t);
            ASSERT_TRUE(alone.converged && from.converged) << it;
            EXPECT_EQ(from.distance, alone.distance) << it << " level " << int(level);
            EXPECT_EQ(from.queries + 1, alone.queries) << it << " level " << int(level);
            ++compared;
        }
    }
    EXPECT_GT(compared, 150);
}

TEST(Backtrack, ALimitBelowTheDistanceStopsTheSearchAndOneAboveItChangesNothing) {
    // A scene's response asks only whether a pair must go back further than its own motion: the
    // search stops once it knows, and answers as before, bit for bit, when it is not further.
    std::mt19937 rng(23);
    QueryScratch s;
    int stopped_early = 0, compared = 0;
    for (int it = 0; it < 60; ++it) {
        const Pose p = test::random_pose(rng, 0.4 + 0.02 * it);
        const Eigen::Vector3d d = test::random_unit(rng) * 0.3;
        for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact}) {
            for (BacktrackRule rule : {BacktrackRule::Exact, BacktrackRule::Paper}) {
                QueryOptions o;
                o.level = level;
                const BacktrackResult full = backtrack_relative(torus().model, torus().model, p, d, o, rule, s);
                if (!(full.distance > 0)) continue;
                EXPECT_FALSE(full.beyond);
                for (double limit : {full.distance, std::nextafter(full.distance, INFINITY), 1.5 * full.distance}) {
                    const BacktrackResult r = backtrack_relative(torus().model, torus().model, p, d, o, rule, s, limit);
                    EXPECT_FALSE(r.beyond) << it << " level " << int(level) << " rule " << int(rule);
                    EXPECT_EQ(r.distance, full.distance) << it << " level " << int(level);
                    EXPECT_EQ(r.queries, full.queries) << it << " level " << int(level);
                    ++compared;
                }
                const BacktrackResult r = backtrack_relative(torus().model, torus().model, p, d, o, rule, s, 0.3 * full.distance);
                EXPECT_TRUE(r.beyond) << it;
                EXPECT_GT(r.distance, 0.3 * full.distance) << it;
                EXPECT_LE(r.queries, full.queries) << it;
                stopped_early += r.queries < full.queries;
            }
        }
    }
    EXPECT_GT(compared, 100);
    EXPECT_GT(stopped_early, 10);
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
