// Rounding of stored bounds (core/src/base/float_round.hpp).
#include "base/float_round.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace {

using spt::detail::next_up;
using spt::detail::round_half_away;
using spt::detail::round_up;

TEST(FloatRound, NextUpIsNextafterTowardsInfinityForEveryKindOfFloat) {
    const float inf = std::numeric_limits<float>::infinity();
    const float cases[] = {0.0f, -0.0f, 1.0f, -1.0f, std::numeric_limits<float>::denorm_min(),
                           -std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::min(),
                           -std::numeric_limits<float>::min(), std::numeric_limits<float>::max(),
                           -std::numeric_limits<float>::max(), inf, -inf, 3.5e-3f, -7.25e12f};
    for (float f : cases) EXPECT_EQ(next_up(f), std::nextafter(f, inf)) << f;
    EXPECT_TRUE(std::isnan(next_up(std::nanf(""))));
    std::mt19937 rng(7);
    std::uniform_int_distribution<uint32_t> bits;
    for (int i = 0; i < 100000; ++i) {
        const uint32_t b = bits(rng);
        float f;
        std::memcpy(&f, &b, sizeof f);
        if (std::isnan(f)) continue;
        const float a = next_up(f), e = std::nextafter(f, inf);
        ASSERT_EQ(std::memcmp(&a, &e, sizeof a), 0) << f;
    }
}

TEST(FloatRound, RoundUpHoldsItsValueAndNeverGivesADenormal) {
    // Zero (a flat patch's thickness) is exact in float and stays zero: products with it cost
    // nothing, where the least denormal made every one a microcode assist.
    EXPECT_EQ(round_up(0.0), 0.0f);
    const float least_normal = std::numeric_limits<float>::min();
    for (double r : {1e-320, 1e-45, 1e-40, 1.1e-38, double(least_normal)}) {
        const float f = round_up(r);
        EXPECT_GE(double(f), r) << r;
        EXPECT_EQ(std::fpclassify(f), FP_NORMAL) << r;
    }
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> exponent(-60, 30);
    for (int i = 0; i < 100000; ++i) {
        const double r = std::pow(10.0, exponent(rng));
        const float f = round_up(r);
        ASSERT_GE(double(f), r);
        ASSERT_EQ(std::fpclassify(f), FP_NORMAL) << r;
    }
}

TEST(FloatRound, RoundHalfAwayIsStdRoundOnFloatValuesOfEitherSignAndZeroOnNaN) {
    // Halves of either sign, -0, the snorm scales' ends and values one ulp beside a half: the
    // branch-free sign must round exactly as std::lround does.
    std::vector<float> cases = {0.0f, -0.0f, 0.5f, -0.5f, 1.5f, -1.5f, 2.5f, -2.5f, 126.5f, -126.5f, 127.0f, -127.0f,
                                32766.5f, -32766.5f, 32767.0f, -32767.0f, 1048575.5f, -1048575.5f};
    for (float h : {0.5f, 1.5f, 63.5f, 126.5f, 32766.5f})
        for (float s : {1.0f, -1.0f})
            cases.push_back(std::nextafter(s * h, 0.0f)), cases.push_back(std::nextafter(s * h, s * 1e9f));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int k = 0; k < 100000; ++k) cases.push_back(u(rng) * (k % 2 ? 127.0f : 32767.0f));
    for (float v : cases) EXPECT_EQ(round_half_away(double(v)), std::lround(v)) << v;
    EXPECT_EQ(round_half_away(std::numeric_limits<double>::quiet_NaN()), 0);
}

} // namespace
