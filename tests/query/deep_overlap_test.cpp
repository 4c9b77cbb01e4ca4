// Deep overlaps: two 480-triangle balls (default conversion, 16,562 samples each) crossing by up
// to half their radius. The deepest pair comes from branch and bound, the backtrack from looks
// that keep only the largest exit root, and neither lists every overlapping pair.
#include "spt/convert.hpp"
#include "spt/query.hpp"
#include "spt/response.hpp"
#include "meshgen.hpp"
#include "query/backtrack_from.hpp"
#include "query/query_run.hpp"
#include "query/scratch.hpp"
#include <gtest/gtest.h>
#include <random>
#include <sstream>

namespace {

using namespace spt;

const CollisionModel& ball() {
    static const TriangleMesh mesh = meshgen::prepare(meshgen::uv_sphere(0.5, 16, 16), "ball").mesh;
    static const SptDocument doc = make_document(mesh);
    static const CollisionModel model(doc);
    return model;
}

// B's centre `gap` along a tilted direction from A's (1: touching balls), turned a little.
Pose offset(double gap) {
    const Eigen::Vector3d dir = Eigen::Vector3d(1, 0.3, -0.2).normalized();
    return Pose::from(gap * dir, Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.2, 1, 0.5).normalized())));
}

// A random direction.
Eigen::Vector3d random_unit(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-1, 1);
    Eigen::Vector3d v;
    do v = Eigen::Vector3d(u(rng), u(rng), u(rng));
    while (!(v.norm() > 0.1));
    return v.normalized();
}

// B's centre along `dir` from A's, 0.5 to 0.97 apart (half a radius deep to a graze), turned at random.
Pose deep_pose(std::mt19937& rng, const Eigen::Vector3d& dir) {
    std::uniform_real_distribution<double> gap(0.5, 0.97), angle(-3, 3);
    const double g = gap(rng), a = angle(rng);
    return Pose::from(g * dir, Eigen::Quaterniond(Eigen::AngleAxisd(a, random_unit(rng))));
}

// The first of the deepest pairs of a complete `all` query, as depth picked it before.
SpherePair deepest_of_all(const Pose& p, QueryScratch& s) {
    QueryOptions all;
    all.mode = QueryMode::All;
    EXPECT_TRUE(collide_relative(ball(), ball(), p, all, s).collide);
    const std::vector<SpherePair>& pairs = s.pairs();
    EXPECT_FALSE(pairs.empty());
    SpherePair best = pairs[0];
    for (const SpherePair& q : pairs)
        if (q.depth > best.depth) best = q;
    return best;
}

TEST(DeepOverlap, DeepestPairOfAHalfRadiusOverlapIsTheFirstDeepestOfEveryPair) {
    QueryScratch s;
    for (double gap : {0.99, 0.9, 0.75, 0.6}) {
        const Pose p = offset(gap);
        const SpherePair best = deepest_of_all(p, s);
        QueryOptions q;
        q.mode = QueryMode::Deepest;
        const QueryResult r = collide_relative(ball(), ball(), p, q, s);
        ASSERT_TRUE(r.collide);
        EXPECT_EQ(r.deepest.depth, double(best.depth)) << "gap " << gap;
        EXPECT_EQ(r.deepest.a, best.a) << "gap " << gap;
        EXPECT_EQ(r.deepest.b, best.b) << "gap " << gap;
    }
}

TEST(DeepOverlap, AnAllowanceFindsADeepPairWithinItInFewerNodePairs) {
    // The deepest-bounded child first, then every pair that cannot beat the best by more than the
    // allowance skipped: never deeper than the deepest, never shallower by more than the allowance.
    QueryScratch s;
    QueryOptions q;
    q.mode = QueryMode::Deepest;
    for (double gap : {0.99, 0.9, 0.75, 0.6}) {
        const Pose p = offset(gap);
        const QueryResult exact = collide_relative(ball(), ball(), p, q, s);
        for (float slack : {0.001f, 0.01f}) {
            const QueryResult within = detail::deepest_within(ball(), ball(), p, q, slack, s);
            ASSERT_TRUE(within.collide);
            EXPECT_LE(within.deepest.depth, exact.deepest.depth) << "gap " << gap;
            EXPECT_GE(within.deepest.depth, exact.deepest.depth - slack) << "gap " << gap;
            EXPECT_LT(within.counters.node_pairs, exact.counters.node_pairs) << "gap " << gap;
        }
    }
}

TEST(DeepOverlap, AShallowContactListsEveryPairAndACrossingOneStopsAtItsFirstDeepPair) {
    QueryScratch s;
    QueryOptions all;
    all.mode = QueryMode::All;
    const Pose shallow = offset(0.99), deep = offset(0.75);
    const QueryResult full = collide_relative(ball(), ball(), shallow, all, s);
    const std::vector<SpherePair> pairs = s.pairs();
    bool is_deep = true;
    const QueryResult r = collide_all_unless_deep(ball(), Pose{}, ball(), shallow, all, s, is_deep);
    EXPECT_FALSE(is_deep);
    // The same walk after a probe that found no deep pair: one descent through both trees (15
    // levels each).
    EXPECT_GE(r.counters.node_pairs, full.counters.node_pairs);
    EXPECT_LE(r.counters.node_pairs, full.counters.node_pairs + 31);
    ASSERT_EQ(s.pairs().size(), pairs.size());
    for (size_t k = 0; k < pairs.size(); ++k) {
        EXPECT_EQ(s.pairs()[k].a, pairs[k].a);
        EXPECT_EQ(s.pairs()[k].b, pairs[k].b);
        EXPECT_EQ(s.pairs()[k].depth, pairs[k].depth);
    }
    const QueryResult every = collide_relative(ball(), ball(), deep, all, s);
    const size_t listed = s.pairs().size();
    const QueryResult cut = collide_all_unless_deep(ball(), Pose{}, ball(), deep, all, s, is_deep);
    EXPECT_TRUE(is_deep);
    EXPECT_TRUE(cut.collide);
    EXPECT_LT(s.pairs().size() * 20, listed) << "the crossing's pairs should not be listed";
    EXPECT_LT(cut.counters.node_pairs * 10, every.counters.node_pairs);
}

// The work of the deepest pair and of each backtrack look depends on the contact, not on how much
// the balls share: half a radius deep costs about what a graze costs (it was 33 times the node
// pairs of the graze for the `all` query depth ran).
TEST(DeepOverlap, HalfRadiusOverlapCostsAboutWhatAGrazeCosts) {
    QueryScratch s;
    auto work = [&](double gap) {
        QueryOptions q;
        q.mode = QueryMode::Deepest;
        const QueryResult d = collide_relative(ball(), ball(), offset(gap), q, s);
        QueryOptions spheres;
        detail::ExitSearch exit;
        exit.back = -Eigen::Vector3d(1, 0.3, -0.2).normalized();
        const QueryResult e = collide_exit(ball(), ball(), offset(gap), spheres, exit, s);
        return d.counters.node_pairs + e.counters.node_pairs;
    };
    const uint64_t graze = work(0.99), half = work(0.75);
    EXPECT_LT(half, 3 * graze) << "graze " << graze << ", half a radius " << half;
}

TEST(DeepOverlap, BacktrackFromItsOwnLooksEqualsTheOneFromEveryPairBitForBit) {
    QueryScratch s;
    QueryOptions all;
    all.mode = QueryMode::All;
    for (double gap : {0.9, 0.75, 0.6})
        for (const Eigen::Vector3d& motion : {Eigen::Vector3d(-1, -0.3, 0.2), Eigen::Vector3d(0.3, -1, 0.1)}) {
            const Pose p = offset(gap);
            collide_relative(ball(), ball(), p, all, s);
            const std::vector<SpherePair> pairs = s.pairs();
            const BacktrackResult from_pairs =
                detail::backtrack_from_pairs(ball(), Pose{}, ball(), p, motion, QueryOptions{}, pairs, s);
            const BacktrackResult own =
                backtrack(ball(), Pose{}, ball(), p, motion, QueryOptions{}, BacktrackRule::Exact, s);
            EXPECT_EQ(own.distance, from_pairs.distance) << "gap " << gap;
            EXPECT_TRUE(own.converged);
            Pose parted = p;
            parted.translation -= own.distance * motion.normalized();
            EXPECT_FALSE(collide_relative(ball(), ball(), parted, QueryOptions{}, s).collide) << "gap " << gap;
        }
}

// A deep overlap's backtrack by branch and bound over the last exit of every pair against the
// looks of rule Exact, on random deep poses and motions: two balls, once parted along a line, do
// not meet again further on it, so the two answers differ only by the looks' rounding up (a
// millionth of a reach a look; docs/queries.md, "Deep overlaps").
TEST(DeepOverlap, LastExitOfEveryPairIsWhereTheLooksPartOnRandomDeepPoses) {
    QueryScratch s;
    std::mt19937 rng(37);
    double reach = 0; // the largest of a pair
    for (const CompactNode& n : ball().tree().nodes())
        if (n.is_active()) reach = std::max(reach, 2.0 * n.ss_radius);
    double worst = 0;
    for (int k = 0; k < 40; ++k) {
        const Eigen::Vector3d dir = random_unit(rng);
        const Pose p = deep_pose(rng, dir);
        // Along the line of centres (as the normal parts a deep pair) and along any motion.
        for (const Eigen::Vector3d& motion : {Eigen::Vector3d(-dir), random_unit(rng)}) {
            const BacktrackResult looks =
                backtrack(ball(), Pose{}, ball(), p, motion, QueryOptions{}, BacktrackRule::Exact, s);
            const BacktrackResult bnb = detail::deep_backtrack(ball(), Pose{}, ball(), p, motion, QueryOptions{}, s);
            ASSERT_TRUE(looks.converged);
            EXPECT_LE(bnb.queries, looks.queries) << "pose " << k;
            EXPECT_TRUE(bnb.converged);
            EXPECT_NEAR(bnb.distance, looks.distance, 1e-5 * reach) << "pose " << k;
            worst = std::max(worst, std::abs(bnb.distance - looks.distance));
            Pose parted = p;
            parted.translation -= bnb.distance * motion.normalized();
            EXPECT_FALSE(collide_relative(ball(), ball(), parted, QueryOptions{}, s).collide) << "pose " << k;
        }
    }
    std::ostringstream text;
    text << worst << " of a reach of " << reach;
    RecordProperty("worst_difference", text.str());
}

// With an allowance the branch and bound skips pairs that cannot part later than its best by more,
// and answers without a look: never before the last exit (a query there finds the balls apart),
// at most the allowance (and the float margin) after it, from far fewer queries' worth of work.
TEST(DeepOverlap, AnAllowanceAnswersAtMostThatLateAndApartWithoutALook) {
    QueryScratch s;
    std::mt19937 rng(41);
    const double allowance = detail::deep_allowance(ball(), ball());
    ASSERT_GT(allowance, 0);
    const double margin = 1e-5 * 2 * ball().extent() + 1e-6;
    for (int k = 0; k < 30; ++k) {
        const Eigen::Vector3d dir = random_unit(rng);
        const Pose p = deep_pose(rng, dir);
        for (const Eigen::Vector3d& motion : {Eigen::Vector3d(-dir), random_unit(rng)}) {
            const BacktrackResult exact = detail::deep_backtrack(ball(), Pose{}, ball(), p, motion, QueryOptions{}, s);
            const BacktrackResult rough =
                detail::deep_backtrack(ball(), Pose{}, ball(), p, motion, QueryOptions{}, s, kNoBacktrackLimit, allowance);
            // From the deepest pair too, as a scene's response starts (any pair is a start).
            QueryOptions deepest;
            deepest.mode = QueryMode::Deepest;
            const QueryResult d = collide_relative(ball(), ball(), p, deepest, s);
            ASSERT_TRUE(d.collide);
            const SpherePair seed{d.deepest.a, d.deepest.b, detail::buffers_of(s).deepest_node_a,
                                  detail::buffers_of(s).deepest_node_b, float(d.deepest.depth), 0};
            const BacktrackResult seeded = detail::deep_backtrack(ball(), Pose{}, ball(), p, motion, QueryOptions{}, s,
                                                                  kNoBacktrackLimit, allowance, &seed);
            for (const BacktrackResult& r : {rough, seeded}) {
                EXPECT_TRUE(r.converged);
                EXPECT_EQ(r.queries, 1) << "pose " << k;
                EXPECT_GE(r.distance, exact.distance - 1e-6) << "pose " << k;
                EXPECT_LE(r.distance, exact.distance + allowance + margin) << "pose " << k;
                Pose parted = p;
                parted.translation -= r.distance * motion.normalized();
                EXPECT_FALSE(collide_relative(ball(), ball(), parted, QueryOptions{}, s).collide) << "pose " << k;
            }
        }
    }
}

// A limit below the distance ends both searches with `beyond` set; above it, no `beyond`.
TEST(DeepOverlap, LastExitOfEveryPairSaysBeyondWhereTheLooksDo) {
    QueryScratch s;
    const Pose p = offset(0.75);
    const Eigen::Vector3d motion(-1, -0.3, 0.2);
    const BacktrackResult full = detail::deep_backtrack(ball(), Pose{}, ball(), p, motion, QueryOptions{}, s);
    ASSERT_GT(full.distance, 0.1);
    for (const double limit : {0.1, full.distance + 1e-3}) {
        const BacktrackResult looks =
            backtrack(ball(), Pose{}, ball(), p, motion, QueryOptions{}, BacktrackRule::Exact, s, limit);
        const BacktrackResult bnb = detail::deep_backtrack(ball(), Pose{}, ball(), p, motion, QueryOptions{}, s, limit);
        EXPECT_EQ(bnb.beyond, looks.beyond) << "limit " << limit;
        EXPECT_EQ(bnb.beyond, limit < full.distance) << "limit " << limit;
        // With an allowance too, though its answer may lie past a limit that the distance does not.
        const BacktrackResult rough = detail::deep_backtrack(ball(), Pose{}, ball(), p, motion, QueryOptions{}, s, limit,
                                                             detail::deep_allowance(ball(), ball()));
        EXPECT_EQ(rough.beyond, limit < full.distance) << "limit " << limit;
    }
}

} // namespace
