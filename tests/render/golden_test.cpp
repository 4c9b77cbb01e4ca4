// Golden-image regression tests: ctest -R golden. Baselines in resources/golden/,
// thresholds and the update workflow in docs/rendering.md.
#include "golden.hpp"
#include "scenes.hpp"
#include <filesystem>
#include <gtest/gtest.h>

using namespace spt::render;
using spt::test::OffscreenRenderer;

namespace {

constexpr int kSize = 256;

} // namespace

TEST(golden, figure_top) {
    OffscreenRenderer r("osmesa", kSize, kSize);
    EXPECT_GOLDEN(r.view(spt::test::figure_scene(*r.renderer), View::Top), "figure_top");
}

TEST(golden, figure_front) {
    OffscreenRenderer r("osmesa", kSize, kSize);
    EXPECT_GOLDEN(r.view(spt::test::figure_scene(*r.renderer), View::Front), "figure_front");
}

TEST(golden, figure_side) {
    OffscreenRenderer r("osmesa", kSize, kSize);
    EXPECT_GOLDEN(r.view(spt::test::figure_scene(*r.renderer), View::Side), "figure_side");
}

TEST(golden, figure_camera) {
    OffscreenRenderer r("osmesa", kSize, kSize);
    EXPECT_GOLDEN(r.view(spt::test::figure_scene(*r.renderer), View::Camera), "figure_camera");
}

TEST(golden, quad_layout) {
    OffscreenRenderer r("osmesa", kSize, kSize);
    EXPECT_GOLDEN(r.quad(spt::test::figure_scene(*r.renderer)), "quad_layout");
}

TEST(golden, spheres_by_level) {
    OffscreenRenderer r("osmesa", kSize, kSize);
    EXPECT_GOLDEN(r.view(spt::test::level_spheres_scene(*r.renderer), View::Camera), "spheres_by_level");
}

TEST(golden, node_bounds) {
    OffscreenRenderer r("osmesa", kSize, kSize);
    EXPECT_GOLDEN(r.view(spt::test::node_bounds_scene(*r.renderer), View::Front), "node_bounds");
}

TEST(golden, node_highlighted_rest_dimmed) {
    OffscreenRenderer r("osmesa", kSize, kSize);
    EXPECT_GOLDEN(r.view(spt::test::node_dimmed_scene(*r.renderer), View::Front), "node_dimmed");
}

TEST(golden, collision_pairs) {
    OffscreenRenderer r("osmesa", kSize, kSize);
    size_t pairs = 0;
    const Frame f = spt::test::collision_scene(*r.renderer, &pairs);
    EXPECT_GT(pairs, 0u) << "the posed tori must overlap";
    std::cout << pairs << " colliding sphere pairs\n";
    EXPECT_GOLDEN(r.view(f, spt::test::collision_close_up(f, View::Camera)), "collision_pairs");
}

TEST(golden, wire_points_trail) {
    OffscreenRenderer r("osmesa", kSize, kSize);
    EXPECT_GOLDEN(r.view(spt::test::wire_trail_scene(*r.renderer), View::Camera), "wire_points_trail");
}

// The comparison must catch a changed image, and leave the evidence behind.
TEST(golden, comparison_detects_change) {
    OffscreenRenderer r("osmesa", kSize, kSize);
    const Image top = r.view(spt::test::figure_scene(*r.renderer), View::Top);
    ASSERT_TRUE(std::filesystem::exists(spt::test::golden_path("figure_front")));

    // A different view against a baseline fails, and writes the actual and diff images.
    const spt::test::GoldenOutcome wrong = spt::test::check_golden(top, "figure_front", /*allow_update=*/false);
    EXPECT_FALSE(wrong.passed);
    EXPECT_TRUE(std::filesystem::exists(wrong.actual_path)) << wrong.message;
    EXPECT_TRUE(std::filesystem::exists(wrong.diff_path)) << wrong.message;
    EXPECT_EQ(read_png(wrong.diff_path).width, kSize);

    // A small square (0.4% of the pixels) changed well past the threshold fails...
    Image changed = top;
    for (int y = 100; y < 116; ++y)
        for (int x = 100; x < 116; ++x) changed.pixel(x, y)[1] ^= 0x80;
    const CompareResult square = compare_images(changed, top);
    EXPECT_FALSE(square.passed) << square.summary();
    EXPECT_EQ(square.differing_pixels, 256u);
    // ...while a change within the channel threshold everywhere passes.
    Image nudged = top;
    for (size_t i = 0; i < nudged.rgba.size(); i += 4) nudged.rgba[i] = uint8_t(nudged.rgba[i] < 250 ? nudged.rgba[i] + 5 : 255);
    EXPECT_TRUE(compare_images(nudged, top).passed);
    // A render of the right view matches its baseline exactly on this machine's llvmpipe.
    const CompareResult same = compare_images(top, read_png(spt::test::golden_path("figure_top")));
    EXPECT_TRUE(same.passed) << same.summary();
}

TEST(golden, missing_baseline_fails) {
    const Image img = Image::filled(8, 8, 10, 20, 30);
    const spt::test::GoldenOutcome o = spt::test::check_golden(img, "no_such_golden_image", /*allow_update=*/false);
    EXPECT_FALSE(o.passed);
    EXPECT_NE(o.message.find("SPT_UPDATE_GOLDEN=1"), std::string::npos) << o.message;
    EXPECT_TRUE(std::filesystem::exists(o.actual_path));
}
