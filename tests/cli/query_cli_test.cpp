// The `spt query` command-line contract, run against the real binary.
#include "mesh/shapes.hpp"
#include <gtest/gtest.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <vector>

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

TEST_F(CliQuery, ThreadsChangeNothingButTheTimes) {
    // 300 poses along a line through the copy: some collide, some not; --threads 3 runs them as one
    // batch on three threads (query_batch) and writes the same rows but for the ns column.
    std::string text;
    for (int i = 0; i < 300; ++i) text += std::to_string(-3.0 + 0.02 * i) + " 0.1 0 0.9238795 0 0.3826834 0 1 0 0\n";
    const auto poses = write("line.txt", text);
    const Outcome one = run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " --repeat 1");
    const Outcome three = run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " --repeat 1 --threads 3");
    ASSERT_EQ(one.code, 0) << one.err;
    ASSERT_EQ(three.code, 0) << three.err;
    auto without_ns = [](const std::string& csv) {
        std::istringstream lines(csv);
        std::vector<std::string> rows;
        for (std::string row; std::getline(lines, row);) rows.push_back(row.substr(0, row.rfind(',')));
        return rows;
    };
    const std::vector<std::string> a = without_ns(one.out), b = without_ns(three.out);
    ASSERT_EQ(a.size(), 301u);
    EXPECT_EQ(a, b);
    size_t collide = 0;
    for (size_t i = 1; i < a.size(); ++i) collide += a[i].find(",1,") != std::string::npos;
    EXPECT_GT(collide, 10u);
    EXPECT_LT(collide, 290u);
}

TEST_F(CliQuery, DistanceModeWritesTheGapAndItsPointsAndInfBeyondTheMaximum) {
    const auto poses = write("apart.txt", "5 0 0 1 0 0 0\n0.2 0 0 1 0 0 0\n40 0 0 1 0 0 0\n");
    const Outcome r = run("query " + mesh() + " " + mesh() + " --poses " + poses.string() +
                          " --mode distance --max-distance 10 --repeat 1");
    ASSERT_EQ(r.code, 0) << r.err;
    std::istringstream lines(r.out);
    std::string header, apart, overlapping, far;
    std::getline(lines, header), std::getline(lines, apart), std::getline(lines, overlapping), std::getline(lines, far);
    EXPECT_EQ(header, "pose,collide,distance,ax,ay,az,bx,by,bz,node_pairs,sphere_tests,ns");
    EXPECT_EQ(apart.rfind("0,0,", 0), 0u) << apart;
    const double gap = std::stod(apart.substr(4, apart.find(',', 4) - 4));
    EXPECT_GT(gap, 0);
    EXPECT_LT(gap, 5);
    EXPECT_EQ(overlapping.rfind("1,1,-", 0), 0u) << overlapping; // overlapping copies: minus the depth
    EXPECT_EQ(far.rfind("2,0,inf,,,,,,,", 0), 0u) << far;        // beyond --max-distance
    EXPECT_EQ(run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " --max-distance 1").code, 1)
        << "--max-distance without --mode distance";
    EXPECT_EQ(run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " --mode distance --max-distance -1").code, 1);
}

TEST_F(CliQuery, DistanceModeAtTheExactLevelGivesTheTrianglesGap) {
    const auto poses = write("apart.txt", "5 0 0 1 0 0 0\n");
    auto gap_at = [&](const std::string& level) {
        const Outcome r = run("query " + mesh() + " " + mesh() + " --poses " + poses.string() +
                              " --mode distance --repeat 1 --level " + level);
        EXPECT_EQ(r.code, 0) << r.err;
        const std::string row = r.out.substr(r.out.find('\n') + 1);
        EXPECT_EQ(row.rfind("0,0,", 0), 0u) << row;
        return std::stod(row.substr(4, row.find(',', 4) - 4));
    };
    const double exact = gap_at("exact"), spheres = gap_at("spheres");
    EXPECT_GT(exact, 0);
    // The spheres sit on the surface: their gap is the triangles' within the sampling's reach.
    EXPECT_NEAR(spheres, exact, 0.05 * exact);
}

TEST_F(CliQuery, NoDepthWritesOverlappingPosesAsZeroWithEmptyPoints) {
    const auto poses = write("two.txt", "5 0 0 1 0 0 0\n0.2 0 0 1 0 0 0\n");
    const Outcome r = run("query " + mesh() + " " + mesh() + " --poses " + poses.string() +
                          " --mode distance --no-depth --repeat 1");
    ASSERT_EQ(r.code, 0) << r.err;
    std::istringstream lines(r.out);
    std::string header, apart, overlapping;
    std::getline(lines, header), std::getline(lines, apart), std::getline(lines, overlapping);
    EXPECT_EQ(apart.rfind("0,0,", 0), 0u) << apart;
    EXPECT_EQ(apart.find(",,"), std::string::npos) << "an apart pose keeps its points: " << apart;
    EXPECT_EQ(overlapping.rfind("1,1,0,,,,,,,", 0), 0u) << overlapping;
    EXPECT_EQ(run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " --no-depth").code, 1)
        << "--no-depth without --mode distance";
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

// CLI11's own range check lets NaN through (every comparison with it is false).
TEST_F(CliQuery, NanOrInfiniteCullAngleIsExitOneNamingTheOption) {
    const auto poses = write("p.txt", "0 0 0 1 0 0 0\n");
    for (const char* angle : {"nan", "inf", "-inf", "91", "1e999"}) {
        const auto r = run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " --culling --cull-angle " + angle);
        EXPECT_EQ(r.code, 1) << angle << "\n" << r.err;
        EXPECT_NE(r.err.find("--cull-angle: must be a finite number of degrees from 0 to 90"), std::string::npos) << r.err;
    }
    EXPECT_EQ(run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " --culling --cull-angle 45").code, 0);
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

// Extreme values (docs/queries.md, "Extreme values"): refused with the line, or answered
// promptly with finite output.
using ExtremePosesCli = CliQuery;

// CSV rows after the header, split at commas.
std::vector<std::vector<std::string>> rows_of(const std::string& csv) {
    std::istringstream lines(csv);
    std::string line;
    std::vector<std::vector<std::string>> rows;
    std::getline(lines, line);
    while (std::getline(lines, line)) {
        std::vector<std::string> cells;
        std::istringstream cs(line);
        for (std::string c; std::getline(cs, c, ',');) cells.push_back(c);
        rows.push_back(cells);
    }
    return rows;
}

TEST_F(ExtremePosesCli, TranslationBeyond1e16IsExitTwoNamingTheLine) {
    for (const char* t : {"1.0000001e16 0 0", "0 1e25 0", "0 0 -1.7976931348623157e308"}) {
        const auto poses = write("far.txt", std::string("# far\n0 0 0 1 0 0 0\n") + t + " 1 0 0 0\n");
        const Outcome r = run("query " + mesh() + " " + mesh() + " --poses " + poses.string());
        EXPECT_EQ(r.code, 2) << t;
        EXPECT_NE(r.err.find("far.txt:3: translation"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("1e16"), std::string::npos) << r.err;
    }
}

TEST_F(ExtremePosesCli, ZeroQuaternionIsExitTwoNamingTheLine) {
    const auto poses = write("zero.txt", "0 0 0 0 0 0 0\n");
    const Outcome r = run("query " + mesh() + " " + mesh() + " --poses " + poses.string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("zero.txt:1: the quaternion"), std::string::npos) << r.err;
}

TEST_F(ExtremePosesCli, TranslationAtTheBoundAnswersNoCollisionWithoutAWalk) {
    const auto poses = write("bound.txt", "1e16 -1e16 1e16 1 0 0 0 1 0 0\n-1e16 0 0 0.3 0.1 0.2 0.4 -1 0 0\n");
    const Outcome r = run("query " + mesh() + " " + mesh() + " --poses " + poses.string() + " --repeat 1");
    ASSERT_EQ(r.code, 0) << r.err;
    for (const auto& row : rows_of(r.out)) {
        ASSERT_EQ(row.size(), 7u);
        for (size_t k : {1, 2, 3, 4}) EXPECT_EQ(row[k], "0") << "column " << k; // collide, depth, backtrack, pairs
    }
}

TEST_F(ExtremePosesCli, TinyHugeAndUnnormalisedQuaternionsAndDirectionsAnswerAsUnitOnes) {
    // The same pose near contact, written with its quaternion and its direction scaled.
    const std::string t = "1.6 0.2 0.1 ";
    const auto poses = write("scaled.txt", t + "0.9 0.3 0.1 0.2 -1 0.2 0.1\n" +          //
                                               t + "0.9e-300 0.3e-300 0.1e-300 0.2e-300 -1 0.2 0.1\n" +
                                               t + "0.9e300 0.3e300 0.1e300 0.2e300 -1 0.2 0.1\n" +
                                               t + "0.9 0.3 0.1 0.2 -1e-300 0.2e-300 0.1e-300\n" +
                                               t + "0.9 0.3 0.1 0.2 -1e300 0.2e300 0.1e300\n" +
                                               t + "0.9 0.3 0.1 0.2 0 0 0\n");
    for (const char* level : {"bounds", "spheres", "exact"}) {
        const Outcome r = run("query " + mesh() + " " + mesh() + " --poses " + poses.string() +
                              " --repeat 1 --level " + std::string(level));
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
        EXPECT_EQ(r.out.find("inf"), std::string::npos) << r.out;
        const auto rows = rows_of(r.out);
        ASSERT_EQ(rows.size(), 6u);
        ASSERT_EQ(rows[0][1], "1") << level; // the pose collides
        EXPECT_NE(rows[0][3], "0") << level;
        for (size_t i = 1; i < 6; ++i) {
            EXPECT_EQ(rows[i][1], rows[0][1]) << level << " row " << i;
            EXPECT_NEAR(std::stod(rows[i][2]), std::stod(rows[0][2]), 1e-6) << level << " row " << i;
            // Zero direction: no motion, no backtrack; any other scale: the unit direction's.
            EXPECT_NEAR(std::stod(rows[i][3]), i == 5 ? 0.0 : std::stod(rows[0][3]), 1e-6) << level << " row " << i;
        }
    }
}

} // namespace
