// The CPU sphere splat against rays cast in double precision: which pixels a sphere covers, at
// what depth, which sphere wins, and that the number of threads changes nothing.
#include "sphere_splat.hpp"
#include "spt/render/camera.hpp"
#include <Eigen/LU>
#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace spt::render;
using spt::render::detail::SphereSplat;
using spt::render::detail::SplatItem;
using spt::render::detail::SplatSphere;

namespace {

constexpr int kW = 80, kH = 60;

SplatSphere sphere(double x, double y, double z, double r, uint8_t red = 200) {
    return SplatSphere{{float(x), float(y), float(z)}, float(r), {red, 100, 50, 255}};
}

Camera camera(View v) {
    Camera c;
    c.view = v;
    c.target = Eigen::Vector3f::Zero();
    c.radius = 1.0f;
    return c;
}

// What a ray through pixel (x, y) finds on sphere s (world = object frame), in double: the window
// depth of the first hit, or -1 if it misses or the hit is outside the depth range; `margin` gets
// how far the ray is from grazing (in units of r^2), so that pixels a rounding could flip are
// left out of the comparison, and `depth_tolerance` how far float sums may move the depth.
double cast(const Camera& cam, const SplatSphere& s, int x, int y, double& margin, double& depth_tolerance) {
    const Eigen::Matrix4d P = cam.projection_matrix(float(kW) / kH).cast<double>();
    const Eigen::Matrix4d V = cam.view_matrix().cast<double>();
    const Eigen::Matrix4d inv = P.inverse();
    const Eigen::Vector4d ndc_near(2.0 * (x + 0.5) / kW - 1, 2.0 * (y + 0.5) / kH - 1, -1, 1);
    const Eigen::Vector4d ndc_far(ndc_near.x(), ndc_near.y(), 1, 1);
    Eigen::Vector4d a = inv * ndc_near, b = inv * ndc_far;
    const Eigen::Vector3d o = a.head<3>() / a.w(), d = (b.head<3>() / b.w() - o).normalized();
    const Eigen::Vector3d c = (V * Eigen::Vector4d(s.center[0], s.center[1], s.center[2], 1)).head<3>();
    const double r = s.radius;
    const Eigen::Vector3d oc = o - c;
    const double bb = d.dot(oc), disc = bb * bb - (oc.squaredNorm() - r * r);
    margin = std::abs(disc) / (r * r);
    if (disc < 0) return -1;
    const double t = -bb - std::sqrt(disc);
    const auto depth_at = [&](double along) {
        const Eigen::Vector3d hit = o + along * d;
        const Eigen::Vector4d clip = P * Eigen::Vector4d(hit.x(), hit.y(), hit.z(), 1);
        return 0.5 * clip.z() / clip.w() + 0.5;
    };
    const double depth = depth_at(t);
    // Float sums place the hit to about a millionth of its distance from the eye (or, orthographic,
    // of the view's depth range): the depth may be off by what that moves it.
    const double reach = std::abs(t) + o.norm() + c.norm();
    depth_tolerance = std::max(2e-6, std::abs(depth_at(t + 1e-6 * reach) - depth));
    return depth >= 0 && depth <= 1 ? depth : -1;
}

SphereSplat splat_one(const Camera& cam, const SplatSphere& s, int threads = 1) {
    SphereSplat splat;
    splat.begin(kW, kH, cam.projection_matrix(float(kW) / kH), !cam.perspective());
    SplatItem item;
    item.spheres = &s;
    item.count = 1;
    item.model_view = cam.view_matrix();
    splat.add(item);
    splat.run(threads);
    return splat;
}

// Every pixel that is not within a rounding of grazing is covered exactly when the double ray hits,
// at the depth it hits; returns the number of covered pixels.
int expect_matches_rays(const Camera& cam, const SplatSphere& s) {
    const SphereSplat splat = splat_one(cam, s);
    int covered = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            double margin = 0, tolerance = 0;
            const double want = cast(cam, s, x, y, margin, tolerance);
            const float got = splat.depth()[size_t(y) * kW + size_t(x)];
            if (got <= 1) ++covered;
            if (margin < 1e-4) continue;
            if (want < 0) {
                EXPECT_EQ(got, SphereSplat::kEmpty) << "pixel " << x << "," << y;
            } else {
                EXPECT_NEAR(got, want, tolerance) << "pixel " << x << "," << y;
            }
        }
    return covered;
}

} // namespace

TEST(sphere_splat, OrthographicSphereCoversThePixelsWhoseRaysHitIt) {
    for (View v : {View::Top, View::Front, View::Side}) {
        const Camera cam = camera(v);
        EXPECT_GT(expect_matches_rays(cam, sphere(0.1, -0.2, 0.05, 0.3)), 100);
        EXPECT_GT(expect_matches_rays(cam, sphere(0.37, 0.11, -0.3, 0.04)), 0); // a few pixels across
        expect_matches_rays(cam, sphere(1.3, 0.9, 0.0, 0.5)); // cut by the view's edges
    }
}

TEST(sphere_splat, PerspectiveSphereCoversThePixelsWhoseRaysHitIt) {
    const Camera cam = camera(View::Camera);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> pos(-1.2, 1.2), rad(0.01, 0.4);
    int covered = 0;
    for (int i = 0; i < 40; ++i) covered += expect_matches_rays(cam, sphere(pos(rng), pos(rng), pos(rng), rad(rng)));
    EXPECT_GT(covered, 1000);
}

TEST(sphere_splat, SphereAcrossTheNearPlaneKeepsOnlyItsPixelsInTheDepthRange) {
    const Camera cam = camera(View::Camera);
    const Eigen::Vector3f eye = cam.eye();
    const Eigen::Vector3f towards = (cam.target - eye).normalized();
    // The near plane is 0.83 from the eye here (camera.cpp): a sphere 1 away of radius 0.28 has
    // its front before it and its outline (0.96 away) beyond it, so only a ring of it shows.
    const float near = (cam.eye() - cam.target).norm() - 2.5f * cam.radius;
    ASSERT_GT(near, 0.75f);
    ASSERT_LT(near, 0.9f);
    const Eigen::Vector3f c = eye + 1.0f * towards;
    const SplatSphere ring = sphere(c.x(), c.y(), c.z(), 0.28);
    EXPECT_GT(expect_matches_rays(cam, ring), 50);
    EXPECT_EQ(splat_one(cam, ring).depth()[size_t(kH / 2) * kW + kW / 2], SphereSplat::kEmpty);
    // The eye inside a sphere: nothing, as the GL impostor drew nothing.
    const SplatSphere around = sphere(eye.x(), eye.y(), eye.z(), 0.5);
    EXPECT_EQ(splat_one(cam, around).x1(), 0);
    // Wholly behind the eye: nothing.
    const Eigen::Vector3f behind = eye - 2.0f * towards;
    EXPECT_EQ(splat_one(cam, sphere(behind.x(), behind.y(), behind.z(), 0.3)).x1(), 0);
}

TEST(sphere_splat, NearerSphereWinsAndATieGoesToTheLaterOne) {
    const Camera cam = camera(View::Front); // looks down -z: larger z is nearer
    const SplatSphere spheres[] = {sphere(0, 0, 0, 0.3, 10), sphere(0, 0, 0, 0.3, 20), sphere(0.2, 0, 0.5, 0.3, 30)};
    SphereSplat splat;
    splat.begin(kW, kH, cam.projection_matrix(float(kW) / kH), true);
    SplatItem item;
    item.spheres = spheres;
    item.count = 3;
    item.model_view = cam.view_matrix();
    splat.add(item);
    splat.run(1);
    int tie = 0, nearer = 0;
    for (size_t i = 0; i < splat.depth().size(); ++i) {
        if (splat.depth()[i] > 1) continue;
        const int x = int(i % kW), y = int(i / kW);
        double m0 = 0, m2 = 0, tol = 0;
        const double d0 = cast(cam, spheres[0], x, y, m0, tol), d2 = cast(cam, spheres[2], x, y, m2, tol);
        if (m0 < 1e-4 || m2 < 1e-4) continue;
        const uint8_t red = uint8_t(splat.plain()[i] & 0xff);
        // Red of the winner, lit: compare the order of the unlit reds instead of exact values.
        if (d2 >= 0 && (d0 < 0 || d2 < d0)) {
            ++nearer;
            EXPECT_GT(red, 20 * 0.2) << "the nearer third sphere wins at " << x << "," << y;
            EXPECT_EQ(splat.plain()[i], splat.marked()[i]);
        } else if (d0 >= 0) {
            ++tie;
            // The second sphere equals the first: the later one's colour shows.
            const double unlit = red / 20.0;
            EXPECT_GT(unlit, 10 * 0.3 / 20.0 * 1.01) << x << "," << y;
        }
    }
    EXPECT_GT(nearer, 50);
    EXPECT_GT(tie, 20);
}

TEST(sphere_splat, MarksIdsAndFadeAreThoseTheShaderWrote) {
    const Camera cam = camera(View::Front);
    std::vector<SplatSphere> set = {sphere(-0.5, 0, 0, 0.2), sphere(0, 0, 0, 0.2), sphere(0.5, 0, 0, 0.2)};
    const std::vector<uint8_t> marks = {0, 0, 0, 255, 255, 255, 0, 0, 0}; // sphere 1 marked
    SphereSplat splat;
    splat.begin(kW, kH, cam.projection_matrix(float(kW) / kH), true);
    SplatItem item;
    item.spheres = set.data() + 1; // spheres 1 and 2 of the set
    item.count = 2;
    item.first_index = 1;
    item.model_view = cam.view_matrix();
    item.use_mark = true;
    item.mark_color = {0, 0, 1, 1};
    item.marks = marks.data();
    item.fade = 1.0f; // all the way to light grey
    splat.add(item);
    splat.run(1);
    const int cy = kH / 2;
    const auto at = [&](float world_x) {
        const Eigen::Vector3f w = cam.project({world_x, 0, 0}, kW, kH);
        return size_t(cy) * kW + size_t(w.x());
    };
    EXPECT_EQ(splat.depth()[at(-0.5f)], SphereSplat::kEmpty); // sphere 0 was not in the item
    const size_t one = at(0.0f), two = at(0.5f);
    EXPECT_EQ(splat.ids()[one], 2u | SphereSplat::kMarkedNow);
    EXPECT_EQ(splat.ids()[two], 3u);
    // Faded all the way: both colours are the same light grey, lit; the marked one stays blue-free.
    for (size_t i : {one, two}) {
        const uint32_t p = splat.plain()[i], m = splat.marked()[i];
        EXPECT_EQ(p, m);
        const int r = int(p & 0xff), b = int(p >> 16 & 0xff);
        EXPECT_NEAR(b, r * 0.87 / 0.84, 3);
        EXPECT_EQ(p >> 24, 255u);
    }
}

TEST(sphere_splat, ThreadCountChangesNothing) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> pos(-1, 1), rad(0.005, 0.08);
    std::vector<SplatSphere> set;
    for (int i = 0; i < 6000; ++i) set.push_back(sphere(pos(rng), pos(rng), pos(rng), rad(rng), uint8_t(i)));
    for (View v : {View::Front, View::Camera}) {
        const Camera cam = camera(v);
        std::vector<SphereSplat> runs;
        for (int threads : {1, 2, 3, 8}) {
            SphereSplat s;
            s.begin(kW * 4, kH * 4, cam.projection_matrix(float(kW) / kH), !cam.perspective());
            SplatItem a, b;
            a.spheres = set.data(), a.count = 4000, a.model_view = cam.view_matrix();
            b.spheres = set.data() + 4000, b.count = 2000, b.first_index = 4000, b.model_view = cam.view_matrix();
            b.use_mark = true;
            s.add(a);
            s.add(b);
            s.run(threads);
            runs.push_back(std::move(s));
        }
        for (size_t k = 1; k < runs.size(); ++k) {
            EXPECT_EQ(runs[k].depth(), runs[0].depth());
            EXPECT_EQ(runs[k].ids(), runs[0].ids());
            EXPECT_EQ(runs[k].x0(), runs[0].x0());
            EXPECT_EQ(runs[k].y1(), runs[0].y1());
            size_t same = 0, covered = 0;
            for (size_t i = 0; i < runs[0].depth().size(); ++i)
                if (runs[0].depth()[i] <= 1)
                    ++covered, same += runs[k].plain()[i] == runs[0].plain()[i] && runs[k].marked()[i] == runs[0].marked()[i];
            EXPECT_EQ(same, covered);
            EXPECT_GT(covered, 1000u);
        }
    }
}

TEST(sphere_splat, NonFiniteOrEmptySpheresDrawNothing) {
    const Camera cam = camera(View::Front);
    const float nan = std::nanf("");
    for (const SplatSphere& s : {sphere(0, 0, 0, 0), sphere(0, 0, 0, -1), sphere(nan, 0, 0, 0.3), sphere(0, 0, 0, nan),
                                 sphere(0, 0, 0, INFINITY), sphere(1e30, 0, 0, 0.3)})
        EXPECT_EQ(splat_one(cam, s).x1(), 0);
}
