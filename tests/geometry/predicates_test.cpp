// Exact orientation predicates: filter against exact arithmetic, hard near-degenerate inputs.
#include "geometry/predicates.hpp"
#include <gtest/gtest.h>
#include <random>

namespace {

using spt::orient3d;
using V3 = Eigen::Vector3d;

// Coordinates k * 2^-20 with |k| < 2^30: exact in double, and the determinant
// of their differences is exact in 128-bit integers.
constexpr double kUnit = 1.0 / (1 << 20);

int sign_int128(const std::array<int64_t, 3>& a, const std::array<int64_t, 3>& b, const std::array<int64_t, 3>& c,
                const std::array<int64_t, 3>& d) {
    __int128 u[3], v[3], w[3];
    for (int i = 0; i < 3; ++i) u[i] = b[i] - a[i], v[i] = c[i] - a[i], w[i] = d[i] - a[i];
    const __int128 det = u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
                         u[2] * (v[0] * w[1] - v[1] * w[0]);
    return det > 0 ? 1 : det < 0 ? -1 : 0;
}

V3 to_double(const std::array<int64_t, 3>& k) { return V3(double(k[0]), double(k[1]), double(k[2])) * kUnit; }

TEST(Predicates, Orient3dNearlyCoplanarPointsMatchIntegerArithmetic) {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int64_t> coord(-(int64_t(1) << 29), int64_t(1) << 29);
    std::uniform_real_distribution<double> st(-2, 3);
    std::uniform_int_distribution<int> nudge(-2, 2);
    int zeros = 0, filtered_disagreements = 0;
    for (int it = 0; it < 20000; ++it) {
        std::array<int64_t, 3> a, b, c, d;
        for (int i = 0; i < 3; ++i) a[i] = coord(rng), b[i] = coord(rng), c[i] = coord(rng);
        const double s = st(rng), t = st(rng);
        // Half the cases on the plane exactly (integer combinations), half rounded near it.
        const bool on_plane = it % 2 == 0;
        const double ks = on_plane ? std::round(s) : s, kt = on_plane ? std::round(t) : t;
        const int wiggle = on_plane ? 0 : nudge(rng);
        for (int i = 0; i < 3; ++i)
            d[i] = int64_t(std::llround(double(a[i]) + ks * double(b[i] - a[i]) + kt * double(c[i] - a[i]))) + wiggle;
        const int want = sign_int128(a, b, c, d);
        zeros += want == 0;
        const int got = orient3d(to_double(a), to_double(b), to_double(c), to_double(d));
        ASSERT_EQ(got, want) << "iteration " << it;
        filtered_disagreements += spt::orient3d_exact(to_double(a), to_double(b), to_double(c), to_double(d)) != want;
    }
    EXPECT_EQ(filtered_disagreements, 0);
    EXPECT_GT(zeros, 0) << "the test should include exactly coplanar cases";
}

TEST(Predicates, Orient3dFarFromOriginKeepsTheSignOfATinyVolume) {
    // A point 1e-9 above a plane through points near 1e6: naive evaluation loses it.
    const V3 a(1e6, 1e6, 1e6), b(1e6 + 1, 1e6, 1e6), c(1e6, 1e6 + 1, 1e6);
    EXPECT_EQ(orient3d(a, b, c, V3(1e6 + 0.25, 1e6 + 0.25, 1e6 + 1.0 / (1 << 30))), 1);
    EXPECT_EQ(orient3d(a, b, c, V3(1e6 + 0.25, 1e6 + 0.25, 1e6 - 1.0 / (1 << 30))), -1);
    EXPECT_EQ(orient3d(a, b, c, V3(1e6 + 0.25, 1e6 + 0.25, 1e6)), 0);
}

TEST(Predicates, Orient2dCollinearPointsGiveZero) {
    EXPECT_EQ(spt::orient2d({0.1, 0.1}, {0.2, 0.2}, {0.30000000000000004, 0.30000000000000004}), 0);
    EXPECT_EQ(spt::orient2d({0, 0}, {1, 0}, {0.5, 1e-300}), 1);
    EXPECT_EQ(spt::orient2d({0, 0}, {1, 0}, {0.5, -1e-300}), -1);
}

} // namespace
