// triangle_gap against a dense sampling of both triangles: never above the sampled minimum, below
// it by no more than the sampling's spacing; triangles that meet answer 0 and a common point.
#include "geometry/tri_distance.hpp"
#include "geometry/tri_tri.hpp"
#include <gtest/gtest.h>
#include <random>

using namespace spt;
using V3 = Eigen::Vector3d;

namespace {

constexpr int kGrid = 48;

// Points of the triangle on a barycentric grid of kGrid steps a side.
std::vector<V3> grid(const V3& a, const V3& b, const V3& c) {
    std::vector<V3> out;
    for (int i = 0; i <= kGrid; ++i)
        for (int j = 0; i + j <= kGrid; ++j) {
            const double u = double(i) / kGrid, v = double(j) / kGrid;
            out.push_back(a + u * (b - a) + v * (c - a));
        }
    return out;
}

double longest_edge(const V3& a, const V3& b, const V3& c) {
    return std::max({(a - b).norm(), (b - c).norm(), (c - a).norm()});
}

// Distance of x to the triangle by its grid (an upper bound, loose by the grid spacing).
double sampled_gap(const std::vector<V3>& p, const std::vector<V3>& q) {
    double best = std::numeric_limits<double>::infinity();
    for (const V3& x : p)
        for (const V3& y : q) best = std::min(best, (x - y).squaredNorm());
    return std::sqrt(best);
}

V3 random_point(std::mt19937& rng, double spread) {
    std::uniform_real_distribution<double> u(-spread, spread);
    return {u(rng), u(rng), u(rng)};
}

} // namespace

TEST(TriangleGap, IsNeverAboveTheSampledMinimumNorBelowItByMoreThanTheGridSpacing) {
    std::mt19937 rng(3);
    int apart = 0;
    for (int trial = 0; trial < 150; ++trial) {
        const V3 a0 = random_point(rng, 1), a1 = random_point(rng, 1), a2 = random_point(rng, 1);
        const V3 shift = random_point(rng, 1.5);
        const V3 b0 = random_point(rng, 1) + shift, b1 = random_point(rng, 1) + shift, b2 = random_point(rng, 1) + shift;
        const TriangleGap g = triangle_gap(a0, a1, a2, b0, b1, b2);
        // The points are on their triangles and as far apart as the distance says.
        EXPECT_NEAR((triangle_closest_point(a0, a1, a2, g.p) - g.p).norm(), 0, 1e-12);
        EXPECT_NEAR((triangle_closest_point(b0, b1, b2, g.q) - g.q).norm(), 0, 1e-12);
        EXPECT_NEAR((g.p - g.q).norm(), g.distance, 1e-12);
        const double sampled = sampled_gap(grid(a0, a1, a2), grid(b0, b1, b2));
        const double spacing = (longest_edge(a0, a1, a2) + longest_edge(b0, b1, b2)) / kGrid;
        EXPECT_LE(g.distance, sampled + 1e-12) << trial;
        EXPECT_GE(g.distance, sampled - spacing) << trial;
        if (triangles_intersect(a0, a1, a2, b0, b1, b2)) {
            EXPECT_EQ(g.distance, 0) << trial;
        } else {
            EXPECT_GT(g.distance, 0) << trial;
            ++apart;
        }
    }
    EXPECT_GT(apart, 50);
}

TEST(TriangleGap, APiercingTriangleAnswersZeroAndAPointOnBoth) {
    // B's edge goes through A's interior while every corner and edge of either stays apart.
    const V3 a0(0, 0, 0), a1(4, 0, 0), a2(0, 4, 0);
    const V3 b0(1, 1, -1), b1(1, 1, 1), b2(1, 3, 5);
    const TriangleGap g = triangle_gap(a0, a1, a2, b0, b1, b2);
    EXPECT_EQ(g.distance, 0);
    EXPECT_NEAR((triangle_closest_point(a0, a1, a2, g.p) - g.p).norm(), 0, 1e-12);
    EXPECT_NEAR((triangle_closest_point(b0, b1, b2, g.p) - g.p).norm(), 0, 1e-12);
}

TEST(TriangleGap, ParallelEdgesAndCoplanarTrianglesGiveTheirGap) {
    // Parallel faces one above the other: the gap is the plane spacing.
    const TriangleGap stacked = triangle_gap(V3(0, 0, 0), V3(1, 0, 0), V3(0, 1, 0), V3(0.1, 0.1, 0.5), V3(0.6, 0.1, 0.5),
                                             V3(0.1, 0.6, 0.5));
    EXPECT_NEAR(stacked.distance, 0.5, 1e-15);
    // Coplanar, side by side: A's corner (1, 0) is 0.25 from B's upright edge.
    const TriangleGap side = triangle_gap(V3(0, 0, 0), V3(1, 0, 0), V3(0, 1, 0), V3(1.25, 0, 0), V3(1.25, 1, 0),
                                          V3(2, 0, 0));
    EXPECT_NEAR(side.distance, 0.25, 1e-15);
}

TEST(TriangleGap, AZeroAreaTriangleCountsAsItsEdges) {
    const V3 a0(0, 0, 0), a1(1, 0, 0), a2(0, 1, 0);
    const TriangleGap g = triangle_gap(a0, a1, a2, V3(0.2, 0.2, 1), V3(0.4, 0.2, 2), V3(0.6, 0.2, 3)); // a segment
    EXPECT_NEAR(g.distance, 1, 1e-15);
    EXPECT_NEAR((g.q - V3(0.2, 0.2, 1)).norm(), 0, 1e-15);
}
