#pragma once
// Welding vertices that lie within a distance of each other.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace spt::detail {

/// Maps each position to a representative (the first vertex of its cluster within `tolerance`);
/// returns the welded index of every input vertex and fills `welded` with the kept positions.
std::vector<uint32_t> weld_positions(const std::vector<Eigen::Vector3d>& positions, double tolerance,
                                     std::vector<Eigen::Vector3d>& welded);

} // namespace spt::detail
