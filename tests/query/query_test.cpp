// Tree queries at every level and mode against the brute-force reference.
#include "query_fixtures.hpp"
#include "query/brute_force.hpp"
#include "spt/error.hpp"
#include "spt/query.hpp"
#include "mesh/hard_shapes.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <array>
#include <set>
#include <thread>

namespace spt {
namespace {

using test::make_object;
using test::random_pose;

using test::torus;
const test::Object& box() {
    static auto o = make_object(make_box({0.8, 0.5, 0.3}, 3));
    return *o;
}

// Sphere pairs with the active nodes that hold them (node = sphere at level bounds).
std::set<std::array<uint32_t, 4>> sphere_pairs(const QueryScratch& s) {
    std::set<std::array<uint32_t, 4>> out;
    for (const auto& p : s.pairs()) out.insert({p.a, p.b, p.node_a, p.node_b});
    return out;
}
std::set<std::pair<uint32_t, uint32_t>> tri_pairs(const QueryScratch& s) {
    std::set<std::pair<uint32_t, uint32_t>> out;
    for (const auto& p : s.triangle_pairs()) out.insert({p.a, p.b});
    return out;
}

QueryOptions opts(QueryLevel level, QueryMode mode) {
    QueryOptions o;
    o.level = level, o.mode = mode;
    return o;
}

// Leaves of several compact triangles (a torus) against needle leaves (a fan's blades, an
// open tube's strips), each object as A and as B: neither the needle-box prefilter of a leaf
// pair nor a compact node's ball tried against an elongated node's box drops a triangle pair.
TEST(Query, ExactLeavesOfCompactTrianglesAgainstNeedlesMatchBruteForce) {
    std::mt19937 rng(13);
    QueryScratch s1, s2;
    const auto fan = test::make_object(make_fan(6));
    const auto tube = test::make_object(make_open_tube(0.02, 1.5, 8));
    for (const bool torus_is_a : {true, false}) {
        int collisions = 0;
        for (const test::Object* needles : {fan.get(), tube.get()})
            for (int it = 0; it < 60; ++it) {
                const Pose p = random_pose(rng, 0.3 + 0.02 * it);
                const CollisionModel& a = torus_is_a ? torus().model : needles->model;
                const CollisionModel& b = torus_is_a ? needles->model : torus().model;
                const QueryResult any = collide_relative(a, b, p, opts(QueryLevel::Exact, QueryMode::Any), s1);
                const QueryResult ref = collide_brute_force(a, b, p, opts(QueryLevel::Exact, QueryMode::All), s2);
                ASSERT_EQ(any.collide, ref.collide) << "pose " << it << (torus_is_a ? ", torus as A" : ", torus as B");
                collide_relative(a, b, p, opts(QueryLevel::Exact, QueryMode::All), s1);
                EXPECT_EQ(tri_pairs(s1), tri_pairs(s2)) << "pose " << it << (torus_is_a ? ", torus as A" : ", torus as B");
                collisions += ref.collide;
            }
        EXPECT_GT(collisions, 10);
        EXPECT_LT(collisions, 110);
    }
}

TEST(Query, EveryLevelAndModeMatchesBruteForceOnSmallMeshes) {
    std::mt19937 rng(11);
    QueryScratch s1, s2;
    int collisions[3] = {0, 0, 0}, poses = 0;
    for (const test::Object* b : {&torus(), &box()}) {
        for (int it = 0; it < 40; ++it, ++poses) {
            const Pose p = random_pose(rng, 0.9 + 0.05 * it);
            for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact}) {
                const QueryResult any = collide_relative(torus().model, b->model, p, opts(level, QueryMode::Any), s1);
                const QueryResult ref = collide_brute_force(torus().model, b->model, p, opts(level, QueryMode::All), s2);
                ASSERT_EQ(any.collide, ref.collide) << "level " << int(level) << " pose " << it;
                collisions[int(level)] += ref.collide;
                const QueryResult all = collide_relative(torus().model, b->model, p, opts(level, QueryMode::All), s1);
                ASSERT_EQ(all.collide, ref.collide);
                if (level == QueryLevel::Exact) {
                    EXPECT_EQ(tri_pairs(s1), tri_pairs(s2));
                    continue;
                }
                EXPECT_EQ(sphere_pairs(s1), sphere_pairs(s2)) << "level " << int(level) << " pose " << it;
                const QueryResult deep = collide_relative(torus().model, b->model, p, opts(level, QueryMode::Deepest), s1);
                const QueryResult ref_deep =
                    collide_brute_force(torus().model, b->model, p, opts(level, QueryMode::Deepest), s2);
                ASSERT_EQ(deep.collide, ref.collide);
                EXPECT_EQ(deep.deepest.depth, ref_deep.deepest.depth);
                if (deep.collide) {
                    EXPECT_GT(deep.deepest.depth, 0);
                    EXPECT_NEAR(deep.deepest.normal.norm(), 1.0, 1e-9);
                }
            }
        }
    }
    // The poses must exercise both answers at every level.
    for (int c : collisions) {
        EXPECT_GT(c, poses / 5);
        EXPECT_LT(c, poses * 4 / 5);
    }
}

// The walk tests the grandchildren of a node in one step; trees whose children are a
// mix of active and inner nodes at every level, or that are a single active node,
// are where a lane could go missing.
TEST(Query, OneSidedAndSingleLeafTreesMatchBruteForce) {
    const test::Object& b = box();
    const SampleSet& samples = torus().doc.samples;
    const uint32_t n = uint32_t(samples.size());
    SptDocument doc = torus().doc;
    SamplingTree one("single leaf", n);
    one.assign_radii(samples, {});
    one.compute_bounds(samples, BoundsMethod::Tight);
    SamplingTree deep("one-sided", n);
    NodeId node = root_id();
    for (uint32_t i = 0; i < 45; ++i) { // peel off 3 samples a level: 45 levels deep
        ASSERT_TRUE(deep.split(node, {3 * i, 3 * i + 1, 3 * i + 2}, samples));
        node = right_child(node);
    }
    doc.trees = {one, deep};
    std::mt19937 rng(5);
    QueryScratch s1, s2;
    int collisions = 0;
    for (const std::string tree : {"single leaf", "one-sided"}) {
        const CollisionModel a(doc, torus().mesh, tree);
        for (int it = 0; it < 30; ++it) {
            const Pose p = random_pose(rng, 0.9 + 0.05 * it);
            for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres}) {
                const QueryResult ref = collide_brute_force(a, b.model, p, opts(level, QueryMode::All), s2);
                const auto ref_pairs = sphere_pairs(s2);
                EXPECT_EQ(collide_relative(a, b.model, p, opts(level, QueryMode::Any), s1).collide, ref.collide);
                EXPECT_EQ(collide_relative(a, b.model, p, opts(level, QueryMode::All), s1).collide, ref.collide);
                EXPECT_EQ(sphere_pairs(s1), ref_pairs) << tree << " level " << int(level) << " pose " << it;
                // B against A too: the one-sided tree on the transformed side.
                const Pose q = p.inverse();
                EXPECT_EQ(collide_relative(b.model, a, q, opts(level, QueryMode::Any), s1).collide, ref.collide);
                const QueryResult deep_ab = collide_relative(a, b.model, p, opts(level, QueryMode::Deepest), s1);
                const QueryResult ref_deep = collide_brute_force(a, b.model, p, opts(level, QueryMode::Deepest), s2);
                EXPECT_EQ(deep_ab.deepest.depth, ref_deep.deepest.depth);
                collisions += ref.collide;
            }
        }
    }
    EXPECT_GT(collisions, 20);
    EXPECT_LT(collisions, 100);
}

TEST(Query, ExactFindsTrianglesCrossingWhereNoSpheresOverlap) {
    // Two coarse boxes (2 triangles a face) with small spheres: a corner of B pokes
    // through the middle of A's face, far from every sample.
    ConvertOptions small;
    small.build.radius.fixed = 0.05f;
    small.auto_tolerance = false; // coarse on purpose: vertex samples only
    auto a = make_object(make_box({1, 1, 1}, 1), small);
    auto b = make_object(make_box({1, 1, 1}, 1), small);
    // Rotate B so a corner points along -x, and put that corner 0.1 inside A's +x face.
    const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d(-1, -1, -1).normalized(), -Eigen::Vector3d::UnitX());
    const Pose p = Pose::from(Eigen::Vector3d(1 + std::sqrt(3.0) - 0.1, 0.01, 0.02), q);
    QueryScratch s;
    EXPECT_FALSE(collide_relative(a->model, b->model, p, opts(QueryLevel::Spheres, QueryMode::Any), s).collide);
    EXPECT_TRUE(collide_relative(a->model, b->model, p, opts(QueryLevel::Exact, QueryMode::Any), s).collide);
    EXPECT_TRUE(collide_brute_force(a->model, b->model, p, opts(QueryLevel::Exact, QueryMode::Any), s).collide);
}

TEST(Query, ExactOnParallelPlatesAtHairlineGapsMatchesBruteForce) {
    // Face to face, the case slabs prune and spheres cannot: every gap from a slight
    // overlap to a slight separation, with and without a tiny tilt.
    auto a = make_object(make_box({0.6, 0.6, 0.05}, 8));
    auto b = make_object(make_box({0.6, 0.6, 0.05}, 8));
    QueryScratch s1, s2;
    int collide = 0, cases = 0;
    for (double tilt : {0.0, 1e-4, 1e-3})
        for (double gap : {-1e-3, -1e-6, 0.0, 1e-6, 1e-4, 1e-3}) {
            const Eigen::Quaterniond q(Eigen::AngleAxisd(tilt, Eigen::Vector3d(1, 2, 0).normalized()));
            const Pose p = Pose::from(Eigen::Vector3d(0.013, -0.021, 0.1 + gap), q);
            const QueryResult ref = collide_brute_force(a->model, b->model, p, opts(QueryLevel::Exact, QueryMode::All), s2);
            EXPECT_EQ(collide_relative(a->model, b->model, p, opts(QueryLevel::Exact, QueryMode::Any), s1).collide,
                      ref.collide)
                << "tilt " << tilt << " gap " << gap;
            collide_relative(a->model, b->model, p, opts(QueryLevel::Exact, QueryMode::All), s1);
            EXPECT_EQ(tri_pairs(s1), tri_pairs(s2)) << "tilt " << tilt << " gap " << gap;
            collide += ref.collide, ++cases;
        }
    EXPECT_GT(collide, 0);
    EXPECT_LT(collide, cases);
}

// Two-sided spheres are tested as discs, then as the faces they lie on, once their balls
// overlap: the walk and the brute-force reference keep the same pairs in every mode, on open
// meshes against themselves and against a closed body, with the mesh and from the .spt alone.
TEST(Query, OpenMeshesAtTheSphereLevelMatchBruteForce) {
    std::mt19937 rng(17);
    QueryScratch s1, s2;
    // Faces sampled (a tolerance, as every default conversion has), coarse enough for brute force.
    ConvertOptions sampled;
    sampled.tolerance = 0.2;
    const auto fan = make_object(make_fan(5), sampled);
    const auto soup = make_object(make_triangle_soup(40, 0.3, 5), sampled);
    const CollisionModel fan_spt(fan->doc), soup_spt(soup->doc);
    struct Pair {
        const CollisionModel *a, *b;
    };
    const Pair pairs[] = {{&fan->model, &fan->model}, {&soup->model, &soup->model}, {&soup->model, &box().model},
                          {&box().model, &fan->model}, {&fan_spt, &fan_spt}, {&soup_spt, &box().model}};
    int collisions = 0, poses = 0;
    for (const Pair& pr : pairs)
        for (int it = 0; it < 30; ++it, ++poses) {
            const Pose p = random_pose(rng, 0.02 * it);
            const QueryResult any = collide_relative(*pr.a, *pr.b, p, opts(QueryLevel::Spheres, QueryMode::Any), s1);
            const QueryResult ref = collide_brute_force(*pr.a, *pr.b, p, opts(QueryLevel::Spheres, QueryMode::All), s2);
            ASSERT_EQ(any.collide, ref.collide) << "pair " << (&pr - pairs) << " pose " << it;
            collide_relative(*pr.a, *pr.b, p, opts(QueryLevel::Spheres, QueryMode::All), s1);
            EXPECT_EQ(sphere_pairs(s1), sphere_pairs(s2)) << "pair " << (&pr - pairs) << " pose " << it;
            const QueryResult deep = collide_relative(*pr.a, *pr.b, p, opts(QueryLevel::Spheres, QueryMode::Deepest), s1);
            const QueryResult ref_deep =
                collide_brute_force(*pr.a, *pr.b, p, opts(QueryLevel::Spheres, QueryMode::Deepest), s2);
            ASSERT_EQ(deep.collide, ref.collide);
            EXPECT_EQ(deep.deepest.depth, ref_deep.deepest.depth);
            collisions += ref.collide;
        }
    EXPECT_GT(collisions, poses / 10);
    EXPECT_LT(collisions, poses * 9 / 10);
}

TEST(Query, OpenSheetsOnePercentApartDoNotCollideFromEitherSide) {
    // Default conversion of an open sheet: two-sided spheres centred on the surface, tested
    // as discs on their faces, so a sheet 1% away is apart from either side.
    const TriangleMesh mesh = make_sheet(2, 6);
    SptDocument doc = make_document(mesh);
    const CollisionModel m(doc, mesh);
    const double gap = 0.01 * mesh.diagonal();
    QueryScratch s;
    const Eigen::Quaterniond flip(Eigen::AngleAxisd(3.141592653589793, Eigen::Vector3d::UnitX()));
    for (double side : {1.0, -1.0})
        for (const Eigen::Quaterniond& q : {Eigen::Quaterniond::Identity(), flip}) {
            // B 1% above or below A, facing the same way or back to back.
            const Pose apart = Pose::from(Eigen::Vector3d(0.05, 0.03, side * gap), q);
            EXPECT_FALSE(collide_relative(m, m, apart, opts(QueryLevel::Spheres, QueryMode::Any), s).collide)
                << "side " << side;
            // Crossing at a slant they meet along a line, which lies in a disc of each.
            const Eigen::Quaterniond slant(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()));
            const Pose into = Pose::from(Eigen::Vector3d(0.05, 0.03, 0), slant * q);
            EXPECT_TRUE(collide_relative(m, m, into, opts(QueryLevel::Exact, QueryMode::Any), s).collide);
            EXPECT_TRUE(collide_relative(m, m, into, opts(QueryLevel::Spheres, QueryMode::Any), s).collide);
        }
}

TEST(Query, SwappingObjectsGivesTheSameAnswer) {
    std::mt19937 rng(5);
    QueryScratch s;
    for (int it = 0; it < 60; ++it) {
        const Pose pa = Pose::from(Eigen::Vector3d(0.3, -0.2, 0.1), test::random_rotation(rng));
        const Pose pb = Pose::from(pa.translation + (0.9 + 0.04 * it) * test::random_unit(rng), test::random_rotation(rng));
        for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact}) {
            const QueryResult ab = collide(torus().model, pa, box().model, pb, opts(level, QueryMode::Deepest), s);
            const QueryResult ba = collide(box().model, pb, torus().model, pa, opts(level, QueryMode::Deepest), s);
            ASSERT_EQ(ab.collide, ba.collide) << it;
            EXPECT_NEAR(ab.deepest.depth, ba.deepest.depth, 1e-5);
            if (ab.deepest.depth > 1e-3) {
                EXPECT_NEAR((ab.deepest.point - ba.deepest.point).norm(), 0, 1e-4);
                EXPECT_NEAR((ab.deepest.normal + ba.deepest.normal).norm(), 0, 1e-4);
            }
        }
    }
}

TEST(Query, CommonRigidMotionIncludingTranslationByAMillionChangesNothing) {
    std::mt19937 rng(9);
    QueryScratch s;
    for (int it = 0; it < 60; ++it) {
        const Pose pb = random_pose(rng, 0.9 + 0.04 * it);
        const Pose g = Pose::from(Eigen::Vector3d(1e6, -1e6, 1e6), test::random_rotation(rng));
        for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact}) {
            const QueryResult here = collide(torus().model, Pose{}, box().model, pb, opts(level, QueryMode::Deepest), s);
            const QueryResult there = collide(torus().model, g, box().model, g * pb, opts(level, QueryMode::Deepest), s);
            ASSERT_EQ(here.collide, there.collide) << it;
            // Any at `exact` prunes with slabs, not spheres: it must not lose a contact far away either.
            ASSERT_EQ(collide(torus().model, g, box().model, g * pb, opts(level, QueryMode::Any), s).collide, here.collide)
                << it;
            EXPECT_NEAR(here.deepest.depth, there.deepest.depth, 1e-5);
            if (here.deepest.depth > 1e-3) {
                EXPECT_NEAR((g.apply(here.deepest.point) - there.deepest.point).norm(), 0, 1e-4);
            }
        }
    }
}

// Two one-sphere objects: A's sphere centre at (-0.5, 0, 0), B's at (0.5, 0, 0) in B's frame.
struct TwoSpheres {
    SptDocument a, b;
    CollisionModel ma, mb;
    TwoSpheres() {
        for (auto [doc, nx] : {std::pair{&a, 1.0f}, std::pair{&b, -1.0f}}) {
            doc->samples.add(Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(nx, 0, 0), 0, 1.0f);
            BuildOptions bo;
            bo.radius.fixed = 0.5f;
            doc->trees.push_back(build_tree("t", doc->samples, bo));
            doc->mesh.diagonal = 1;
        }
        ma = CollisionModel(a);
        mb = CollisionModel(b);
    }
};

TEST(Query, ExactlyTouchingSpheresDoNotCollide) {
    TwoSpheres t;
    QueryScratch s;
    const QueryOptions o = opts(QueryLevel::Spheres, QueryMode::Deepest);
    EXPECT_FALSE(collide_relative(t.ma, t.mb, Pose{}, o, s).collide);
    const Pose in = Pose::from(Eigen::Vector3d(-std::ldexp(1.0, -20), 0, 0), Eigen::Quaterniond::Identity());
    const QueryResult r = collide_relative(t.ma, t.mb, in, o, s);
    EXPECT_TRUE(r.collide);
    EXPECT_FLOAT_EQ(float(r.deepest.depth), float(std::ldexp(1.0, -20)));
}

TEST(Query, DeepPenetrationOfCoincidentObjectsIsFoundAtEveryLevel) {
    QueryScratch s;
    for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact}) {
        const QueryResult r = collide_relative(torus().model, torus().model, Pose{}, opts(level, QueryMode::Deepest), s);
        EXPECT_TRUE(r.collide);
        if (level != QueryLevel::Bounds) {
            const float r2 = 2 * torus().model.tree().nodes()[1].ss_radius; // coincident spheres: depth 2r
            EXPECT_GE(r.deepest.depth, 0.9 * r2);
        }
    }
    TwoSpheres t; // one inside the other
    const QueryResult r = collide_relative(t.ma, t.mb, Pose::from(Eigen::Vector3d(-1, 0, 0), Eigen::Quaterniond::Identity()),
                                           opts(QueryLevel::Spheres, QueryMode::Deepest), s);
    EXPECT_TRUE(r.collide);
    EXPECT_FLOAT_EQ(float(r.deepest.depth), 1.0f);
}

TEST(Query, NormalCullingSkipsSpheresButNeverAddsPairs) {
    std::mt19937 rng(21);
    QueryScratch s;
    uint64_t tests_on = 0, tests_off = 0;
    for (int it = 0; it < 60; ++it) {
        const Pose p = random_pose(rng, 1.0 + 0.03 * it);
        QueryOptions o = opts(QueryLevel::Spheres, QueryMode::All);
        tests_off += collide_relative(torus().model, torus().model, p, o, s).counters.sphere_tests;
        const auto off = sphere_pairs(s);
        o.normal_culling = true;
        tests_on += collide_relative(torus().model, torus().model, p, o, s).counters.sphere_tests;
        const auto on = sphere_pairs(s);
        EXPECT_TRUE(std::includes(off.begin(), off.end(), on.begin(), on.end()));
    }
    EXPECT_LT(tests_on, tests_off);
}

TEST(Query, ExactLevelWithoutTrianglesIsAUsageError) {
    const CollisionModel no_mesh(torus().doc);
    QueryScratch s;
    try {
        collide_relative(no_mesh, torus().model, Pose{}, opts(QueryLevel::Exact, QueryMode::Any), s);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Usage);
        EXPECT_NE(std::string(e.what()).find("exact"), std::string::npos);
    }
}

TEST(Query, ThreadsWithTheirOwnScratchAgreeWithOneThread) {
    std::mt19937 rng(4);
    std::vector<Pose> poses;
    for (int i = 0; i < 200; ++i) poses.push_back(random_pose(rng, 0.9 + 0.01 * i));
    std::vector<double> serial(poses.size()), parallel(poses.size());
    QueryScratch s;
    const QueryOptions o = opts(QueryLevel::Spheres, QueryMode::Deepest);
    for (size_t i = 0; i < poses.size(); ++i) serial[i] = collide_relative(torus().model, box().model, poses[i], o, s).deepest.depth;
    auto work = [&](size_t first) {
        QueryScratch mine;
        for (size_t i = first; i < poses.size(); i += 2)
            parallel[i] = collide_relative(torus().model, box().model, poses[i], o, mine).deepest.depth;
    };
    std::thread t1(work, 0), t2(work, 1);
    t1.join(), t2.join();
    EXPECT_EQ(serial, parallel);
}

} // namespace
} // namespace spt

namespace spt {
namespace {

// One spelling of the levels for the command line, scenes and Python: each name gives its level
// and back; a name in another case or with spaces is none.
TEST(QueryLevelNames, EachNameGivesItsLevelAndBackAndNothingElseIsALevel) {
    for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact})
        EXPECT_EQ(query_level_named(query_level_name(level)), level);
    EXPECT_STREQ(query_level_name(QueryLevel::Spheres), "spheres");
    for (const char* wrong : {"", "Spheres", " exact", "sphere", "triangles"}) EXPECT_FALSE(query_level_named(wrong)) << wrong;
}

} // namespace
} // namespace spt
