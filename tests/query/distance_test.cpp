// distance_relative against every sphere pair: the smallest gap, its points, max_distance and the
// relative error allowance; overlapping models give the deepest overlap, negated. Level exact
// against every triangle pair.
#include "query_fixtures.hpp"
#include "spt/distance.hpp"
#include "spt/error.hpp"
#include "geometry/tri_distance.hpp"
#include "mesh/shapes.hpp"
#include "query/model_access.hpp"
#include "query/exact_data.hpp"
#include "query/node_slab.hpp"
#include <gtest/gtest.h>
#include <random>

using namespace spt;
using namespace spt::test;

namespace {

struct Nearest {
    double gap = std::numeric_limits<double>::infinity();
};

// The smallest gap between any sampling sphere of A and any of B at b_in_a (brute force).
Nearest every_pair(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a) {
    Nearest n;
    const CompactTree& ta = a.tree();
    const CompactTree& tb = b.tree();
    for (const CompactNode& na : ta.nodes()) {
        if (!na.is_active()) continue;
        for (uint32_t k = na.first; k < na.first + na.count; ++k) {
            const Eigen::Vector3d ca = ta.sphere_center(na, k).cast<double>() + a.origin();
            for (const CompactNode& nb : tb.nodes()) {
                if (!nb.is_active()) continue;
                for (uint32_t l = nb.first; l < nb.first + nb.count; ++l) {
                    const Eigen::Vector3d cb = b_in_a.apply(tb.sphere_center(nb, l).cast<double>() + b.origin());
                    n.gap = std::min(n.gap, (ca - cb).norm() - na.ss_radius - nb.ss_radius);
                }
            }
        }
    }
    return n;
}

std::vector<Pose> apart_poses(int count) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-4, 4);
    std::vector<Pose> poses;
    while (int(poses.size()) < count) {
        const double x = u(rng), y = u(rng), z = u(rng);
        poses.push_back(Pose::from(Eigen::Vector3d(x, y, z), random_rotation(rng)));
    }
    return poses;
}

} // namespace

TEST(Distance, IsTheSmallestGapOfAnySpherePairWithItsPoints) {
    const Object& t = torus();
    QueryScratch scratch;
    int apart = 0, overlapping = 0;
    for (const Pose& p : apart_poses(60)) {
        const DistanceResult d = distance_relative(t.model, t.model, p, DistanceOptions{}, scratch);
        const Nearest n = every_pair(t.model, t.model, p);
        if (n.gap < 0) {
            ++overlapping;
            EXPECT_TRUE(d.collide);
            EXPECT_LE(d.distance, 0);
            continue;
        }
        ++apart;
        ASSERT_FALSE(d.collide);
        ASSERT_FALSE(d.beyond);
        EXPECT_NEAR(d.distance, n.gap, 1e-6) << "pose " << p.translation.transpose();
        // The points are on the spheres and as far apart as the gap.
        EXPECT_NEAR((d.point_b - d.point_a).norm(), d.distance, 1e-5);
        EXPECT_LT(d.counters.sphere_tests, uint64_t(t.model.tree().sphere_count()) * t.model.tree().sphere_count() / 10)
            << "the bounds prune";
    }
    EXPECT_GT(apart, 20);
    EXPECT_GT(overlapping, 2);
}

TEST(Distance, OverlappingModelsAnswerTheDeepestOverlapOfTheirLevelNegated) {
    const Object& t = torus();
    QueryScratch scratch;
    const Pose p = Pose::from(Eigen::Vector3d(0.3, 0, 0), Eigen::Quaterniond::Identity());
    for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact}) {
        DistanceOptions o;
        o.level = level;
        const DistanceResult d = distance_relative(t.model, t.model, p, o, scratch);
        QueryOptions deepest;
        deepest.level = level;
        deepest.mode = QueryMode::Deepest;
        deepest.solids = false;
        const QueryResult q = collide_relative(t.model, t.model, p, deepest, scratch);
        ASSERT_TRUE(q.collide);
        EXPECT_TRUE(d.collide);
        EXPECT_DOUBLE_EQ(d.distance, -q.deepest.depth);
        EXPECT_NEAR((d.point_a - d.point_b).norm(), q.deepest.depth, 1e-9);
    }
}

TEST(Distance, MaxDistanceAnswersBeyondAndRelativeErrorStaysWithinItsAllowance) {
    const Object& t = torus();
    QueryScratch scratch;
    int beyond = 0, within = 0;
    for (const Pose& p : apart_poses(60)) {
        const Nearest n = every_pair(t.model, t.model, p);
        if (n.gap <= 0) continue;
        DistanceOptions capped;
        capped.max_distance = 0.5;
        const DistanceResult c = distance_relative(t.model, t.model, p, capped, scratch);
        if (n.gap >= 0.5) {
            EXPECT_TRUE(c.beyond) << n.gap;
            EXPECT_TRUE(std::isinf(c.distance));
            ++beyond;
        } else {
            EXPECT_FALSE(c.beyond);
            EXPECT_NEAR(c.distance, n.gap, 1e-6);
            ++within;
        }
        DistanceOptions rough;
        rough.relative_error = 0.1;
        const DistanceResult r = distance_relative(t.model, t.model, p, rough, scratch);
        EXPECT_GE(r.distance, n.gap - 1e-6);
        EXPECT_LE(r.distance * 0.9, n.gap + 1e-6);
    }
    EXPECT_GT(beyond, 5);
    EXPECT_GT(within, 2);
}

TEST(Distance, BadOptionsAreUsageErrors) {
    const Object& t = torus();
    QueryScratch scratch;
    DistanceOptions bad;
    bad.max_distance = 0;
    EXPECT_THROW(distance_relative(t.model, t.model, Pose{}, bad, scratch), Error);
    bad = DistanceOptions{};
    bad.relative_error = std::nan("");
    EXPECT_THROW(distance_relative(t.model, t.model, Pose{}, bad, scratch), Error);
}

namespace {

// The smallest gap between any triangle of A and any of B at b_in_a (every pair).
double every_triangle_pair(const Object& a, const Object& b, const Pose& b_in_a) {
    double best = std::numeric_limits<double>::infinity();
    for (const Triangle& x : a.mesh.triangles)
        for (const Triangle& y : b.mesh.triangles) {
            const auto& pa = a.mesh.positions;
            const auto& pb = b.mesh.positions;
            best = std::min(best, triangle_gap(pa[x[0]], pa[x[1]], pa[x[2]], b_in_a.apply(pb[y[0]]),
                                               b_in_a.apply(pb[y[1]]), b_in_a.apply(pb[y[2]]))
                                      .distance);
        }
    return best;
}

} // namespace

TEST(Distance, BoxesFaceToFaceGiveTheGapOfTheirNearestSpheres) {
    // Flat faces nearly parallel: each node's disc bounds the pair together with the other's disc
    // (its reach back along the first's normal), not its ball; neither may overshoot.
    const auto box = make_object(make_box(Eigen::Vector3d(1.0, 1.0, 0.25), 6));
    QueryScratch scratch;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> gap(0.001, 0.2), slide(-0.8, 0.8), tilt(-0.03, 0.03), turn(-kPi, kPi);
    int apart = 0;
    for (int k = 0; k < 30; ++k) {
        const Eigen::Quaterniond q(Eigen::AngleAxisd(turn(rng), Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(tilt(rng), Eigen::Vector3d::UnitX()) *
                                   Eigen::AngleAxisd(tilt(rng), Eigen::Vector3d::UnitY()));
        const Pose p = Pose::from(Eigen::Vector3d(slide(rng), slide(rng), 0.5 + gap(rng)), q);
        const Nearest n = every_pair(box->model, box->model, p);
        if (!(n.gap > 0)) continue;
        ++apart;
        const DistanceResult d = distance_relative(box->model, box->model, p, DistanceOptions{}, scratch);
        ASSERT_FALSE(d.collide);
        EXPECT_NEAR(d.distance, n.gap, 1e-6) << "pose " << k;
    }
    EXPECT_GT(apart, 15);
}

TEST(DistanceExact, IsTheSmallestGapOfAnyTrianglePairWithPointsOnTheSurfaces) {
    const Object& t = torus();
    QueryScratch scratch;
    DistanceOptions exact;
    exact.level = QueryLevel::Exact;
    int apart = 0;
    for (const Pose& p : apart_poses(40)) {
        const DistanceResult d = distance_relative(t.model, t.model, p, exact, scratch);
        const double truth = every_triangle_pair(t, t, p);
        if (truth == 0) {
            EXPECT_TRUE(d.collide);
            EXPECT_LE(d.distance, 0);
            continue;
        }
        ++apart;
        ASSERT_FALSE(d.collide);
        ASSERT_FALSE(d.beyond);
        EXPECT_NEAR(d.distance, truth, 1e-12 * t.model.diagonal());
        EXPECT_NEAR((d.point_a - d.point_b).norm(), d.distance, 1e-12);
        // Each point lies on its mesh: some triangle holds it.
        double on_a = std::numeric_limits<double>::infinity(), on_b = on_a;
        const Pose inv = p.inverse();
        for (const Triangle& x : t.mesh.triangles) {
            const auto& v = t.mesh.positions;
            on_a = std::min(on_a, (triangle_closest_point(v[x[0]], v[x[1]], v[x[2]], d.point_a) - d.point_a).norm());
            const Eigen::Vector3d qb = inv.apply(d.point_b);
            on_b = std::min(on_b, (triangle_closest_point(v[x[0]], v[x[1]], v[x[2]], qb) - qb).norm());
        }
        EXPECT_LT(on_a, 1e-9);
        EXPECT_LT(on_b, 1e-9);
    }
    EXPECT_GT(apart, 20);
}

TEST(DistanceExact, MaxDistanceAndRelativeErrorHoldOnTheTriangles) {
    const Object& t = torus();
    QueryScratch scratch;
    int beyond = 0, within = 0;
    for (const Pose& p : apart_poses(40)) {
        const double truth = every_triangle_pair(t, t, p);
        if (truth == 0) continue;
        DistanceOptions capped;
        capped.level = QueryLevel::Exact;
        capped.max_distance = 0.5;
        const DistanceResult c = distance_relative(t.model, t.model, p, capped, scratch);
        if (truth >= 0.5) {
            EXPECT_TRUE(c.beyond) << truth;
            ++beyond;
        } else {
            EXPECT_NEAR(c.distance, truth, 1e-12);
            ++within;
        }
        DistanceOptions rough;
        rough.level = QueryLevel::Exact;
        rough.relative_error = 0.1;
        const DistanceResult r = distance_relative(t.model, t.model, p, rough, scratch);
        EXPECT_GE(r.distance, truth - 1e-12);
        EXPECT_LE(r.distance * 0.9, truth + 1e-12);
    }
    EXPECT_GT(beyond, 5);
    EXPECT_GT(within, 2);
}

// Two sheets in one plane (or a hair off it), side by side: every corner lies on the other's
// plane, so the planes' gaps bound nothing and the line of the triangles' centroids tells the
// pairs apart; it must never drop the nearest pair.
TEST(DistanceExact, SheetsSideBySideInOnePlaneGiveTheGapOfTheirNearestTriangles) {
    const auto sheet = make_object(make_sheet(1.0, 10));
    QueryScratch scratch;
    DistanceOptions exact;
    exact.level = QueryLevel::Exact;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> turn(-kPi, kPi), lift(-1e-3, 1e-3), tilt(-0.05, 0.05);
    int apart = 0;
    for (int k = 0; k < 50; ++k) {
        const double a = turn(rng);
        const Eigen::Vector3d across(std::cos(a), std::sin(a), 0);
        const Eigen::Quaterniond spin(Eigen::AngleAxisd(turn(rng), Eigen::Vector3d::UnitZ()) *
                                      Eigen::AngleAxisd(k % 3 == 0 ? tilt(rng) : 0, Eigen::Vector3d::UnitX()));
        const Pose p = Pose::from(1.6 * across + Eigen::Vector3d(0, 0, k % 2 ? lift(rng) : 0), spin);
        const double truth = every_triangle_pair(*sheet, *sheet, p);
        if (truth == 0) continue;
        ++apart;
        const DistanceResult d = distance_relative(sheet->model, sheet->model, p, exact, scratch);
        ASSERT_FALSE(d.beyond);
        EXPECT_NEAR(d.distance, truth, 1e-12) << "pose " << k;
        EXPECT_NEAR((d.point_a - d.point_b).norm(), d.distance, 1e-12);
    }
    EXPECT_GT(apart, 30);
}

// A small part near the middle of a faceted ball: every facet is about as far, and the box of a
// leaf of curved facets has a slab that bounds the leaf short of its facets' own planes. Bounded
// by the boxes alone, the walk took each such leaf down the whole small part (3,452 node pairs a
// pose for assimp's regr01.dae inside a globe, 210 with the planes).
TEST(DistanceExact, ASmallPartInsideAFacetedBallIsBoundedByTheFacetsPlanes) {
    const auto ball = make_object(make_ball(1.0, 32, 16));
    const auto part = make_object(make_torus(0.02, 0.006, 8, 4));
    QueryScratch scratch;
    DistanceOptions exact;
    exact.level = QueryLevel::Exact;
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> near(-0.05, 0.05);
    uint64_t node_pairs = 0;
    for (int k = 0; k < 12; ++k) {
        const Pose p = Pose::from(Eigen::Vector3d(near(rng), near(rng), near(rng)), random_rotation(rng));
        const double truth = every_triangle_pair(*ball, *part, p);
        ASSERT_GT(truth, 0.8);
        const DistanceResult d = distance_relative(ball->model, part->model, p, exact, scratch);
        ASSERT_FALSE(d.collide);
        EXPECT_NEAR(d.distance, truth, 1e-12) << "pose " << k;
        node_pairs += d.counters.node_pairs;
    }
    // 46,159 node pairs over these poses with the boxes alone; 6,129 with the planes.
    EXPECT_LT(node_pairs, 12'000u);
}

// The planes those bounds use: unit normals in float, every corner within plane_pad of its
// triangle's plane, and the pad no more than float rounding.
TEST(DistanceExact, EveryTrianglesCornersLieWithinThePadOfItsFloatPlane) {
    const auto bracket = make_object(make_bracket());
    for (const Object* o : {&torus(), static_cast<const Object*>(bracket.get())}) {
        const ExactData& e = detail::exact_of(o->model);
        ASSERT_EQ(e.tri_plane.size(), 4 * e.triangles.size());
        EXPECT_LE(e.plane_pad, 1e-6 * o->model.diagonal());
        for (size_t f = 0; f < e.triangles.size(); ++f) {
            const float* p = &e.tri_plane[4 * f];
            const Eigen::Vector3d n(p[0], p[1], p[2]);
            EXPECT_NEAR(n.norm(), 1.0, 1e-6) << "triangle " << f;
            for (uint32_t v : e.triangles[f]) EXPECT_LE(std::abs(n.dot(e.positions[v]) - double(p[3])), double(e.plane_pad));
        }
    }
}

TEST(DistanceExact, NeedsTheMeshesOfBothModels) {
    const Object& t = torus();
    const CollisionModel no_mesh(t.doc);
    QueryScratch scratch;
    DistanceOptions exact;
    exact.level = QueryLevel::Exact;
    EXPECT_THROW(distance_relative(t.model, no_mesh, Pose::from(Eigen::Vector3d(5, 0, 0), Eigen::Quaterniond::Identity()),
                                   exact, scratch),
                 Error);
}

TEST(Distance, EveryNodesSlabHoldsTheSpheresBelowIt) {
    // The torus (vertex samples on a curved surface) and the bracket's flat faces sampled densely.
    const auto bracket = make_object(make_bracket(), ConvertOptions{});
    std::mt19937 rng(41);
    std::normal_distribution<float> g;
    for (const Object* o : {static_cast<const Object*>(&torus()), static_cast<const Object*>(bracket.get())}) {
        const CompactTree& t = o->model.tree();
        const float* slab = detail::node_slab_of(o->model);
        ASSERT_NE(slab, nullptr);
        size_t thin = 0;
        const auto& nodes = t.nodes();
        for (size_t i = 0; i < nodes.size(); ++i) {
            const float* s = slab + detail::kSlabStride * i;
            if (!(s[3] >= 0)) continue;
            const Eigen::Vector3f n(s[0], s[1], s[2]), c(nodes[i].center[0], nodes[i].center[1], nodes[i].center[2]);
            const auto shape = detail::NodeShape::of(nodes[i].bv_radius, slab, i);
            thin += s[3] + s[4] < 2 * nodes[i].bv_radius; // thinner than the ball
            EXPECT_NEAR(n.norm(), 1, 1e-5);
            // Directions to check the disc's support against: its normal, across it, and at random.
            std::vector<Eigen::Vector3f> dirs{n, -n, n.unitOrthogonal()};
            for (int k = 0; k < 6; ++k) dirs.push_back(Eigen::Vector3f(g(rng), g(rng), g(rng)).normalized());
            // Every sphere below node i (children: the next node and `first`).
            std::vector<size_t> open{i};
            while (!open.empty()) {
                const size_t j = open.back();
                open.pop_back();
                if (!nodes[j].is_active()) {
                    open.push_back(j + 1), open.push_back(nodes[j].first);
                    continue;
                }
                EXPECT_LE(nodes[j].ss_radius, s[6]);
                for (uint32_t k = nodes[j].first; k < nodes[j].first + nodes[j].count; ++k) {
                    const Eigen::Vector3f d = t.sphere_center(nodes[j], k) - c;
                    EXPECT_LE(n.dot(d) + nodes[j].ss_radius, s[3]) << "node " << i << " sphere " << k;
                    EXPECT_LE(nodes[j].ss_radius - n.dot(d), s[4]) << "node " << i << " sphere " << k;
                    EXPECT_LE((d - n.dot(d) * n).norm(), s[5] * (1 + 1e-6f)) << "node " << i << " sphere " << k;
                    for (const Eigen::Vector3f& u : dirs)
                        EXPECT_LE(d.dot(u) + nodes[j].ss_radius, shape.support(u) + 1e-6f * nodes[i].bv_radius)
                            << "node " << i << " sphere " << k;
                }
            }
        }
        EXPECT_GT(thin, nodes.size() / 4) << "faces give thin discs";
    }
}

TEST(Distance, SpheresSupportIsTheFurthestReachOfAnySphereAlongADirection) {
    const auto bracket = make_object(make_bracket(), ConvertOptions{});
    std::mt19937 rng(43);
    std::normal_distribution<double> g;
    std::vector<std::pair<double, uint32_t>> heap;
    for (const Object* o : {static_cast<const Object*>(&torus()), static_cast<const Object*>(bracket.get())}) {
        const CompactTree& t = o->model.tree();
        for (int k = 0; k < 20; ++k) {
            const Eigen::Vector3d u = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
            double reach = -1e300;
            for (const CompactNode& n : t.nodes())
                if (n.is_active())
                    for (uint32_t s = n.first; s < n.first + n.count; ++s)
                        reach = std::max(reach, t.sphere_center(n, s).cast<double>().dot(u) + double(n.ss_radius));
            for (const float* slab : {detail::node_slab_of(o->model), static_cast<const float*>(nullptr)}) {
                const detail::SphereSupport found = detail::spheres_support(t, slab, u, heap);
                EXPECT_EQ(found.reach, reach) << "direction " << k;
                const CompactNode& n = t.nodes()[found.node];
                ASSERT_TRUE(n.is_active());
                EXPECT_EQ(t.sphere_center(n, found.sphere).cast<double>().dot(u) + double(n.ss_radius), reach);
            }
        }
    }
}

TEST(Distance, AbsoluteErrorStaysWithinItsAllowanceAtEveryLevel) {
    const Object& t = torus();
    QueryScratch scratch;
    for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact}) {
        int apart = 0, overlapping = 0;
        std::vector<Pose> poses = apart_poses(40);
        for (size_t i = 0; i < 20; ++i) // and some near the centre, mostly overlapping
            poses.push_back(Pose::from(0.15 * poses[i].translation, poses[i].rotation));
        for (const Pose& p : poses) {
            DistanceOptions full, rough;
            full.level = rough.level = level;
            rough.absolute_error = 0.2;
            const DistanceResult f = distance_relative(t.model, t.model, p, full, scratch);
            const DistanceResult r = distance_relative(t.model, t.model, p, rough, scratch);
            (f.collide ? overlapping : apart) += 1;
            // Apart, or overlapping (minus the deepest depth): at most the allowance above, never below.
            EXPECT_EQ(r.collide, f.collide);
            EXPECT_GE(r.distance, f.distance - 1e-6);
            EXPECT_LE(r.distance, f.distance + 0.2 + 1e-6);
            EXPECT_LE(r.counters.node_pairs, f.counters.node_pairs);
        }
        EXPECT_GT(apart, 20);
        EXPECT_GT(overlapping, 4);
    }
    DistanceOptions bad;
    bad.absolute_error = -1;
    EXPECT_THROW(distance_relative(t.model, t.model, Pose{}, bad, scratch), Error);
}

TEST(Distance, WithoutDepthOverlapAnswersZeroAtOnceAndApartPosesTheSame) {
    const Object& t = torus();
    QueryScratch scratch;
    int overlapping = 0;
    for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact}) {
        std::vector<Pose> poses = apart_poses(30);
        for (size_t i = 0; i < 30; ++i) // and as many near the centre, mostly overlapping
            poses.push_back(Pose::from(0.15 * poses[i].translation, poses[i].rotation));
        for (const Pose& p : poses) {
            DistanceOptions full, quick;
            full.level = quick.level = level;
            quick.depth = false;
            const DistanceResult f = distance_relative(t.model, t.model, p, full, scratch);
            const DistanceResult q = distance_relative(t.model, t.model, p, quick, scratch);
            EXPECT_EQ(q.collide, f.collide);
            if (!f.collide) {
                EXPECT_EQ(q.distance, f.distance);
                EXPECT_EQ(q.point_a, f.point_a);
                continue;
            }
            ++overlapping;
            EXPECT_EQ(q.distance, 0);
            EXPECT_TRUE(q.point_a.array().isNaN().all() && q.point_b.array().isNaN().all());
            EXPECT_LT(q.counters.node_pairs, f.counters.node_pairs) << "no deepest walk";
        }
    }
    EXPECT_GT(overlapping, 4);
}
