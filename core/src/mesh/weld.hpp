#pragma once
// Welding vertices that lie within a distance of each other.
#include <Eigen/Core>
#include <atomic>
#include <cstdint>
#include <vector>

namespace spt::detail {

/// Maps each position to a representative (the first vertex of its cluster within `tolerance`);
/// returns the welded index of every input vertex and fills `welded` with the kept positions.
/// Once `cancel` (may be null; looked at every 65,536 vertices) is set, it returns at once with
/// the rest of the map unset: the caller looks at the flag and drops the result.
std::vector<uint32_t> weld_positions(const std::vector<Eigen::Vector3d>& positions, double tolerance,
                                     std::vector<Eigen::Vector3d>& welded, const std::atomic<bool>* cancel = nullptr);

} // namespace spt::detail
