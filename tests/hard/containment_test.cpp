// Containment: a closed part is a solid at every level (an object wholly inside it collides
// though no surfaces meet); open parts hold nothing; --surfaces gives FCL's answer.
#include "hard_support.hpp"
#include "spt/response.hpp"
#include "mesh/hard_shapes.hpp"
#include "query/brute_force.hpp"
#include <gtest/gtest.h>

namespace spt {
namespace {

using hard::kLevels;

// A hollow shell: a box with a box-shaped cavity (the inner surface faces into the cavity).
TriangleMesh hollow_box(double outer, double inner) {
    const TriangleMesh a = make_box(Eigen::Vector3d::Constant(outer), 4), b = make_box(Eigen::Vector3d::Constant(inner), 4);
    std::vector<Eigen::Vector3d> p = a.positions;
    std::vector<Triangle> t = a.triangles;
    const uint32_t base = uint32_t(p.size());
    for (const auto& q : b.positions) p.push_back(q);
    for (const auto& tri : b.triangles) t.push_back({tri[0] + base, tri[2] + base, tri[1] + base});
    return prepare_mesh("hollow box", std::move(p), std::move(t)).mesh;
}

bool collides(const hard::Object& a, const hard::Object& b, const Pose& p, QueryLevel level, bool solids = true) {
    QueryScratch s;
    QueryOptions o;
    o.level = level;
    o.solids = solids;
    const bool tree = collide_relative(a.model, b.model, p, o, s).collide;
    EXPECT_EQ(tree, collide_brute_force(a.model, b.model, p, o, s).collide) << "level " << int(level);
    return tree;
}

TEST(Containment, SmallCubeWhollyInsideABigCubeCollidesAtEveryLevelAndEitherOrder) {
    for (double scale : {1e-4, 1.0, 1e4}) {
        const auto big = hard::make_object(hard::transformed(make_box({1, 1, 1}, 4), scale, Eigen::Vector3d::Zero()));
        const auto small = hard::make_object(hard::transformed(make_box({0.1, 0.1, 0.1}, 2), scale, Eigen::Vector3d::Zero()));
        const Pose off{Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized())),
                       scale * Eigen::Vector3d(0.2, -0.3, 0.1)};
        for (QueryLevel level : kLevels) {
            EXPECT_TRUE(collides(*big, *small, off, level)) << "scale " << scale << " level " << int(level);
            EXPECT_TRUE(collides(*small, *big, off.inverse(), level)) << "scale " << scale << " level " << int(level);
        }
        // Surfaces only (FCL's answer): no surfaces meet.
        EXPECT_FALSE(collides(*big, *small, off, QueryLevel::Exact, false));
        EXPECT_FALSE(collides(*small, *big, off.inverse(), QueryLevel::Exact, false));
        // Moved out of the big cube, apart.
        const Pose out{off.rotation, scale * Eigen::Vector3d(3, 0, 0)};
        for (QueryLevel level : kLevels) EXPECT_FALSE(collides(*big, *small, out, level));
    }
}

TEST(Containment, ObjectInTheCavityOfAHollowShellDoesNotCollide) {
    const auto shell = hard::make_object(hollow_box(1.0, 0.7));
    const auto small = hard::make_object(make_box({0.1, 0.1, 0.1}, 2));
    const Pose in_cavity{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.2, 0.1, -0.3)};
    const Pose in_wall{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.85, 0.0, 0.0)}; // 0.75..0.95 inside the wall
    for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact}) {
        EXPECT_FALSE(collides(*shell, *small, in_cavity, level)) << "level " << int(level);
    }
    EXPECT_TRUE(collides(*shell, *small, in_wall, QueryLevel::Exact));
}

TEST(Containment, ObjectInTheRegionTwoOverlappingClosedPartsShareCollidesAtEveryLevel) {
    // Two boxes of side 2, the second moved by (0.45, 0.13, 0.07) (no face of one in a plane of the
    // other): one solid, as a model built of overlapping parts is meant. By ray parity the
    // shared region was outside at the exact level (two crossings).
    const TriangleMesh a = make_box({1, 1, 1}, 2);
    std::vector<Eigen::Vector3d> p = a.positions;
    std::vector<Triangle> t = a.triangles;
    const auto base = uint32_t(p.size());
    for (const auto& q : a.positions) p.push_back(q + Eigen::Vector3d(0.45, 0.13, 0.07));
    for (const auto& tri : a.triangles) t.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
    const ImportedMesh both = prepare_mesh("overlapping boxes", std::move(p), std::move(t));
    ASSERT_TRUE(both.report.closed);
    EXPECT_EQ(both.report.components, 2u);
    EXPECT_EQ(both.report.inverted_components, 0u);
    const auto solid = hard::make_object(both.mesh);
    const auto small = hard::make_object(make_box({0.1, 0.1, 0.1}, 2));
    const Pose shared{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.22, 0.05, 0.0)};
    const Pose first_only{Eigen::Quaterniond::Identity(), Eigen::Vector3d(-0.8, 0.0, 0.0)};
    const Pose second_only{Eigen::Quaterniond::Identity(), Eigen::Vector3d(1.25, 0.1, 0.1)};
    const Pose outside{Eigen::Quaterniond::Identity(), Eigen::Vector3d(2.0, 0.1, 0.1)};
    for (QueryLevel level : kLevels) {
        for (const Pose& in : {shared, first_only, second_only})
            EXPECT_TRUE(collides(*solid, *small, in, level)) << "level " << int(level) << " at " << in.translation.transpose();
        EXPECT_TRUE(collides(*small, *solid, shared.inverse(), level)) << "level " << int(level);
        EXPECT_FALSE(collides(*solid, *small, outside, level)) << "level " << int(level);
    }
}

TEST(Containment, OpenBoxHoldsNothing) {
    const auto box = hard::make_object(make_open_box({1, 1, 1}, 4));
    const auto small = hard::make_object(make_box({0.1, 0.1, 0.1}, 2));
    const Pose inside{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.1, -0.2, 0)};
    for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact})
        EXPECT_FALSE(collides(*box, *small, inside, level)) << "level " << int(level);
}

TEST(Containment, SheetInsideAClosedSolidCollides) {
    // A's solid holds every piece of B, open or not: the sheet lies in A's material.
    const auto big = hard::make_object(make_box({1, 1, 1}, 4));
    const auto sheet = hard::make_object(make_sheet(0.5, 4));
    const Pose p{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0.1, 0.2)};
    for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact}) EXPECT_TRUE(collides(*big, *sheet, p, level));
}

TEST(Containment, BacktrackMovesAContainedObjectOut) {
    const auto big = hard::make_object(make_box({1, 1, 1}, 4));
    const auto small = hard::make_object(make_box({0.1, 0.1, 0.1}, 2));
    const Pose inside{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.2, 0, 0)};
    const Eigen::Vector3d motion(-1, 0, 0); // moving in along -x: backing out is along +x
    QueryScratch s;
    for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact}) {
        QueryOptions o;
        o.level = level;
        const BacktrackResult r = backtrack_relative(big->model, small->model, inside, motion, o, BacktrackRule::Exact, s);
        ASSERT_TRUE(r.converged);
        // Out when the small cube clears the big one's face: 1 - 0.2 + 0.1 = 0.9, within the models' tolerance.
        EXPECT_NEAR(r.distance, 0.9, 0.03) << "level " << int(level);
        const Pose out{inside.rotation, inside.translation + r.distance * Eigen::Vector3d::UnitX()};
        EXPECT_FALSE(collide_relative(big->model, small->model, out, o, s).collide);
    }
}

} // namespace
} // namespace spt
