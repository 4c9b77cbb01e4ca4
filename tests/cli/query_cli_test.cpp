// The `spt query` command-line contract, run against the real binary.
#include "mesh/shapes.hpp"
#include <gtest/gtest.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;

struct Outcome {
    int code;
    std::string out, err;
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class CliQuery : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("spt_cli_query_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
        const spt::TriangleMesh m = spt::make_torus(1.0, 0.35, 16, 8);
        std::ofstream obj(dir_ / "torus.obj");
        for (const auto& p : m.positions) obj << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
        for (const auto& t : m.triangles) obj << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path write(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name) << text;
        return dir_ / name;
    }
    Outcome run(const std::string& args) {
        const std::string cmd = std::string(SPT_BINARY_DIR) + "/cli/spt " + args + " >" + (dir_ / "out").string() +
                                " 2>" + (dir_ / "err").string();
        const int status = std::system(cmd.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir_ / "out"), slurp(dir_ / "err")};
    }
    std::string mesh() const { return (dir_ / "torus.obj").string(); }
    fs::path dir_;
};

TEST_F(CliQuery, OutputHasExactlyTheSpecifiedHeaderAndOneRowPerPose) {
    const auto poses = write("poses.txt", "# comment\n0 0 0 1 0 0 0 1 0 0\n5 0 0 1 0 0 0\n");
    const Outcome r = run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " --mode deepest --repeat 3");
    ASSERT_EQ(r.code, 0) << r.err;
    std::istringstream lines(r.out);
    std::string header, row0, row1, extra;
    std::getline(lines, header), std::getline(lines, row0), std::getline(lines, row1);
    EXPECT_EQ(header, "pose,collide,depth,backtrack,node_pairs,sphere_tests,ns");
    EXPECT_EQ(row0.rfind("0,1,", 0), 0u) << row0; // coincident copies collide
    EXPECT_EQ(row1.rfind("1,0,0,0,", 0), 0u) << row1; // far apart: no collision, no depth, no backtrack
    EXPECT_FALSE(std::getline(lines, extra) && !extra.empty());
}

TEST_F(CliQuery, BadPoseLineIsExitTwoNamingTheLine) {
    const auto poses = write("bad.txt", "# first\n0 0 0 1 0 0 0\n0 0 zero 1 0 0 0\n");
    const Outcome r = run("query " + mesh() + " " + mesh() + " --poses " + poses.string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("bad.txt:3"), std::string::npos) << r.err;
}

TEST_F(CliQuery, WrongNumberCountIsExitTwoNamingTheLine) {
    const auto poses = write("short.txt", "0 0 0 1 0 0\n");
    const Outcome r = run("query " + mesh() + " " + mesh() + " --poses " + poses.string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("short.txt:1"), std::string::npos) << r.err;
}

TEST_F(CliQuery, UnknownFlagIsExitOne) {
    const auto poses = write("p.txt", "0 0 0 1 0 0 0\n");
    EXPECT_EQ(run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " --no-such-flag").code, 1);
    EXPECT_EQ(run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " --level cubes").code, 1);
}

TEST_F(CliQuery, ExactLevelOnSptFilesWithoutMeshesExplainsWhy) {
    const auto poses = write("p.txt", "0 0 0 1 0 0 0\n");
    const std::string spt = (dir_ / "t.spt").string();
    ASSERT_EQ(run("convert " + mesh() + " -o " + spt + " --quiet").code, 0);
    const Outcome r = run("query " + spt + " " + spt + " --poses " + poses.string() + " --level exact");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("--mesh-a"), std::string::npos) << r.err;
    const Outcome ok = run("query " + spt + " " + spt + " --poses " + poses.string() + " --level exact --mesh-a " + mesh() +
                       " --mesh-b " + mesh());
    EXPECT_EQ(ok.code, 0) << ok.err;
}

TEST_F(CliQuery, OutputFileGetsTheCsv) {
    const auto poses = write("p.txt", "0 0 0 1 0 0 0\n");
    const fs::path csv = dir_ / "out.csv";
    ASSERT_EQ(run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " -o " + csv.string()).code, 0);
    EXPECT_EQ(slurp(csv).rfind("pose,collide,depth,backtrack,node_pairs,sphere_tests,ns\n0,1,", 0), 0u);
}

} // namespace
