// `spt convert MESH --motion SCENE.json --object NAME`: a tree built for the motion, recorded in the
// file so that `--recipe` rebuilds it byte for byte; wrong use refused.
#include "run_command.hpp"
#include "spt/spt_file.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace spt;
using namespace spt::test;

namespace {

std::string resource(const std::string& path) { return std::string(SPT_SOURCE_DIR) + "/resources/" + path; }

std::string bytes_of(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

TEST(ConvertCli, MotionBuildsATreeForTheSceneAndARecipeRebuildsItTheSame) {
    TempDir out("motion-cli");
    const std::string first = out.file("torus.spt"), again = out.file("again.spt");
    auto r = run_command(spt_binary() + " convert " + q(resource("meshes/torus.obj")) + " --motion " +
                         q(resource("scenes/fig8.json")) + " --object torus --tree-name fig8 -o " + q(first));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const SptDocument doc = load_spt(first);
    ASSERT_EQ(doc.trees.size(), 1u);
    const SamplingTree& t = doc.trees.front();
    EXPECT_EQ(t.name(), "fig8");
    ASSERT_EQ(t.motion_builds().size(), 1u);
    EXPECT_EQ(t.motion_builds()[0].object, "torus");
    // Relative to the file's folder, so the pair can move together.
    EXPECT_FALSE(t.motion_builds()[0].scene.empty());
    EXPECT_NE(t.motion_builds()[0].scene.front(), '/') << t.motion_builds()[0].scene;
    r = run_command(spt_binary() + " info " + q(first));
    EXPECT_NE(r.output.find("built for a motion under node 1: object 'torus' of "), std::string::npos) << r.output;
    r = run_command(spt_binary() + " convert " + q(resource("meshes/torus.obj")) + " --recipe " + q(first) + " -o " +
                    q(again));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("1 build from motion redone"), std::string::npos) << r.output;
    EXPECT_EQ(bytes_of(first), bytes_of(again));
}

TEST(ConvertCli, MotionWithoutObjectOrWithAnUnknownOneIsRefused) {
    TempDir out("motion-cli-bad");
    auto r = run_command(spt_binary() + " convert " + q(resource("meshes/torus.obj")) + " --motion " +
                         q(resource("scenes/fig8.json")) + " -o " + q(out.file("a.spt")));
    EXPECT_EQ(r.exit_code, 1) << "usage\n" << r.output;
    EXPECT_NE(r.output.find("--object"), std::string::npos) << r.output;
    r = run_command(spt_binary() + " convert " + q(resource("meshes/torus.obj")) + " --motion " +
                    q(resource("scenes/fig8.json")) + " --object teapot -o " + q(out.file("b.spt")));
    EXPECT_EQ(r.exit_code, 2) << "bad input\n" << r.output;
    EXPECT_NE(r.output.find("no object named 'teapot'"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out.file("b.spt")));
}
