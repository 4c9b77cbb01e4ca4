// The sphere level's discs of two-sided samples: never apart when they share a point (with
// the normal's snorm8 tilt and float rounding), apart when only their balls overlap.
#include "geometry/sample_disc.hpp"
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <random>

namespace spt {
namespace {

using detail::LeafShape;
using detail::leaf_shapes_may_touch;
using V = Eigen::Vector3f;

LeafShape disc(const V& c, const V& n, float r) { return {c, n.normalized(), r, detail::kDiscHalfThickness * r, true}; }
LeafShape ball(const V& c, float r) { return {c, V::Zero(), r, 0, false}; }

// The normal as the compact tree stores it: each component rounded to 1/127.
V snorm8(const V& n) {
    V q;
    for (int k = 0; k < 3; ++k) q[k] = std::round(std::clamp(n[k], -1.0f, 1.0f) * 127.0f);
    return q.normalized();
}

V random_unit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    return V(g(rng), g(rng), g(rng)).normalized();
}

// A disc whose face holds x within 0.9 of the radius from the centre (the sampler's
// coverage), its normal stored as snorm8.
LeafShape disc_holding(const V& x, const V& n, float r, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0, 1);
    const V in_plane = (random_unit(rng) - n.dot(random_unit(rng)) * n).cross(n).normalized();
    return disc(x + 0.9f * r * u(rng) * in_plane, snorm8(n), r);
}

TEST(SampleDisc, ParallelSheetsCloserThanTwoRadiiAreApart) {
    const V up(0, 0, 1);
    EXPECT_FALSE(leaf_shapes_may_touch(disc(V(0, 0, 0), up, 1), disc(V(0.3f, 0, 0.5f), up, 1), 0));
    EXPECT_FALSE(leaf_shapes_may_touch(disc(V(0, 0, 0), up, 1), disc(V(0, 0, 0.1f), -up, 1), 0));
    // Within the discs' thickness they touch; grown by a pad they reach further.
    EXPECT_TRUE(leaf_shapes_may_touch(disc(V(0, 0, 0), up, 1), disc(V(0.3f, 0, 0.01f), up, 1), 0));
    EXPECT_TRUE(leaf_shapes_may_touch(disc(V(0, 0, 0), up, 1), disc(V(0.3f, 0, 0.5f), up, 1), 0.5f));
}

TEST(SampleDisc, CrossingPlanesWhoseChordsMissAreApart) {
    // B stands upright beside A's rim: its chord on A's plane lies outside A's disc.
    EXPECT_FALSE(leaf_shapes_may_touch(disc(V(0, 0, 0), V(0, 0, 1), 1), disc(V(1.2f, 0, 0), V(1, 0, 0), 1), 0));
    // Upright, its centre off A's plane: the balls overlap, the chords along y do not.
    const LeafShape a = disc(V(0.8f, 0, 0), V(0, 0, 1), 1), b = disc(V(0, 1.4f, -0.8f), V(1, 0, 0), 1);
    ASSERT_LT((a.c - b.c).norm(), 2.0f);
    EXPECT_FALSE(leaf_shapes_may_touch(a, b, 0));
    EXPECT_FALSE(leaf_shapes_may_touch(b, a, 0));
    EXPECT_TRUE(leaf_shapes_may_touch(a, disc(V(0, 1.0f, -0.8f), V(1, 0, 0), 1), 0));
    // Overlapping chords meet.
    EXPECT_TRUE(leaf_shapes_may_touch(disc(V(0, 0, 0), V(0, 0, 1), 1), disc(V(0, 1.5f, 0), V(1, 0, 1), 1), 0));
}

TEST(SampleDisc, DiscAgainstABallIsTheBallsReachOfTheThinDisc) {
    const LeafShape d = disc(V(0, 0, 0), V(0, 0, 1), 1);
    EXPECT_FALSE(leaf_shapes_may_touch(d, ball(V(0, 0, 0.6f), 0.5f), 0));       // above the middle
    EXPECT_TRUE(leaf_shapes_may_touch(d, ball(V(0, 0, 0.45f), 0.5f), 0));
    EXPECT_FALSE(leaf_shapes_may_touch(d, ball(V(1.4f, 0, 0.4f), 0.5f), 0));    // past the rim, above
    EXPECT_TRUE(leaf_shapes_may_touch(ball(V(1.4f, 0, 0.4f), 0.5f), d, 0.2f)); // either order, with a pad
    EXPECT_TRUE(leaf_shapes_may_touch(ball(V(0, 0, 5), 0.5f), ball(V(0, 0, 0), 0.5f), 0)); // two balls: the caller decides
}

// Any two discs holding a common point of their faces, at any angle and scale, with
// snorm8 normals and far from the origin: never apart. Balls holding it: never apart.
TEST(SampleDisc, ShapesHoldingACommonSurfacePointAreNeverApart) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1, 1);
    int tested = 0;
    for (float scale : {1e-4f, 1.0f, 1e3f})
        for (int it = 0; it < 20000; ++it) {
            const V x = scale * V(u(rng), u(rng), u(rng)) + V(scale * 10, 0, 0);
            const V na = random_unit(rng);
            // Nearly parallel faces are the hard case: half of them within a few degrees.
            const V nb = it % 2 ? random_unit(rng) : (na + 0.05f * random_unit(rng)).normalized();
            const float ra = scale * (0.01f + 0.1f * std::abs(u(rng))), rb = scale * (0.01f + 0.1f * std::abs(u(rng)));
            const LeafShape a = disc_holding(x, na, ra, rng), b = disc_holding(x, nb, rb, rng);
            ASSERT_TRUE(leaf_shapes_may_touch(a, b, 0)) << "scale " << scale << " case " << it;
            const V inside = x + 0.9f * rb * random_unit(rng);
            ASSERT_TRUE(leaf_shapes_may_touch(a, ball(inside, rb), 0)) << "scale " << scale << " case " << it;
            ++tested;
        }
    EXPECT_EQ(tested, 60000);
}

} // namespace
} // namespace spt
