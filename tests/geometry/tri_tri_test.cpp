// Triangle-triangle intersection: touching, coplanar, degenerate and random cases against a reference.
#include "geometry/tri_tri.hpp"
#include <gtest/gtest.h>
#include <array>
#include <random>

namespace {

using V3 = Eigen::Vector3d;
using I3 = std::array<long long, 3>;

// Independent oracle in exact integer arithmetic: two non-degenerate closed
// triangles meet iff an edge of one meets the other triangle.
I3 sub(const I3& a, const I3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
I3 cross(const I3& a, const I3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
long long dot(const I3& a, const I3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
int sgn(long long x) { return (x > 0) - (x < 0); }
int orient(const I3& a, const I3& b, const I3& c, const I3& d) { return sgn(dot(cross(sub(b, a), sub(c, a)), sub(d, a))); }
bool degenerate(const I3& a, const I3& b, const I3& c) { return cross(sub(b, a), sub(c, a)) == I3{0, 0, 0}; }

using I2 = std::array<long long, 2>;
int orient2(const I2& a, const I2& b, const I2& c) {
    return sgn((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}
bool on_seg(const I2& p, const I2& q, const I2& x) {
    return std::min(p[0], q[0]) <= x[0] && x[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= x[1] &&
           x[1] <= std::max(p[1], q[1]);
}
bool seg_seg2(const I2& a, const I2& b, const I2& c, const I2& d) {
    const int o1 = orient2(a, b, c), o2 = orient2(a, b, d), o3 = orient2(c, d, a), o4 = orient2(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && on_seg(a, b, c)) || (o2 == 0 && on_seg(a, b, d)) || (o3 == 0 && on_seg(c, d, a)) ||
           (o4 == 0 && on_seg(c, d, b));
}
bool in_tri2(const I2& x, const I2& a, const I2& b, const I2& c) {
    const int s1 = orient2(a, b, x), s2 = orient2(b, c, x), s3 = orient2(c, a, x);
    return !((s1 < 0 || s2 < 0 || s3 < 0) && (s1 > 0 || s2 > 0 || s3 > 0));
}

bool segment_meets_triangle(const I3& p, const I3& q, const I3& a, const I3& b, const I3& c) {
    const int sp = orient(a, b, c, p), sq = orient(a, b, c, q);
    if (sp * sq > 0) return false;
    if (sp == 0 && sq == 0) { // in the plane: drop the normal's largest axis
        const I3 n = cross(sub(b, a), sub(c, a));
        int drop = 0;
        for (int k = 1; k < 3; ++k)
            if (std::llabs(n[k]) > std::llabs(n[drop])) drop = k;
        const int i = drop == 0 ? 1 : 0, j = drop == 2 ? 1 : 2;
        auto pr = [&](const I3& x) { return I2{x[i], x[j]}; };
        if (in_tri2(pr(p), pr(a), pr(b), pr(c))) return true;
        return seg_seg2(pr(p), pr(q), pr(a), pr(b)) || seg_seg2(pr(p), pr(q), pr(b), pr(c)) ||
               seg_seg2(pr(p), pr(q), pr(c), pr(a));
    }
    const int s1 = orient(p, q, a, b), s2 = orient(p, q, b, c), s3 = orient(p, q, c, a);
    return !((s1 < 0 || s2 < 0 || s3 < 0) && (s1 > 0 || s2 > 0 || s3 > 0));
}

bool oracle(const std::array<I3, 3>& t, const std::array<I3, 3>& u) {
    for (int k = 0; k < 3; ++k) {
        if (segment_meets_triangle(t[k], t[(k + 1) % 3], u[0], u[1], u[2])) return true;
        if (segment_meets_triangle(u[k], u[(k + 1) % 3], t[0], t[1], t[2])) return true;
    }
    return false;
}

V3 d(const I3& x) { return V3(double(x[0]), double(x[1]), double(x[2])); }

TEST(TriTri, RandomGridTrianglesWithManyDegeneraciesAgreeWithIntegerOracle) {
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> c(0, 3);
    int hits = 0, coplanar = 0, tested = 0;
    for (int it = 0; it < 200000; ++it) {
        std::array<I3, 3> t, u;
        for (auto& x : t) x = {c(rng), c(rng), c(rng)};
        for (auto& x : u) x = {c(rng), c(rng), c(rng)};
        if (degenerate(t[0], t[1], t[2]) || degenerate(u[0], u[1], u[2])) continue;
        ++tested;
        const bool want = oracle(t, u);
        coplanar += orient(t[0], t[1], t[2], u[0]) == 0 && orient(t[0], t[1], t[2], u[1]) == 0 &&
                    orient(t[0], t[1], t[2], u[2]) == 0;
        hits += want;
        const bool got = spt::triangles_intersect(d(t[0]), d(t[1]), d(t[2]), d(u[0]), d(u[1]), d(u[2]));
        ASSERT_EQ(got, want) << "iteration " << it;
        ASSERT_EQ(spt::triangles_intersect(d(u[2]), d(u[0]), d(u[1]), d(t[1]), d(t[0]), d(t[2])), want)
            << "order and winding must not matter, iteration " << it;
    }
    EXPECT_GT(hits, tested / 10);
    EXPECT_LT(hits, tested);
    EXPECT_GT(coplanar, 100);
}

TEST(TriTri, TrianglesTouchingAtOneVertexIntersect) {
    EXPECT_TRUE(spt::triangles_intersect(V3(0, 0, 0), V3(1, 0, 0), V3(0, 1, 0), V3(1, 0, 0), V3(2, 0, 1), V3(2, 1, 1)));
}

TEST(TriTri, TrianglesSeparatedByOneUlpDoNotIntersect) {
    const double z = std::nextafter(0.1, 1.0);
    EXPECT_TRUE(spt::triangles_intersect(V3(0, 0, 0.1), V3(1, 0, 0.1), V3(0, 1, 0.1), V3(0.2, 0.2, 0.1),
                                         V3(0.3, 0.2, 1), V3(0.2, 0.3, 1)));
    EXPECT_FALSE(spt::triangles_intersect(V3(0, 0, 0.1), V3(1, 0, 0.1), V3(0, 1, 0.1), V3(0.2, 0.2, z),
                                          V3(0.3, 0.2, 1), V3(0.2, 0.3, 1)));
}

TEST(TriTri, ZeroAreaTriangleNeverIntersects) {
    EXPECT_FALSE(spt::triangles_intersect(V3(0, 0, 0), V3(1, 0, 0), V3(2, 0, 0), V3(0.5, -1, -1), V3(0.5, 1, -1),
                                          V3(0.5, 0, 1)));
}

} // namespace
