#pragma once
// Pose files of `spt query`: one pose of B in A's frame a line,
// "tx ty tz qw qx qy qz [dx dy dz]"; '#' starts a comment line; blank lines are skipped.
#include "spt/pose.hpp"
#include <optional>
#include <string>
#include <vector>

namespace spt::cli {

/// One pose line: the pose and, if given, B's motion direction (A's frame).
struct PoseLine {
    Pose pose;
    std::optional<Eigen::Vector3d> direction;
    size_t line = 0; ///< 1-based line number in the file
};

/// Reads a pose file; throws Error(BadInput) "FILE:LINE: problem" on the first bad line.
std::vector<PoseLine> read_pose_file(const std::string& path);

} // namespace spt::cli
