#pragma once
// Exact crossings of a segment with triangles, for point-in-solid tests by ray parity.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace spt {

/// How segment p->q meets the closed triangle (a, b, c), decided by orientation predicates.
enum class Crossing {
    Misses,      ///< no common point (or only q's end, which callers keep beyond everything)
    Crosses,     ///< through the triangle's interior, transversally
    StartsOn,    ///< p lies on the triangle
    Degenerate,  ///< through an edge or a vertex, or in the triangle's plane: try another ray
};

/// Classifies segment p->q against triangle (a, b, c); q must lie beyond every triangle.
Crossing segment_crossing(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Fixed ray directions (unit, none along an axis or a diagonal) tried in turn until one
/// meets no edge or vertex.
const std::array<Eigen::Vector3d, 8>& parity_directions();

/// Exact: is p inside the closed surface made by `faces` of (positions, triangles)? Odd
/// crossings of a ray; p on a face counts as inside; false if every direction is degenerate.
bool inside_by_parity(const std::vector<Eigen::Vector3d>& positions, const std::vector<std::array<uint32_t, 3>>& triangles,
                      const std::vector<uint32_t>& faces, const Eigen::Vector3d& p);

} // namespace spt
