// `spt render` as a user runs it: the real binary, real files, exit codes.
#include "spt/convert.hpp"
#include "spt/render/image.hpp"
#include "run_command.hpp"
#include <unistd.h>
#include "test_meshes.hpp"
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <sys/wait.h>

namespace fs = std::filesystem;
using spt::render::Image;

namespace {

struct CliRun {
    int code = -1;
    std::string err;
    std::string out;
};

class RenderCli : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::path(SPT_BINARY_DIR) / "test-output" / "render-cli" / info->name();
        fs::remove_all(dir);
        fs::create_directories(dir);
        figure = (dir / "figure.obj").string();
        spt::test::write_obj(spt::test::box_figure(), figure);
    }

    // Runs `spt ARGS` in the test directory with environment assignments `env`;
    // captures exit code, stdout and stderr.
    CliRun spt(const std::string& args, const std::string& env = "") {
        const std::string out = (dir / "stdout.txt").string(), err = (dir / "stderr.txt").string();
        const std::string cmd = "cd '" + dir.string() + "' && " + env + " '" + std::string(SPT_BINARY_DIR) + "/cli/spt' " + args +
                                " >'" + out + "' 2>'" + err + "'";
        const int status = std::system(cmd.c_str());
        CliRun r;
        r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        r.out = slurp(out);
        r.err = slurp(err);
        return r;
    }

    static std::string slurp(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }

    fs::path dir;
    std::string figure;
};

bool has_two_colours(const Image& im) {
    for (size_t i = 4; i < im.rgba.size(); i += 4)
        if (im.rgba[i] != im.rgba[0] || im.rgba[i + 1] != im.rgba[1] || im.rgba[i + 2] != im.rgba[2]) return true;
    return false;
}

TEST_F(RenderCli, mesh_alone_needs_only_an_output) {
    const CliRun r = spt("render figure.obj -o out.png");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    const Image im = spt::render::read_png((dir / "out.png").string());
    EXPECT_EQ(im.width, 512);
    EXPECT_EQ(im.height, 512);
    EXPECT_TRUE(has_two_colours(im));
}

TEST_F(RenderCli, same_input_gives_byte_identical_png) {
    const std::string args = "render figure.obj --view quad --overlay spheres,bounds,grid,axes --size 200x150";
    ASSERT_EQ(spt(args + " -o a.png").code, 0);
    ASSERT_EQ(spt(args + " -o b.png").code, 0);
    const std::string a = slurp(dir / "a.png"), b = slurp(dir / "b.png");
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, b);
}

TEST_F(RenderCli, thread_count_and_driver_choice_do_not_change_the_bytes) {
    const std::string args = "render figure.obj --view quad --overlay spheres,node --node 3 --size 160x120";
    ASSERT_EQ(spt(args + " -o a.png").code, 0);
    ASSERT_EQ(spt(args + " -o b.png", "LP_NUM_THREADS=1").code, 0);
    // The off-screen backends pin llvmpipe whatever the environment asks for.
    ASSERT_EQ(spt(args + " -o c.png", "LP_NUM_THREADS=3 GALLIUM_DRIVER=softpipe").code, 0);
    EXPECT_EQ(slurp(dir / "a.png"), slurp(dir / "b.png"));
    EXPECT_EQ(slurp(dir / "a.png"), slurp(dir / "c.png"));
}

TEST_F(RenderCli, help_lists_the_options) {
    const CliRun r = spt("render --help");
    EXPECT_EQ(r.code, 0);
    for (const char* opt : {"--tree", "--view", "--size", "--frames", "--backend", "--overlay", "Exit codes"})
        EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

TEST_F(RenderCli, bad_arguments_exit_1) {
    for (const char* args :
         {"render figure.obj", "render figure.obj --view diagonal -o x.png", "render figure.obj --size 0x10 -o x.png",
          "render figure.obj --size 64 -o x.png", "render figure.obj --size 64xabc -o x.png",
          "render figure.obj --frames 5:2 -o x{frame}.png", "render figure.obj --frames 1-3 -o x{frame}.png",
          "render figure.obj --frame 1 --frames 1:2 -o x{frame}.png", "render figure.obj --frames 1:3 -o x.png",
          "render figure.obj --overlay spheres,bogus -o x.png", "render figure.obj --overlay none,grid -o x.png",
          "render figure.obj --backend vulkan -o x.png", "render figure.obj --overlay bounds --node 99999 -o x.png",
          "render figure.obj --mesh-opacity 2 -o x.png", "render figure.obj --mesh-opacity nan -o x.png",
          "render figure.obj --mesh-opacity inf -o x.png"}) {
        const CliRun r = spt(args);
        EXPECT_EQ(r.code, 1) << args << "\n" << r.err;
        EXPECT_FALSE(r.err.empty()) << args;
        EXPECT_FALSE(fs::exists(dir / "x.png")) << args;
    }
}

// Linux would grant the allocations of a render larger than the memory there is and kill the
// process when it touched them: such a size is refused up front. An address-space limit
// (ulimit -v, counted like available memory) makes the case the same on every machine.
TEST_F(RenderCli, size_beyond_the_memory_there_is_exits_1_before_any_work) {
    if (spt::test::kAddressSanitizer)
        GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space and cannot run under ulimit -v";
    const std::string limit = "ulimit -v 2500000 &&"; // about 2.4 GiB; 8192x8192 needs about 6
    const CliRun big = spt("render figure.obj --size 8192x8192 -o x.png", limit);
    EXPECT_EQ(big.code, 1) << big.err;
    EXPECT_NE(big.err.find("--size 8192x8192 needs about 6.00 GiB"), std::string::npos) << big.err;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    const CliRun small = spt("render figure.obj --size 64x64 -o y.png", limit);
    EXPECT_EQ(small.code, 0) << small.err;
    EXPECT_TRUE(fs::exists(dir / "y.png"));
}

TEST_F(RenderCli, broken_input_exits_2_naming_the_file) {
    std::ofstream(dir / "junk.obj") << "this is not a mesh\n";
    std::ofstream(dir / "junk.spt") << "SPTREE and then nothing useful";
    for (const char* input : {"junk.obj", "missing.obj", "junk.spt"}) {
        const CliRun r = spt(std::string("render ") + input + " -o x.png");
        EXPECT_EQ(r.code, 2) << input << "\n" << r.err;
        EXPECT_NE(r.err.find(input), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir / "x.png"));
    }
}

TEST_F(RenderCli, tree_of_another_mesh_exits_2) {
    spt::test::write_obj(spt::test::torus(1, 0.35, 24, 12), (dir / "torus.obj").string());
    ASSERT_EQ(spt("convert torus.obj -o torus.spt -q").code, 0);
    const CliRun r = spt("render figure.obj --tree torus.spt --overlay spheres -o x.png");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("torus.spt"), std::string::npos) << r.err;
}

TEST_F(RenderCli, tree_file_and_spt_input) {
    ASSERT_EQ(spt("convert figure.obj -o figure.spt -q").code, 0);
    const CliRun with_tree = spt("render figure.obj --tree figure.spt --overlay spheres,node --node 2 -o a.png");
    ASSERT_EQ(with_tree.code, 0) << with_tree.err;
    // The tree from the file is the one make_document builds by default, so the image
    // is the same as when the tree is built on the fly.
    ASSERT_EQ(spt("render figure.obj --overlay spheres,node --node 2 -o b.png").code, 0);
    EXPECT_EQ(slurp(dir / "a.png"), slurp(dir / "b.png"));
    const CliRun spt_only = spt("render figure.spt --size 128x128 -o c.png");
    ASSERT_EQ(spt_only.code, 0) << spt_only.err;
    EXPECT_TRUE(has_two_colours(spt::render::read_png((dir / "c.png").string())));
    EXPECT_EQ(spt("render figure.spt --tree figure.spt -o d.png").code, 1);
    EXPECT_EQ(spt("render figure.obj --tree figure.spt --tree-name nope --overlay spheres -o d.png").code, 1);
}

TEST_F(RenderCli, spt_without_trees_exits_2) {
    // From the file as written (OBJ text rounds the coordinates), so the hash matches.
    spt::SptDocument doc = spt::make_document(spt::import_mesh(figure).mesh);
    doc.trees.clear();
    spt::save_spt(doc, (dir / "empty.spt").string());
    for (const char* args : {"render empty.spt -o x.png", "render figure.obj --tree empty.spt -o x.png"}) {
        const CliRun r = spt(args);
        EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
        EXPECT_NE(r.err.find("empty.spt: holds no sampling tree"), std::string::npos) << r.err;
    }
}

TEST_F(RenderCli, unwritable_output_exits_3) {
    // A folder cannot be made under a file.
    const CliRun r = spt("render figure.obj -o figure.obj/dir/out.png");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_NE(r.err.find("figure.obj/dir/out.png"), std::string::npos) << r.err;
}

TEST_F(RenderCli, frames_go_into_a_folder_made_for_them) {
    const CliRun r = spt("render figure.obj --size 64x64 --frames 0:1 -o 'new/frames/f{frame}.png'");
    ASSERT_EQ(r.code, 0) << r.err;
    for (int f : {0, 1}) EXPECT_TRUE(fs::exists(dir / "new" / "frames" / ("f" + std::to_string(f) + ".png"))) << f;
}

TEST_F(RenderCli, frames_number_the_outputs) {
    const CliRun r = spt("render figure.obj --size 64x64 --frames 2:4 -o 'f{frame}.png'");
    ASSERT_EQ(r.code, 0) << r.err;
    for (int f : {2, 3, 4}) EXPECT_TRUE(fs::exists(dir / ("f" + std::to_string(f) + ".png"))) << f;
    EXPECT_FALSE(fs::exists(dir / "f1.png"));
    EXPECT_FALSE(fs::exists(dir / "f5.png"));
    // A static mesh looks the same in every frame.
    EXPECT_EQ(slurp(dir / "f2.png"), slurp(dir / "f4.png"));
    ASSERT_EQ(spt("render figure.obj --size 64x64 --frame 7 -o 'g{frame}.png'").code, 0);
    EXPECT_TRUE(fs::exists(dir / "g7.png"));
}

TEST_F(RenderCli, egl_backend_writes_the_same_bytes) {
    ASSERT_EQ(spt("render figure.obj --size 96x96 --overlay spheres,grid -o o.png").code, 0);
    const CliRun r = spt("render figure.obj --size 96x96 --overlay spheres,grid --backend egl -o e.png");
    if (r.code == 1 && r.err.find("egl") != std::string::npos) GTEST_SKIP() << "EGL unavailable: " << r.err;
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(slurp(dir / "o.png"), slurp(dir / "e.png"));
}

// Scenes: one PNG a frame, overlays a scene needs refused for meshes.
TEST(RenderSceneCli, FramesAreWrittenOneAPngAndSceneOverlaysNeedAScene) {
    const std::string dir = std::string(SPT_BINARY_DIR) + "/test-tmp/render-scene-" + std::to_string(::getpid());
    std::filesystem::create_directories(dir);
    const std::string scene = std::string(SPT_SOURCE_DIR) + "/resources/scenes/thin_wall.json";
    auto r = spt::test::run_command(spt::test::spt_binary() + " render " + spt::test::q(scene) +
                                    " --size 64x64 --frames 0:2 --overlay contacts,normals,ghost,trails -o " +
                                    spt::test::q(dir + "/f{frame}.png"));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    for (int f = 0; f <= 2; ++f) EXPECT_TRUE(std::filesystem::exists(dir + "/f" + std::to_string(f) + ".png"));
    // Frame 0 (the initial state) and frame 2 differ: the ball moved.
    EXPECT_NE(spt::render::read_png(dir + "/f0.png").rgba, spt::render::read_png(dir + "/f2.png").rgba);
    r = spt::test::run_command(spt::test::spt_binary() + " render " +
                               spt::test::q(std::string(SPT_SOURCE_DIR) + "/resources/meshes/box.ply") +
                               " --overlay contacts -o " + spt::test::q(dir + "/m.png"));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    // Contact manifolds exist only with effect dynamics: a scene without it is refused, naming both,
    // rather than rendered with the overlay silently empty.
    r = spt::test::run_command(spt::test::spt_binary() + " render " + spt::test::q(scene) +
                               " --size 64x64 --overlay manifold -o " + spt::test::q(dir + "/m.png"));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("thin_wall.json"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("'manifold'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("'dynamics'"), std::string::npos) << r.output;
    std::filesystem::remove_all(dir);
}

} // namespace

namespace {

const std::string kFigureGltf = std::string(SPT_SOURCE_DIR) + "/resources/models/walking_figure.gltf";

// Two times of the walk are two pictures; the clip's start is its bind pose's picture only when
// the clip starts there, so the test compares times with each other.
TEST_F(RenderCli, a_clip_poses_the_mesh_at_the_time_asked) {
    const std::string base = "render '" + kFigureGltf + "' --view side --size 128x128 --clip walk";
    ASSERT_EQ(spt(base + " --time 0.1 -o a.png").code, 0);
    ASSERT_EQ(spt(base + " --time 0.1 -o b.png").code, 0);
    ASSERT_EQ(spt(base + " --time 0.35 -o c.png").code, 0);
    EXPECT_EQ(slurp(dir / "a.png"), slurp(dir / "b.png"));
    EXPECT_NE(slurp(dir / "a.png"), slurp(dir / "c.png"));
    // Past the clip's end the pose holds at its end (1 s).
    ASSERT_EQ(spt(base + " --time 1 -o end.png").code, 0);
    ASSERT_EQ(spt(base + " --time 5 -o later.png").code, 0);
    EXPECT_EQ(slurp(dir / "end.png"), slurp(dir / "later.png"));
}

TEST_F(RenderCli, clip_options_refuse_what_they_cannot_pose) {
    const CliRun no_clip = spt("render '" + kFigureGltf + "' --time 0.5 -o x.png");
    EXPECT_EQ(no_clip.code, 1);
    EXPECT_NE(no_clip.err.find("--time needs --clip"), std::string::npos) << no_clip.err;
    const CliRun missing = spt("render '" + kFigureGltf + "' --clip run -o x.png");
    EXPECT_EQ(missing.code, 1);
    EXPECT_NE(missing.err.find("0 'walk', 1 'idle'"), std::string::npos) << missing.err;
    const CliRun bounds = spt("render '" + kFigureGltf + "' --clip walk --overlay bounds -o x.png");
    EXPECT_EQ(bounds.code, 1);
    const CliRun nan = spt("render '" + kFigureGltf + "' --clip walk --time nan -o x.png");
    EXPECT_EQ(nan.code, 1);
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

// --color-by contacts: the scene's motion recorded with this tree colours its spheres; the legend
// goes to stdout. Wrong use is a usage error (1), a scene or object that is not there bad input (2).
TEST_F(RenderCli, color_by_contacts_runs_the_motion_and_refuses_wrong_use) {
    const std::string torus = std::string(SPT_SOURCE_DIR) + "/resources/meshes/torus.obj";
    const std::string fig8 = std::string(SPT_SOURCE_DIR) + "/resources/scenes/fig8.json";
    const std::string base = "render '" + torus + "' --overlay spheres --size 64x64 --color-by contacts ";
    const CliRun ok = spt(base + "--scene '" + fig8 + "' --object torus --motion-steps 40 -o heat.png");
    ASSERT_EQ(ok.code, 0) << ok.err;
    EXPECT_NE(ok.out.find("object torus, 40 steps"), std::string::npos) << ok.out;
    EXPECT_NE(ok.out.find("0 steps: "), std::string::npos) << ok.out;
    EXPECT_TRUE(fs::exists(dir / "heat.png"));

    const CliRun no_scene = spt(base + "-o x.png");
    EXPECT_EQ(no_scene.code, 1);
    EXPECT_NE(no_scene.err.find("--color-by contacts needs --scene"), std::string::npos) << no_scene.err;
    const CliRun no_object = spt(base + "--scene '" + fig8 + "' -o x.png");
    EXPECT_EQ(no_object.code, 1);
    const CliRun scene_alone = spt("render '" + torus + "' --scene '" + fig8 + "' --object torus -o x.png");
    EXPECT_EQ(scene_alone.code, 1);
    EXPECT_NE(scene_alone.err.find("are for --color-by contacts"), std::string::npos) << scene_alone.err;
    const CliRun unknown = spt("render '" + torus + "' --color-by heat -o x.png");
    EXPECT_EQ(unknown.code, 1);
    const CliRun no_spheres = spt("render '" + torus + "' --color-by contacts --scene '" + fig8 + "' --object torus -o x.png");
    EXPECT_EQ(no_spheres.code, 1);

    const CliRun missing = spt(base + "--scene no_such_scene.json --object torus -o x.png");
    EXPECT_EQ(missing.code, 2);
    EXPECT_NE(missing.err.find("no_such_scene.json"), std::string::npos) << missing.err;
    const CliRun no_such = spt(base + "--scene '" + fig8 + "' --object cube -o x.png");
    EXPECT_EQ(no_such.code, 2);
    EXPECT_NE(no_such.err.find("no object named 'cube'"), std::string::npos) << no_such.err;
    // The object 'part' is another mesh than the torus this tree was made from.
    const CliRun other = spt(base + "--scene '" + fig8 + "' --object part -o x.png");
    EXPECT_EQ(other.code, 2);
    EXPECT_NE(other.err.find("fig8.json"), std::string::npos) << other.err;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

} // namespace
