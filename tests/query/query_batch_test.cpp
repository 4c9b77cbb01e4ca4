// query_batch: one call for many poses of a pair, the same answers as one query at a time, in
// pose order, on any number of threads and on a host's task system.
#include "host_task_system.hpp"
#include "query_fixtures.hpp"
#include "spt/error.hpp"
#include "spt/query_batch.hpp"
#include <gtest/gtest.h>
#include <random>

using namespace spt;
using namespace spt::test;

namespace {

// 1,000 poses of the torus against itself: B's centre within 2.5 of A's, any rotation.
std::vector<Pose> batch_poses() {
    std::mt19937 rng(41);
    std::uniform_real_distribution<double> u(-2.5, 2.5);
    std::vector<Pose> poses;
    for (int i = 0; i < 1000; ++i) poses.push_back(Pose::from(Eigen::Vector3d(u(rng), u(rng), u(rng)), random_rotation(rng)));
    return poses;
}

} // namespace

TEST(QueryBatch, GivesEachPoseTheAnswerOfItsOwnQueryOnAnyThreadCount) {
    const Object& t = torus();
    const std::vector<Pose> poses = batch_poses();
    for (QueryMode mode : {QueryMode::Any, QueryMode::All, QueryMode::Deepest}) {
        QueryOptions q;
        q.mode = mode;
        QueryScratch scratch;
        std::vector<QueryResult> one;
        for (const Pose& p : poses) one.push_back(collide_relative(t.model, t.model, p, q, scratch));
        size_t collide = 0;
        for (int threads : {1, 2, 3, 7}) {
            BatchOptions o;
            o.threads = threads;
            const std::vector<QueryResult> batch = query_batch(t.model, t.model, poses, q, o);
            ASSERT_EQ(batch.size(), poses.size());
            for (size_t i = 0; i < poses.size(); ++i) {
                ASSERT_EQ(batch[i].collide, one[i].collide) << "pose " << i << ", " << threads << " threads";
                EXPECT_EQ(batch[i].counters.node_pairs, one[i].counters.node_pairs) << "pose " << i;
                EXPECT_EQ(batch[i].counters.sphere_tests, one[i].counters.sphere_tests) << "pose " << i;
                if (mode == QueryMode::Deepest && one[i].collide) {
                    EXPECT_EQ(batch[i].deepest.depth, one[i].deepest.depth);
                }
                collide += batch[i].collide;
            }
        }
        EXPECT_GT(collide, 400u) << "both answers occur";
        EXPECT_LT(collide, 4u * 990u);
    }
}

TEST(QueryBatch, RunsOnAHostsTaskSystemAndTimesEachPose) {
    const Object& t = torus();
    const std::vector<Pose> poses = batch_poses();
    HostTaskSystem host(3);
    BatchOptions o;
    o.threads = 3;
    o.tasks = &host;
    o.repeat = 3;
    std::vector<int64_t> ns;
    const std::vector<QueryResult> batch = query_batch(t.model, t.model, poses, QueryOptions{}, o, &ns);
    ASSERT_EQ(ns.size(), poses.size());
    for (int64_t v : ns) EXPECT_GE(v, 0);

    BatchOptions alone;
    alone.threads = 1;
    const std::vector<QueryResult> one = query_batch(t.model, t.model, poses, QueryOptions{}, alone);
    for (size_t i = 0; i < poses.size(); ++i) EXPECT_EQ(batch[i].collide, one[i].collide) << i;
}

TEST(QueryBatch, AnEmptyBatchIsEmptyAndBadOptionsAreRefused) {
    const Object& t = torus();
    EXPECT_TRUE(query_batch(t.model, t.model, {}, QueryOptions{}).empty());
    BatchOptions bad;
    bad.repeat = 0;
    EXPECT_THROW(query_batch(t.model, t.model, batch_poses(), QueryOptions{}, bad), Error);
    // The exact level without triangles: the query's own refusal, from the batch.
    SptDocument doc = t.doc;
    const CollisionModel spheres_only(doc);
    QueryOptions exact;
    exact.level = QueryLevel::Exact;
    EXPECT_THROW(query_batch(spheres_only, spheres_only, batch_poses(), exact), Error);
}

TEST(QueryBatch, DistancesComeInPoseOrderTheSameOnAnyThreadCount) {
    const Object& t = torus();
    const std::vector<Pose> poses = batch_poses();
    QueryScratch scratch;
    BatchOptions one, three;
    one.threads = 1;
    three.threads = 3;
    for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact}) {
        DistanceOptions d;
        d.level = level;
        const std::vector<DistanceResult> a = distance_batch(t.model, t.model, poses, d, one);
        const std::vector<DistanceResult> b = distance_batch(t.model, t.model, poses, d, three);
        ASSERT_EQ(a.size(), poses.size());
        ASSERT_EQ(b.size(), poses.size());
        for (size_t i = 0; i < poses.size(); i += 7) {
            const DistanceResult single = distance_relative(t.model, t.model, poses[i], d, scratch);
            EXPECT_EQ(a[i].distance, single.distance) << i;
            EXPECT_EQ(b[i].distance, single.distance) << i;
            EXPECT_EQ(b[i].point_a, single.point_a) << i;
            EXPECT_EQ(b[i].counters.node_pairs, single.counters.node_pairs) << i;
        }
    }
}
