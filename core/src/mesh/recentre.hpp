#pragma once
// Mesh files whose vertices sit far from the origin (a level exported in world units):
// assimp parses coordinates into float, which keeps 1/16 of a unit at 10^6, so a part a few
// units across comes out quantised and its vertices merge. OBJ and PLY text, and binary PLY
// with double coordinates, carry more: their positions are rewritten relative to their
// bounding box's centre, in double, before assimp reads them, and the centre is added back.
#include <Eigen/Core>
#include <atomic>
#include <optional>
#include <string>

namespace spt::detail {

/// A mesh file's bytes with its vertex positions relative to `origin`.
struct RecentredFile {
    std::string bytes;      ///< the file as assimp should read it
    Eigen::Vector3d origin; ///< added to every position read from `bytes` (model units)
};

/// Whether float coordinates lose detail on positions in the box [lo, hi]: the farthest
/// coordinate's float spacing is coarser than 2^-20 of the box's largest side (or the box is
/// a point off the origin).
bool far_for_float(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

/// `path`, an OBJ, an ASCII PLY or a binary PLY whose x, y and z are doubles, with its vertex
/// positions relative to their bounding box's centre (read and subtracted in double); nullopt
/// for another format, for a file laid out otherwise than this reader expects (assimp then
/// reads it as it is), or for positions that are not far_for_float. Throws Cancelled.
std::optional<RecentredFile> recentre_positions(const std::string& path, const std::atomic<bool>* cancel);

} // namespace spt::detail
