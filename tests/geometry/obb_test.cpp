// Oriented boxes hold every point after float rounding, near and far from the origin, and
// the separating-axis test never separates boxes that touch.
#include "geometry/obb.hpp"
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <random>

namespace spt {
namespace {

Eigen::Vector3d axis(const Obb& b, int k) { return {b.axis[k][0], b.axis[k][1], b.axis[k][2]}; }
Eigen::Vector3d centre(const Obb& b) { return {b.center[0], b.center[1], b.center[2]}; }

bool holds(const Obb& b, const Eigen::Vector3d& p) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(axis(b, k).dot(p - centre(b))) > double(b.half[k])) return false;
    return true;
}

TEST(Obb, FittedBoxHoldsEveryPointFarFromTheOrigin) {
    // A thin tilted rod 1000 units out: the box must follow it and hold each double point.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    const Eigen::Vector3d along = Eigen::Vector3d(1, -2, 3).normalized();
    const Eigen::Vector3d e1 = along.unitOrthogonal(), e2 = along.cross(e1);
    const Eigen::Vector3d origin(1000, -1000, 500);
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 500; ++i) pts.push_back(origin + 5 * u(rng) * along + 0.01 * u(rng) * e1 + 0.002 * u(rng) * e2);
    const Obb b = fit_obb(pts);
    float longest = 0, thinnest = 1e9f;
    for (float h : b.half) longest = std::max(longest, h), thinnest = std::min(thinnest, h);
    EXPECT_GT(longest, 4.9f);
    EXPECT_LT(thinnest, 0.0021f + 1e-4f); // found the thin directions
    for (const auto& p : pts) EXPECT_TRUE(holds(b, p));
}

// Random pairs of boxes: whenever the test separates them, no point of one is in the other
// (checked on a dense set of points of each box, in double).
TEST(Obb, SeparatingAxisTestNeverSeparatesBoxesThatTouch) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    int separated = 0, touching = 0;
    for (int it = 0; it < 400; ++it) {
        auto random_box = [&] {
            std::vector<Eigen::Vector3d> pts;
            const Eigen::Quaterniond q = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized();
            const Eigen::Vector3d size(0.05 + std::abs(u(rng)), 0.05 + std::abs(u(rng)), 0.01 + 0.1 * std::abs(u(rng)));
            for (int i = 0; i < 60; ++i) pts.push_back(q * Eigen::Vector3d(size.x() * u(rng), size.y() * u(rng), size.z() * u(rng)));
            return std::make_pair(fit_obb(pts), pts);
        };
        const auto [a, pa] = random_box();
        const auto [b, pb] = random_box();
        const Eigen::Quaterniond q = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized();
        const Eigen::Vector3d t(1.5 * u(rng), 1.5 * u(rng), 1.5 * u(rng));
        const bool disjoint = obbs_disjoint(a, b, q.toRotationMatrix().cast<float>(), t.cast<float>(), 1e-5f);
        // Points of B's box (its corners and a grid) placed in A's frame, tested against A's box.
        bool overlap = false;
        for (int i = 0; i <= 8 && !overlap; ++i)
            for (int j = 0; j <= 8 && !overlap; ++j)
                for (int k = 0; k <= 8 && !overlap; ++k) {
                    const Eigen::Vector3d local = centre(b) + (i / 4.0 - 1) * b.half[0] * axis(b, 0) +
                                                  (j / 4.0 - 1) * b.half[1] * axis(b, 1) + (k / 4.0 - 1) * b.half[2] * axis(b, 2);
                    overlap = holds(a, q * local + t);
                }
        if (overlap) {
            ++touching;
            EXPECT_FALSE(disjoint) << "pair " << it << " overlaps but was separated";
        }
        separated += disjoint;
    }
    EXPECT_GT(separated, 100);
    EXPECT_GT(touching, 20);
}

TEST(Obb, ParallelBoxesFaceToFaceAreSeparatedByTheGapAlone) {
    // Two flat plates, one above the other: separated at a gap of 1e-3, not at -1e-3.
    std::vector<Eigen::Vector3d> plate;
    for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0}) plate.push_back({x, y, 0});
    const Obb a = fit_obb(plate), b = fit_obb(plate);
    const Eigen::Matrix3f I = Eigen::Matrix3f::Identity();
    EXPECT_TRUE(obbs_disjoint(a, b, I, {0.5f, 0.3f, 1e-3f}, 1e-5f));
    EXPECT_FALSE(obbs_disjoint(a, b, I, {0.5f, 0.3f, 0.0f}, 1e-5f));
}

// A tree node stores two axes and rebuilds the third: it must be the axis the extents were
// measured along, bit for bit.
TEST(Obb, ThirdAxisIsTheFloatCrossProductOfTheFirstTwo) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int it = 0; it < 50; ++it) {
        std::vector<Eigen::Vector3d> pts;
        for (int i = 0; i < 12; ++i) pts.push_back({100 + u(rng), 3 * u(rng), 0.1 * u(rng)});
        const Obb b = fit_obb(pts);
        const Eigen::Vector3f w = third_axis(b.axis[0], b.axis[1]);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(b.axis[2][k], w[k]);
        for (const auto& p : pts) EXPECT_TRUE(holds(b, p));
    }
}

TEST(Obb, EmptyAndDegeneratePointSets) {
    const Obb empty = fit_obb({});
    EXPECT_TRUE(obbs_disjoint(empty, empty, Eigen::Matrix3f::Identity(), Eigen::Vector3f::Zero(), 0));
    const Obb one = fit_obb({{1, 2, 3}});
    EXPECT_TRUE(holds(one, {1, 2, 3}));
    EXPECT_FALSE(obbs_disjoint(one, one, Eigen::Matrix3f::Identity(), Eigen::Vector3f::Zero(), 0));
    const Obb line = fit_obb({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});
    for (float h : line.half) EXPECT_TRUE(std::isfinite(h));
    EXPECT_TRUE(holds(line, {1, 1, 1}));
}

TEST(Obb, AnAxisAlignedFlatPatchIsExactlyZeroThickNotADenormalThick) {
    // A wall of an architectural mesh: its box's thinnest extent is 0, which float holds exactly.
    const std::vector<Eigen::Vector3d> wall = {{0, 0, 5}, {4, 0, 5}, {4, 3, 5}, {0, 3, 5}, {2, 1, 5}};
    const Obb b = fit_obb(wall);
    int zero = 0;
    for (float h : b.half) {
        EXPECT_NE(std::fpclassify(h), FP_SUBNORMAL);
        zero += h == 0;
    }
    EXPECT_EQ(zero, 1);
    for (const auto& p : wall) EXPECT_TRUE(holds(b, p));
    // Two such walls in one plane still meet; one a hair above does not.
    EXPECT_FALSE(obbs_disjoint(b, b, Eigen::Matrix3f::Identity(), Eigen::Vector3f::Zero(), 0));
    EXPECT_TRUE(obbs_disjoint(b, b, Eigen::Matrix3f::Identity(), Eigen::Vector3f(0, 0, 1e-3f), 0));
}

} // namespace
} // namespace spt
