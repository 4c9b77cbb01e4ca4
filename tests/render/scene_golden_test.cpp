// Golden frames of the bundled scenes, rendered by `spt render SCENE.json` (frame k = after step k).
#include "golden.hpp"
#include "run_command.hpp"
#include "spt/render/image.hpp"
#include <filesystem>
#include <gtest/gtest.h>
#include <unistd.h>

namespace {

using spt::test::q;

// Renders `frame` of resources/scenes/SCENE with `args` at 256 x 256 and reads it back.
spt::render::Image render_scene(const std::string& scene, int frame, const std::string& args) {
    const std::string out = std::string(SPT_BINARY_DIR) + "/test-tmp/scene-golden-" + std::to_string(::getpid()) +
                            "-" + scene + ".png";
    std::filesystem::create_directories(std::filesystem::path(out).parent_path());
    const auto r = spt::test::run_command(spt::test::spt_binary() + " render " +
                                          q(std::string(SPT_SOURCE_DIR) + "/resources/scenes/" + scene) +
                                          " --size 256x256 --frame " + std::to_string(frame) + " " + args + " -o " + q(out));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    spt::render::Image image = spt::render::read_png(out);
    std::filesystem::remove(out);
    return image;
}

TEST(golden, scene_fig8_response) {
    EXPECT_GOLDEN(render_scene("fig8.json", 31, "--overlay contacts,normals,ghost,trails,grid"), "scene_fig8");
}

TEST(golden, scene_walking_feet_strike) {
    EXPECT_GOLDEN(render_scene("walking.json", 50, "--view side --overlay contacts,normals,pairs,grid"),
                  "scene_walking");
}

// The skinned figure posed by its walk clip (`spt render MODEL --clip NAME --time T`): mid-stride
// with the sampling spheres that follow the surface, and a quarter cycle later as a mesh.
spt::render::Image render_clip(double time, const std::string& args) {
    const std::string out = std::string(SPT_BINARY_DIR) + "/test-tmp/clip-golden-" + std::to_string(::getpid()) + ".png";
    std::filesystem::create_directories(std::filesystem::path(out).parent_path());
    const auto r = spt::test::run_command(spt::test::spt_binary() + " render " +
                                          q(std::string(SPT_SOURCE_DIR) + "/resources/models/walking_figure.gltf") +
                                          " --clip walk --time " + std::to_string(time) + " --size 256x256 " + args +
                                          " -o " + q(out));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    spt::render::Image image = spt::render::read_png(out);
    std::filesystem::remove(out);
    return image;
}

// The walking figure's sampling spheres coloured by the steps each was in contact during walking.json
// (`spt render MODEL --color-by contacts --scene SCENE --object NAME`): the soles bright, the rest grey.
TEST(golden, contacts_walking_heat_map) {
    const std::string out = std::string(SPT_BINARY_DIR) + "/test-tmp/contacts-golden-" + std::to_string(::getpid()) + ".png";
    std::filesystem::create_directories(std::filesystem::path(out).parent_path());
    const std::string res = std::string(SPT_SOURCE_DIR) + "/resources/";
    const auto r = spt::test::run_command(
        spt::test::spt_binary() + " render " + q(res + "models/walking_figure.gltf") + " --tree " +
        q(res + "scenes/figure_walk.spt") + " --tree-name walk --color-by contacts --scene " +
        q(res + "scenes/walking.json") + " --object walker --view side --overlay spheres,grid --size 256x256 -o " + q(out));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_GOLDEN(spt::render::read_png(out), "contacts_walking");
    std::filesystem::remove(out);
}

TEST(golden, skinned_figure_walk_spheres) {
    EXPECT_GOLDEN(render_clip(0.125, "--view side --overlay spheres,grid"), "skinned_walk_0125");
}

TEST(golden, skinned_figure_walk_mesh) {
    EXPECT_GOLDEN(render_clip(0.375, "--view camera --overlay grid"), "skinned_walk_0375");
}

TEST(golden, scene_thin_wall_ccd) {
    EXPECT_GOLDEN(render_scene("thin_wall.json", 3, "--view top --overlay contacts,normals,trails"), "scene_thin_wall");
}

TEST(golden, scene_box_settled) {
    EXPECT_GOLDEN(render_scene("box_settle.json", 300, "--view front --overlay contacts,normals,grid"),
                  "scene_box_settle");
}

TEST(golden, scene_pile) {
    EXPECT_GOLDEN(render_scene("pile.json", 60, "--overlay grid,axes"), "scene_pile");
}

} // namespace

namespace {

// Scenes with effect dynamics, overlay manifold: each manifold point a dot (new this step or kept
// and warm-started, two colours) with its normal.

TEST(golden, scene_bounce_rebound) {
    // Step 90 is the one step the ball touches the floor: its new manifold points under it.
    EXPECT_GOLDEN(render_scene("bounce.json", 90, "--view front --overlay manifold,contacts,normals,trails,grid"),
                  "scene_bounce");
}

TEST(golden, scene_slope_holds_and_slides) {
    // After 2 s the box with friction 0.6 holds where it was put (kept points), the one with 0.2 has slid
    // down its trail (its points are new as they move).
    EXPECT_GOLDEN(render_scene("slope.json", 200, "--overlay manifold,trails,grid"), "scene_slope");
}

TEST(golden, scene_stack_standing) {
    EXPECT_GOLDEN(render_scene("stack.json", 500, "--view front --overlay manifold,grid"), "scene_stack");
}

TEST(golden, scene_balls_in_box_heaped) {
    EXPECT_GOLDEN(render_scene("balls_in_box.json", 300, "--overlay manifold,grid"), "scene_balls_in_box");
}

TEST(golden, scene_pile_dynamics_heaped) {
    // 1000 objects: frame 100 (1 s, the cube already slumped into a heap) keeps the render to seconds.
    EXPECT_GOLDEN(render_scene("pile_dynamics.json", 100, "--overlay manifold,grid"), "scene_pile_dynamics");
}

} // namespace
