#pragma once
/// Pose files: one pose of B in A's frame a line, "tx ty tz qw qx qy qz [dx dy dz]"; '#' starts
/// a comment line; blank lines are skipped. `spt query --poses` reads them; the editor's cost
/// panel writes them.
#include "spt/pose.hpp"
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace spt {

/// Largest translation component a pose file may hold (model units): beyond it a double
/// keeps no digit below 1 and the pose is refused as bad input (docs/queries.md).
constexpr double kMaxCoordinate = 1e16;

/// One pose line: the pose and, if given, B's motion direction (A's frame).
struct PoseLine {
    Pose pose;
    std::optional<Eigen::Vector3d> direction;
    size_t line = 0; ///< 1-based line number in the file
};

/// Reads a pose file (numbers separated by spaces, tabs or commas; a leading UTF-8 byte order
/// mark skipped); throws Error(BadInput) "FILE:LINE: problem" on the first bad line:
/// not 7 or 10 finite numbers, a translation beyond kMaxCoordinate, a zero quaternion.
/// Any other quaternion is normalised; any finite direction is kept (zero: no motion).
std::vector<PoseLine> read_pose_file(const std::string& path);

/// Same, from a stream; `path` names it in messages.
std::vector<PoseLine> parse_poses(std::istream& in, const std::string& path);

/// Writes `poses` (no directions) to `path`, one a line with 17 significant digits, so that
/// read_pose_file gives back the same translations and, normalising again, rotations within an ulp; `comment` becomes a '#' line first when not
/// empty. Throws Error(CannotWrite) naming the file.
void write_pose_file(const std::string& path, const std::vector<Pose>& poses, const std::string& comment);

} // namespace spt
