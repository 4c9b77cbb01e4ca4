// Slab bounds hold every point after float rounding, near and far from the origin.
#include "geometry/slab.hpp"
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <random>

namespace spt {
namespace {

TEST(Slab, FittedSlabHoldsEveryPointFarFromTheOrigin) {
    // A bumpy tilted patch 1000 units out: the float slab must still hold each double point.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    const Eigen::Vector3d n = Eigen::Vector3d(1, -2, 3).normalized();
    const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    const Eigen::Vector3d origin(1000, -1000, 500);
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 500; ++i) pts.push_back(origin + u(rng) * e1 + u(rng) * e2 + 1e-3 * u(rng) * n);
    const Slab s = fit_slab(pts);
    EXPECT_LT(s.h, 2e-3 + 1e-4); // found the thin direction
    EXPECT_GT(std::abs(Eigen::Vector3d(s.n[0], s.n[1], s.n[2]).dot(n)), 0.999);
    for (const auto& p : pts) {
        const double v = double(s.n[0]) * p.x() + double(s.n[1]) * p.y() + double(s.n[2]) * p.z() - double(s.d);
        EXPECT_LE(std::abs(v), double(s.h));
    }
}

TEST(Slab, SeparatesOnlySpheresWhollyOutside) {
    const Slab s = fit_slab({{0, 0, -0.2}, {1, 0, 0.2}, {0, 1, 0.2}, {1, 1, -0.2}, {0.5, 0.5, 0}});
    // The thinnest direction of this point set is z: the slab is |z| <= 0.2.
    ASSERT_NEAR(std::abs(s.n[2]), 1.0, 1e-6);
    EXPECT_FALSE(s.separates({0.5f, 0.5f, 0.9f}, 0.71f));  // reaches into the slab
    EXPECT_FALSE(s.separates({0.5f, 0.5f, 0.0f}, 0.0f));   // inside
    EXPECT_FALSE(s.separates({9.0f, 9.0f, 0.0f}, 0.0f));   // a slab is unbounded sideways
    EXPECT_TRUE(s.separates({0.5f, 0.5f, 0.9f}, 0.69f));   // above it
    EXPECT_TRUE(s.separates({0.5f, 0.5f, -0.9f}, 0.69f));  // below it
}

TEST(Slab, EmptyPointSetIsMarkedEmpty) {
    const Slab s = fit_slab({});
    EXPECT_LT(s.h, 0);
}

TEST(Slab, DegeneratePointSetsGiveAFiniteSlab) {
    const Slab one = fit_slab({{1, 2, 3}});
    EXPECT_GE(one.h, 0);
    EXPECT_FALSE(one.separates({1, 2, 3}, 0));
    const Slab line = fit_slab({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});
    EXPECT_TRUE(std::isfinite(line.n[0]) && std::isfinite(line.d) && std::isfinite(line.h));
    EXPECT_FALSE(line.separates({1, 1, 1}, 0));
}

} // namespace
} // namespace spt
