// Keyframe sampling and clip time (core/src/anim/keyframes.cpp, pose.cpp).
#include "anim/keyframes.hpp"
#include "spt/animation.hpp"
#include <gtest/gtest.h>
#include <cmath>

namespace spt {
namespace {

Track<Eigen::Vector3d> two_keys(Interpolation how) {
    Track<Eigen::Vector3d> t;
    t.interpolation = how;
    t.times = {1.0, 3.0};
    t.values = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, -2, 8)};
    return t;
}

Eigen::Vector4d xyzw(const Eigen::Quaterniond& q) { return {q.x(), q.y(), q.z(), q.w()}; }

TEST(Keyframes, LinearTranslationLerpsBetweenKeys) {
    const auto t = two_keys(Interpolation::Linear);
    EXPECT_TRUE(detail::sample_vector(t, 1.5).isApprox(Eigen::Vector3d(1, -0.5, 2)));
    EXPECT_TRUE(detail::sample_vector(t, 2.0).isApprox(Eigen::Vector3d(2, -1, 4)));
}

TEST(Keyframes, TimesBeforeTheFirstKeyOrAfterTheLastHoldThatKey) {
    const auto t = two_keys(Interpolation::Linear);
    EXPECT_EQ(detail::sample_vector(t, -5.0), t.values[0]);
    EXPECT_EQ(detail::sample_vector(t, 3.0), t.values[1]);
    EXPECT_EQ(detail::sample_vector(t, 1e300), t.values[1]);
    EXPECT_EQ(detail::sample_vector(t, std::nan("")), t.values[0]);
}

TEST(Keyframes, StepHoldsTheEarlierKeyUntilTheNext) {
    const auto t = two_keys(Interpolation::Step);
    EXPECT_EQ(detail::sample_vector(t, 2.999), t.values[0]);
    EXPECT_EQ(detail::sample_vector(t, 3.0), t.values[1]);
}

TEST(Keyframes, CubicSplineIsGltfsHermiteWithTheKeysTangents) {
    auto t = two_keys(Interpolation::CubicSpline);
    t.in_tangents = {Eigen::Vector3d(9, 9, 9), Eigen::Vector3d(1, 0, -1)};
    t.out_tangents = {Eigen::Vector3d(2, 2, 0), Eigen::Vector3d(9, 9, 9)};
    // Half way (s = 0.5, span 2): (v0 + v1) / 2 + span / 8 * (b0 - a1).
    const Eigen::Vector3d mid = 0.5 * (t.values[0] + t.values[1]) + 0.25 * (t.out_tangents[0] - t.in_tangents[1]);
    EXPECT_TRUE(detail::sample_vector(t, 2.0).isApprox(mid, 1e-12));
    EXPECT_TRUE(detail::sample_vector(t, 1.0).isApprox(t.values[0]));
    EXPECT_TRUE(detail::sample_vector(t, 3.0).isApprox(t.values[1]));
}

TEST(Keyframes, RotationSlerpsAlongTheShorterArc) {
    Track<Eigen::Vector4d> r;
    r.times = {0, 1};
    const Eigen::Quaterniond a(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()));
    const Eigen::Quaterniond b(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()));
    r.values = {xyzw(a), -xyzw(b)}; // -b is the same rotation: the path must not go the long way
    const Eigen::Quaterniond q = detail::sample_rotation(r, 0.5);
    EXPECT_NEAR(q.angularDistance(Eigen::Quaterniond(Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitZ()))), 0, 1e-12);
}

TEST(Keyframes, CubicSplineRotationComesOutUnit) {
    Track<Eigen::Vector4d> r;
    r.interpolation = Interpolation::CubicSpline;
    r.times = {0, 1};
    r.values = {xyzw(Eigen::Quaterniond::Identity()), xyzw(Eigen::Quaterniond(Eigen::AngleAxisd(2, Eigen::Vector3d::UnitX())))};
    r.in_tangents = {Eigen::Vector4d::Zero(), Eigen::Vector4d(3, 0, 0, 1)};
    r.out_tangents = {Eigen::Vector4d(1, 2, 0, 0), Eigen::Vector4d::Zero()};
    for (double t : {0.1, 0.5, 0.9}) EXPECT_NEAR(detail::sample_rotation(r, t).norm(), 1, 1e-12);
}

TEST(Keyframes, MorphWeightsLerpPerTarget) {
    Track<std::vector<double>> w;
    w.times = {0, 2};
    w.values = {{0, 1}, {1, 0}};
    std::vector<double> out;
    detail::sample_weights(w, 0.5, 2, out);
    EXPECT_DOUBLE_EQ(out[0], 0.25);
    EXPECT_DOUBLE_EQ(out[1], 0.75);
}

TEST(ClipTime, LoopingWrapsNegativeAndLargeTimesIntoTheClip) {
    Clip c;
    c.duration = 2;
    EXPECT_DOUBLE_EQ(clip_time(c, 5.5), 1.5);
    EXPECT_DOUBLE_EQ(clip_time(c, -0.5), 1.5);
    EXPECT_DOUBLE_EQ(clip_time(c, 1, 2, 0.5), 0.5); // 0.5 + 2 * 1 = 2.5, wrapped
}

TEST(ClipTime, WithoutLoopTheEndsHold) {
    Clip c;
    c.duration = 2;
    EXPECT_DOUBLE_EQ(clip_time(c, 7, 1, 0, false), 2);
    EXPECT_DOUBLE_EQ(clip_time(c, -1, 1, 0, false), 0);
}

TEST(ClipTime, AClipOfOnePoseOrANonFiniteTimeGivesZero) {
    Clip c;
    EXPECT_EQ(clip_time(c, 3), 0);
    c.duration = 1;
    EXPECT_EQ(clip_time(c, INFINITY), 0);
    EXPECT_EQ(clip_time(c, NAN), 0);
}

} // namespace
} // namespace spt
