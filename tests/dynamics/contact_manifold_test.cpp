// Contact manifolds from sampling spheres (dynamics/contact_manifold.cpp): at most four points that
// span the contact, one normal, depths along it.
#include "dynamics/contact_manifold.hpp"
#include "meshgen.hpp"
#include "spt/convert.hpp"
#include <gtest/gtest.h>

namespace {

using namespace spt;

CollisionModel model_of(const meshgen::RawMesh& raw, const char* name) {
    const TriangleMesh mesh = meshgen::prepare(raw, name).mesh;
    return CollisionModel(make_document(mesh, {}), mesh);
}

TEST(ContactManifold, ABoxOnAFloorGetsItsFourCornersAndTheFloorsNormal) {
    const CollisionModel floor = model_of(meshgen::box(8, 0.5, 8, 8), "floor"), box = model_of(meshgen::box(1, 1, 1, 4), "box");
    const Pose floor_pose = Pose::from({0, -0.25, 0}, Eigen::Quaterniond::Identity());
    const Pose box_pose = Pose::from({0.3, 0.5, -0.2}, Eigen::Quaterniond::Identity()); // resting on it
    QueryScratch scratch;
    detail::Manifold m;
    detail::ManifoldWork work;
    detail::contact_manifold(box, box_pose, floor, floor_pose, 0.01, true, false, false, scratch, work, m);
    ASSERT_EQ(m.points.size(), 4u);
    for (const detail::ManifoldContact& c : m.points) {
        EXPECT_NEAR(c.normal.y(), -1, 1e-9); // the struck floor's normal, from the box towards it
        EXPECT_NEAR(c.on_b.y(), 0, 0.02);    // on the floor's top
        // Near a corner of the box's bottom: within a few sphere radii of (x +- 0.5, z +- 0.5).
        EXPECT_NEAR(std::abs(c.on_b.x() - 0.3), 0.5, 0.1) << c.on_b.transpose();
        EXPECT_NEAR(std::abs(c.on_b.z() + 0.2), 0.5, 0.1) << c.on_b.transpose();
        EXPECT_GT(c.depth, -0.01);
        EXPECT_LT(c.depth, 0.02);
    }
    // Four different corners.
    for (size_t i = 0; i < 4; ++i)
        for (size_t j = i + 1; j < 4; ++j) EXPECT_GT((m.points[i].on_b - m.points[j].on_b).norm(), 0.5);
}

TEST(ContactManifold, StackedBoxesWhoseSidesLieInOnePlaneKeepAnUpwardNormal) {
    // The side faces' spheres along the shared edges overlap deeply; their normals are parallel,
    // not opposed, and must neither tilt the normal nor make the overlap look deep.
    const CollisionModel box = model_of(meshgen::box(1, 1, 1, 4), "box");
    const Pose lower = Pose::from({0, 0.5, 0}, Eigen::Quaterniond::Identity());
    const Pose upper = Pose::from({0, 1.5005, 0}, Eigen::Quaterniond::Identity());
    QueryScratch scratch;
    detail::Manifold m;
    detail::ManifoldWork work;
    detail::contact_manifold(box, lower, box, upper, 0.01, true, true, false, scratch, work, m);
    ASSERT_EQ(m.points.size(), 4u);
    for (const detail::ManifoldContact& c : m.points) {
        EXPECT_GT(c.normal.y(), 0.9999) << c.normal.transpose();
        EXPECT_NEAR(c.depth, -0.0005, 0.01);
    }
}

TEST(ContactManifold, ApartByMoreThanTheMarginIsNoContact) {
    const CollisionModel box = model_of(meshgen::box(1, 1, 1, 2), "box");
    QueryScratch scratch;
    detail::Manifold m;
    detail::ManifoldWork work;
    detail::contact_manifold(box, Pose(), box, Pose::from({0, 1.2, 0}, Eigen::Quaterniond::Identity()), 0.05, true,
                             true, false, scratch, work, m);
    EXPECT_TRUE(m.points.empty());
    detail::contact_manifold(box, Pose(), box, Pose::from({0, 1.2, 0}, Eigen::Quaterniond::Identity()), 0.3, true,
                             true, false, scratch, work, m);
    ASSERT_FALSE(m.points.empty()); // within a margin of 0.3: a speculative contact, apart by about 0.2
    for (const detail::ManifoldContact& c : m.points) EXPECT_NEAR(c.depth, -0.2, 0.05);
}

TEST(ContactManifold, DeeplyOverlappingBallsGetAPointAlongTheirCentresWithoutEveryPair) {
    const CollisionModel ball = model_of(meshgen::icosphere(0.5, 3), "ball");
    const Pose a = Pose(), b = Pose::from({0.3, 0.05, 0}, Eigen::Quaterniond::Identity()); // centres 0.3 apart, radius 0.5
    QueryScratch scratch;
    detail::Manifold m;
    detail::ManifoldWork work;
    detail::contact_manifold(ball, a, ball, b, 0.01, true, true, false, scratch, work, m);
    ASSERT_FALSE(m.points.empty());
    const Eigen::Vector3d along = b.translation.normalized();
    EXPECT_GT(m.points[0].normal.dot(along), 0.5) << m.points[0].normal.transpose();
    // The all query of the same pair: every sphere pair of the shared volume.
    QueryOptions all;
    all.mode = QueryMode::All;
    const QueryResult every = collide(ball, a, ball, b, all, scratch);
    EXPECT_LT(m.counters.sphere_tests * 4, every.counters.sphere_tests);
}

detail::ManifoldContact at(double x, double z, double depth) {
    detail::ManifoldContact c;
    c.normal = Eigen::Vector3d::UnitY();
    c.on_b = Eigen::Vector3d(x, 0, z), c.on_a = c.on_b + depth * c.normal;
    c.depth = depth;
    return c;
}

TEST(ReduceManifold, AGridKeepsItsFourCornersWhateverItsRipple) {
    std::vector<detail::ManifoldContact> grid;
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j) grid.push_back(at(0.1 * i, 0.1 * j, 1e-4 * ((i * 7 + j * 3) % 5)));
    const std::vector<detail::ManifoldContact> kept = detail::reduce_manifold(grid, 0.01);
    ASSERT_EQ(kept.size(), 4u);
    for (const detail::ManifoldContact& c : kept) {
        EXPECT_TRUE(c.on_b.x() == 0 || std::abs(c.on_b.x() - 1) < 1e-12) << c.on_b.transpose();
        EXPECT_TRUE(c.on_b.z() == 0 || std::abs(c.on_b.z() - 1) < 1e-12) << c.on_b.transpose();
    }
}

TEST(ReduceManifold, AClearlyDeeperPointReplacesTheNearestCorner) {
    std::vector<detail::ManifoldContact> grid;
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j) grid.push_back(at(0.25 * i, 0.25 * j, i == 1 && j == 1 ? 0.05 : 0.0));
    const std::vector<detail::ManifoldContact> kept = detail::reduce_manifold(grid, 0.01);
    ASSERT_EQ(kept.size(), 4u);
    EXPECT_TRUE(std::any_of(kept.begin(), kept.end(), [](const detail::ManifoldContact& c) { return c.depth == 0.05; }));
}

TEST(ReduceManifold, APointContactStaysOnePoint) {
    std::vector<detail::ManifoldContact> same(6, at(0.5, 0.5, 0.01));
    EXPECT_EQ(detail::reduce_manifold(same, 0.01).size(), 1u);
}

} // namespace
