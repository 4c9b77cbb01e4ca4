// Pose files: what the editor writes, `spt query` reads back (translations bit for bit); bad
// lines are named.
#include "spt/error.hpp"
#include "spt/pose_file.hpp"
#include "test_support.hpp"
#include <Eigen/Geometry>
#include <fstream>
#include <gtest/gtest.h>
#include <random>
#include <sstream>

namespace spt {
namespace {

TEST(PoseFile, WrittenPosesReadBackAsTheSameTranslationsAndRotationsWithinAnUlp) {
    const test::TempDir dir("pose-file");
    std::mt19937 rng(3);
    std::normal_distribution<double> n;
    std::vector<Pose> poses;
    for (int k = 0; k < 50; ++k)
        poses.push_back(Pose::from(Eigen::Vector3d(n(rng), 1e6 * n(rng), 1e-9 * n(rng)),
                                   Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized()));
    const std::string path = dir.file("poses.txt");
    write_pose_file(path, poses, "fifty poses");
    const std::vector<PoseLine> back = read_pose_file(path);
    ASSERT_EQ(back.size(), poses.size());
    for (size_t k = 0; k < poses.size(); ++k) {
        EXPECT_EQ(back[k].pose.translation, poses[k].translation) << k;
        // The reader normalises every quaternion again: an ulp at most.
        EXPECT_LE((back[k].pose.rotation.coeffs() - poses[k].rotation.coeffs()).cwiseAbs().maxCoeff(), 4e-16) << k;
        EXPECT_FALSE(back[k].direction.has_value());
        EXPECT_EQ(back[k].line, k + 2); // after the comment line
    }
}

TEST(PoseFile, UnwritablePathIsCannotWriteNamingIt) {
    try {
        write_pose_file("/proc/nope/poses.txt", {Pose{}}, "");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::CannotWrite);
        EXPECT_NE(std::string(e.what()).find("/proc/nope/poses.txt"), std::string::npos);
    }
}

TEST(PoseFile, BadLineIsBadInputNamingFileAndLine) {
    std::istringstream in("# comment\n0 0 0 1 0 0 0\n\n1 2 3 0 0 0 0\n");
    try {
        parse_poses(in, "p.txt");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        EXPECT_NE(std::string(e.what()).find("p.txt:4: the quaternion"), std::string::npos) << e.what();
    }
}

TEST(PoseFile, AByteOrderMarkCommasAndCrlfReadAsTheSamePoses) {
    std::istringstream plain("0.5 0 0 1 0 0 0\n1 2 3 0 1 0 0 0 -1 0\n");
    std::istringstream saved("\xEF\xBB\xBF# from a spreadsheet\r\n0.5,0,0,1,0,0,0\r\n1, 2, 3, 0, 1, 0, 0, 0, -1, 0\r\n");
    const std::vector<PoseLine> a = parse_poses(plain, "plain.txt"), b = parse_poses(saved, "saved.csv");
    ASSERT_EQ(a.size(), 2u);
    ASSERT_EQ(b.size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(a[i].pose.translation, b[i].pose.translation) << i;
        EXPECT_EQ(a[i].pose.rotation.coeffs(), b[i].pose.rotation.coeffs()) << i;
        EXPECT_EQ(a[i].direction.has_value(), b[i].direction.has_value()) << i;
    }
    EXPECT_EQ(*b[1].direction, Eigen::Vector3d(0, -1, 0));
    EXPECT_EQ(b[1].line, 3u);
}

} // namespace
} // namespace spt
