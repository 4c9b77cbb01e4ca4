// `spt info` on good and damaged files.
#include "run_command.hpp"
#include "test_support.hpp"
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace spt::test;

namespace {

class InfoCli : public ::testing::Test {
protected:
    void SetUp() override {
        const auto r = run_command(spt_binary() + " convert " + q(project_meshes() + "/figure.obj") + " -o " +
                                   q(dir.file("figure.spt")));
        ASSERT_EQ(r.exit_code, 0) << r.output;
        std::ifstream in(dir.file("figure.spt"), std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    std::string write(const std::string& name, const std::vector<char>& b) {
        std::ofstream(dir.file(name), std::ios::binary).write(b.data(), std::streamsize(b.size()));
        return dir.file(name);
    }
    TempDir dir{"info"};
    std::vector<char> bytes;
};

TEST_F(InfoCli, DescribesAValidFile) {
    const auto r = run_command(spt_binary() + " info " + q(dir.file("figure.spt")));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("valid"), std::string::npos);
    EXPECT_NE(r.output.find("tree 'default'"), std::string::npos);
}

TEST_F(InfoCli, JsonHasTheDocumentedFields) {
    const auto r = run_command(spt_binary() + " info --json " + q(dir.file("figure.spt")) + " 2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_TRUE(j["valid"].get<bool>());
    EXPECT_EQ(j["mesh"]["name"], "figure.obj");
    EXPECT_GT(j["samples"]["total"].get<int>(), 0);
    const auto& t = j["trees"][0];
    for (const char* key : {"nodes", "active_nodes", "depth", "ss_radius", "query_layout_bytes"}) EXPECT_TRUE(t.contains(key)) << key;
}

TEST_F(InfoCli, TruncatedFilesExitTwoWithAnOffset) {
    for (size_t len : {size_t(0), size_t(10), size_t(31), size_t(32), bytes.size() / 2, bytes.size() - 1}) {
        const std::string path = write("cut.spt", std::vector<char>(bytes.begin(), bytes.begin() + long(len)));
        const auto r = run_command(spt_binary() + " info " + q(path));
        EXPECT_EQ(r.exit_code, 2) << len << "\n" << r.output;
        EXPECT_FALSE(r.crashed);
        EXPECT_NE(r.output.find("cut.spt: byte "), std::string::npos) << r.output;
    }
}

TEST_F(InfoCli, BitFlippedFilesExitTwo) {
    for (size_t at : {size_t(3), size_t(20), size_t(40), bytes.size() / 3, bytes.size() - 2}) {
        auto b = bytes;
        b[at] = char(b[at] ^ 0x10);
        const auto r = run_command(spt_binary() + " info " + q(write("flip.spt", b)));
        EXPECT_EQ(r.exit_code, 2) << at << "\n" << r.output;
        EXPECT_NE(r.output.find("flip.spt"), std::string::npos) << r.output;
    }
}

// A file named .spt is read as one, whatever it holds (a mesh under its own name is described).
TEST_F(InfoCli, MissingFileAndMeshInsteadOfSptExitTwo) {
    EXPECT_EQ(run_command(spt_binary() + " info /nonexistent.spt").exit_code, 2);
    std::filesystem::copy_file(project_meshes() + "/torus.obj", dir.file("torus.spt"));
    const auto r = run_command(spt_binary() + " info " + q(dir.file("torus.spt")));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("not an .spt file"), std::string::npos) << r.output;
}

} // namespace

namespace {

// A mesh file instead of a .spt: its clips, one line each (index, duration in seconds, joints, name).
TEST(InfoModelCli, ListsTheClipsOfAnAnimatedMesh) {
    const auto r = run_command(spt_binary() + " info /usr/share/assimp/models/FBX/animation_with_skeleton.fbx");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("skin: 13 joints"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("      0      0.8333      13  Armature|ArmatureAction"), std::string::npos) << r.output;
}

TEST(InfoModelCli, JsonListsEachClipWithItsIndexDurationAndJoints) {
    const auto r = run_command(spt_binary() + " info --json " +
                               q("/usr/share/assimp/models/MDL/MDL (HL1)/man.mdl") + " 2>/dev/null");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    ASSERT_EQ(j["clips"].size(), 6u);
    EXPECT_EQ(j["clips"][1]["name"], "walk");
    EXPECT_EQ(j["clips"][1]["index"], 1);
    EXPECT_NEAR(j["clips"][1]["duration"].get<double>(), 0.8333, 1e-3);
    EXPECT_EQ(j["clips"][1]["joints"], 6);
}

TEST(InfoModelCli, AMeshWithoutClipsSaysNone) {
    const auto r = run_command(spt_binary() + " info " + q(project_meshes() + "/figure.obj"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("clips: 0"), std::string::npos) << r.output;
}

TEST(InfoModelCli, AMissingOrUnreadableModelExitsTwoNamingIt) {
    TempDir dir{"info-model"};
    std::ofstream(dir.file("junk.gltf")) << "{ not json";
    for (const std::string& path : {dir.file("none.gltf"), dir.file("junk.gltf")}) {
        const auto r = run_command(spt_binary() + " info " + q(path));
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_FALSE(r.crashed);
        EXPECT_NE(r.output.find(path), std::string::npos) << r.output;
    }
}

} // namespace
