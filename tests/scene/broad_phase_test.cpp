// The broad phase finds exactly the overlapping pairs (against all pairs), step after step.
#include "spt/broad_phase.hpp"
#include <gtest/gtest.h>
#include <random>

namespace {

using namespace spt;

// n spheres in a cube whose side grows with n so that each sphere meets a few others.
std::vector<BroadSphere> random_spheres(size_t n, std::mt19937& rng) {
    const double side = 6.0 * std::cbrt(double(n));
    std::uniform_real_distribution<double> pos(-side / 2, side / 2), rad(0.2, 2.5), u(0, 1);
    std::vector<BroadSphere> s(n);
    for (BroadSphere& b : s) {
        b.center = {pos(rng), pos(rng), pos(rng)};
        b.radius = rad(rng);
        b.is_static = u(rng) < 0.2;
    }
    return s;
}

TEST(BroadPhase, CandidatesAreExactlyTheOverlappingPairsFrom10To10000Objects) {
    std::mt19937 rng(7);
    for (size_t n : {10, 100, 1000, 10000}) {
        BroadPhase bp;
        std::vector<BroadSphere> s = random_spheres(n, rng);
        std::normal_distribution<double> step(0, 0.5);
        size_t total = 0;
        for (int frame = 0; frame < 4; ++frame) { // later frames reuse the previous order
            const std::vector<CandidatePair> expected = all_overlapping_pairs(s);
            EXPECT_EQ(bp.find(s), expected) << n << " objects, frame " << frame;
            total += expected.size();
            for (BroadSphere& b : s)
                if (!b.is_static) b.center += Eigen::Vector3d(step(rng), step(rng), step(rng));
        }
        EXPECT_GT(total, n / 4) << "the random scenes should overlap somewhere";
    }
}

TEST(BroadPhase, ClusteredAndCoincidentSpheresAndTouchingOnes) {
    std::vector<BroadSphere> s(50);
    for (size_t i = 0; i < s.size(); ++i) s[i].center = {0, double(i % 5), 0}, s[i].radius = 0.5;
    // Touching (distance exactly the sum of radii) is not overlapping, as in the queries.
    BroadPhase bp;
    const std::vector<CandidatePair> pairs = bp.find(s);
    for (const CandidatePair& p : pairs) EXPECT_EQ(s[p.a].center, s[p.b].center);
    EXPECT_EQ(pairs, all_overlapping_pairs(s));
    EXPECT_EQ(all_overlapping_pairs(s).size(), 5u * (10 * 9 / 2));
}

TEST(BroadPhase, StaticObjectsAreNeverPairedWithEachOther) {
    std::vector<BroadSphere> s(3);
    s[0].radius = s[1].radius = s[2].radius = 1;
    s[0].is_static = s[1].is_static = true;
    BroadPhase bp;
    EXPECT_EQ(bp.find(s), (std::vector<CandidatePair>{{0, 2}, {1, 2}}));
}

} // namespace
