// Off-screen contexts: backends, usage errors, core profile on llvmpipe, row order, determinism, drawing.
#include "scenes.hpp"
#include "spt/error.hpp"
#include "spt/render/offscreen.hpp"
#include "test_meshes.hpp"
#include <algorithm>
#include <gtest/gtest.h>

using namespace spt::render;
using spt::test::OffscreenRenderer;

namespace {

// Creates an egl renderer, or explains why this machine has none.
std::unique_ptr<OffscreenRenderer> try_egl(int w, int h, std::string* why) {
    try {
        return std::make_unique<OffscreenRenderer>("egl", w, h);
    } catch (const spt::Error& e) {
        *why = e.what();
        return nullptr;
    }
}

Frame empty_frame(Color background) {
    Frame f;
    f.grid = f.axes = false;
    f.background = background;
    return f;
}

} // namespace

TEST(offscreen, both_backends_are_built) {
    const auto names = offscreen_backends();
    ASSERT_FALSE(names.empty());
    EXPECT_EQ(names.front(), "osmesa");
    EXPECT_NE(std::find(names.begin(), names.end(), "egl"), names.end());
}

TEST(offscreen, unknown_backend_and_bad_size_are_usage_errors) {
    for (auto [backend, w, h] : {std::tuple{"vulkan", 16, 16}, std::tuple{"osmesa", 0, 16}, std::tuple{"osmesa", 16, 20000}}) {
        try {
            make_offscreen_context(backend, w, h);
            FAIL() << backend << " " << w << "x" << h;
        } catch (const spt::Error& e) {
            EXPECT_EQ(e.kind(), spt::ErrorKind::Usage) << e.what();
        }
    }
}

TEST(offscreen, osmesa_context_is_core_profile_on_llvmpipe) {
    auto ctx = make_offscreen_context("osmesa", 32, 16);
    EXPECT_EQ(ctx->width(), 32);
    EXPECT_EQ(ctx->height(), 16);
    EXPECT_EQ(ctx->gl_renderer().rfind("llvmpipe", 0), 0u) << ctx->gl_renderer();
    EXPECT_NE(ctx->gl_version().find("Core Profile"), std::string::npos) << ctx->gl_version();
}

TEST(offscreen, clears_to_the_background_and_reads_top_row_first) {
    OffscreenRenderer r("osmesa", 40, 30);
    // Blue everywhere, then red in the upper half (GL's y grows upwards).
    r.renderer->draw(empty_frame({0, 0, 1, 1}), Camera{}, Viewport{0, 0, 40, 30}, r.context->framebuffer());
    r.renderer->draw(empty_frame({1, 0, 0, 1}), Camera{}, Viewport{0, 15, 40, 15}, r.context->framebuffer());
    const Image im = r.context->read_pixels();
    ASSERT_EQ(im.width, 40);
    ASSERT_EQ(im.height, 30);
    for (int y : {0, 14})
        for (int x : {0, 39}) {
            EXPECT_EQ(im.pixel(x, y)[0], 255) << x << "," << y;
            EXPECT_EQ(im.pixel(x, y)[2], 0);
        }
    for (int y : {15, 29}) {
        EXPECT_EQ(im.pixel(0, y)[0], 0) << y;
        EXPECT_EQ(im.pixel(0, y)[2], 255) << y;
    }
}

TEST(offscreen, same_pixels_on_every_run) {
    std::vector<uint8_t> first;
    for (int run = 0; run < 2; ++run) {
        OffscreenRenderer r("osmesa", 128, 96);
        const std::vector<uint8_t> png = encode_png(r.quad(spt::test::collision_scene(*r.renderer)));
        if (run == 0) first = png;
        else EXPECT_EQ(png, first);
    }
}

TEST(offscreen, osmesa_and_egl_give_the_same_pixels) {
    std::string why;
    std::unique_ptr<OffscreenRenderer> egl = try_egl(160, 120, &why);
    if (!egl) GTEST_SKIP() << "EGL surfaceless is not available here: " << why;
    const Image from_egl = egl->quad(spt::test::collision_scene(*egl->renderer));
    egl.reset();
    OffscreenRenderer osmesa("osmesa", 160, 120);
    const Image from_osmesa = osmesa.quad(spt::test::collision_scene(*osmesa.renderer));
    EXPECT_EQ(from_egl.rgba, from_osmesa.rgba);
}

TEST(offscreen, renderer_draws_what_the_frame_holds) {
    OffscreenRenderer r("osmesa", 64, 64);
    const Frame blank = empty_frame({1, 1, 1, 1});
    Frame with_mesh = blank;
    MeshItem m;
    m.mesh = r.renderer->add_mesh(spt::test::torus(1.0, 0.35, 24, 12));
    with_mesh.meshes.push_back(m);
    const Bounds b = r.renderer->bounds(with_mesh);
    EXPECT_NEAR(b.max.x(), 1.35f, 1e-4f);
    EXPECT_NEAR(b.min.y(), -0.35f, 1e-4f);
    const Camera cam = fit_camera(View::Top, b);
    r.renderer->draw(with_mesh, cam, Viewport{0, 0, 64, 64}, r.context->framebuffer());
    const Image im = r.context->read_pixels();
    // The torus's hole shows the background; its ring does not.
    EXPECT_EQ(im.pixel(32, 32)[0], 255);
    EXPECT_LT(im.pixel(32 + 15, 32)[0], 250);
    // Removing the mesh leaves a blank image.
    r.renderer->remove_mesh(m.mesh);
    r.renderer->draw(blank, cam, Viewport{0, 0, 64, 64}, r.context->framebuffer());
    const Image after = r.context->read_pixels();
    EXPECT_TRUE(std::all_of(after.rgba.begin(), after.rgba.end(), [](uint8_t v) { return v == 255; }));
}

TEST(offscreen, sphere_items_draw_ranges_and_colour_overrides) {
    OffscreenRenderer r("osmesa", 64, 64);
    // Two spheres side by side along X, seen from the front.
    const SphereSetHandle set = r.renderer->add_spheres(
        {{{{-1, 0, 0}, 0.8f}, {0, 0, 1, 1}}, {{{1, 0, 0}, 0.8f}, {0, 0, 1, 1}}});
    EXPECT_EQ(r.renderer->sphere_count(set), 2u);
    Frame f = empty_frame({1, 1, 1, 1});
    SphereItem second;
    second.spheres = set;
    second.first = 1;
    second.count = 1;
    second.color = Color{1, 0, 0, 1};
    f.spheres.push_back(second);
    Bounds b;
    b.add(Eigen::Vector3f(-1.8f, -0.8f, -0.8f));
    b.add(Eigen::Vector3f(1.8f, 0.8f, 0.8f));
    r.renderer->draw(f, fit_camera(View::Front, b), Viewport{0, 0, 64, 64}, r.context->framebuffer());
    const Image im = r.context->read_pixels();
    const uint8_t* left = im.pixel(18, 32);
    const uint8_t* right = im.pixel(46, 32);
    EXPECT_EQ(left[0], 255) << "the first sphere is outside the range";
    EXPECT_GT(right[0], 100) << "the second sphere is drawn in the override colour";
    EXPECT_EQ(right[2], 0);
}
