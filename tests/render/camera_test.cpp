// Cameras and viewports: fitting, documented orientations, zoom, quad tiling, projection to window pixels.
#include "spt/render/camera.hpp"
#include "spt/render/renderer.hpp"
#include <gtest/gtest.h>

using namespace spt::render;

namespace {

Eigen::Vector3f ndc(const Camera& c, float aspect, const Eigen::Vector3f& p) {
    const Eigen::Vector4f clip = c.projection_matrix(aspect) * c.view_matrix() * p.homogeneous();
    return clip.head<3>() / clip.w();
}

Bounds box() {
    Bounds b;
    b.add(Eigen::Vector3f(-1.0f, 0.5f, -2.0f));
    b.add(Eigen::Vector3f(3.0f, 2.5f, 0.5f));
    return b;
}

} // namespace

TEST(camera, fitted_views_keep_the_whole_box_in_view_and_depth) {
    const Bounds b = box();
    for (View v : {View::Top, View::Front, View::Side, View::Camera})
        for (float aspect : {1.0f, 2.0f, 0.5f}) {
            const Camera c = fit_camera(v, b);
            for (int i = 0; i < 8; ++i) {
                const Eigen::Vector3f corner((i & 1) ? b.max.x() : b.min.x(), (i & 2) ? b.max.y() : b.min.y(),
                                             (i & 4) ? b.max.z() : b.min.z());
                const Eigen::Vector3f n = ndc(c, aspect, corner);
                EXPECT_LE(n.cwiseAbs().maxCoeff(), 1.0f) << view_name(v) << " aspect " << aspect << " corner " << i;
            }
        }
}

TEST(camera, views_are_oriented_as_documented) {
    const Bounds b = box();
    const Eigen::Vector3f c = b.center();
    auto screen_delta = [&](View v, const Eigen::Vector3f& d) {
        const Camera cam = fit_camera(v, b);
        return Eigen::Vector3f(ndc(cam, 1, c + d) - ndc(cam, 1, c));
    };
    const Eigen::Vector3f X = Eigen::Vector3f::UnitX(), Y = Eigen::Vector3f::UnitY(), Z = Eigen::Vector3f::UnitZ();
    // Top: +X right, -Z up; +Y towards the eye (smaller depth).
    EXPECT_GT(screen_delta(View::Top, X).x(), 0);
    EXPECT_GT(screen_delta(View::Top, -Z).y(), 0);
    EXPECT_LT(screen_delta(View::Top, Y).z(), 0);
    // Front: +X right, +Y up, +Z towards the eye.
    EXPECT_GT(screen_delta(View::Front, X).x(), 0);
    EXPECT_GT(screen_delta(View::Front, Y).y(), 0);
    EXPECT_LT(screen_delta(View::Front, Z).z(), 0);
    // Side: -Z right, +Y up, +X towards the eye.
    EXPECT_GT(screen_delta(View::Side, -Z).x(), 0);
    EXPECT_GT(screen_delta(View::Side, Y).y(), 0);
    EXPECT_LT(screen_delta(View::Side, X).z(), 0);
    // Camera: looks down on the scene, +Y up on screen.
    const Camera cam = fit_camera(View::Camera, b);
    EXPECT_GT(cam.eye().y(), c.y());
    EXPECT_GT(screen_delta(View::Camera, 0.1f * Y).y(), 0);
}

TEST(camera, zoom_magnifies) {
    Camera c = fit_camera(View::Front, box());
    const Eigen::Vector3f p = box().center() + Eigen::Vector3f(0.5f, 0, 0);
    const float before = ndc(c, 1, p).x();
    c.zoom = 2;
    EXPECT_NEAR(ndc(c, 1, p).x() - ndc(c, 1, box().center()).x(), 2 * (before - 0.0f), 1e-4f);
}

TEST(camera, quad_viewports_tile_with_one_pixel_gaps) {
    for (auto [w, h] : {std::pair{256, 256}, std::pair{255, 100}, std::pair{640, 480}}) {
        const auto v = quad_viewports(w, h);
        // upper left, upper right, lower left, lower right
        EXPECT_EQ(v[0].x, 0);
        EXPECT_EQ(v[2].y, 0);
        EXPECT_EQ(v[0].x + v[0].width + 1, v[1].x);
        EXPECT_EQ(v[1].x + v[1].width, w);
        EXPECT_EQ(v[2].y + v[2].height + 1, v[0].y);
        EXPECT_EQ(v[0].y + v[0].height, h);
        EXPECT_EQ(v[3].x, v[1].x);
        EXPECT_EQ(v[3].y, 0);
    }
}

TEST(camera, project_gives_window_pixels) {
    const Bounds b = box();
    for (View v : {View::Top, View::Front, View::Side, View::Camera}) {
        const Camera c = fit_camera(v, b);
        const Eigen::Vector3f centre = c.project(c.target, 200, 100);
        EXPECT_NEAR(centre.x(), 100.0f, 1e-3f) << view_name(v);
        EXPECT_NEAR(centre.y(), 50.0f, 1e-3f) << view_name(v);
        EXPECT_GT(centre.z(), 0.0f);
        EXPECT_LT(centre.z(), 1.0f);
        // Screen up is up in window pixels; a point nearer the eye has a smaller depth.
        const Eigen::Vector3f up = c.project(c.target + 0.1f * c.up(), 200, 100);
        EXPECT_GT(up.y(), centre.y()) << view_name(v);
        EXPECT_NEAR(up.x(), centre.x(), 1e-3f) << view_name(v);
        EXPECT_LT(c.project(c.target + 0.1f * c.back(), 200, 100).z(), centre.z()) << view_name(v);
    }
}
