#pragma once
// Poses compared bit for bit: what a step does not move keeps its pose's bits exactly.
#include "spt/pose.hpp"

namespace spt::detail {

/// True when both poses have the same translation and quaternion coefficients.
inline bool same_pose(const Pose& p, const Pose& q) {
    return p.translation == q.translation && p.rotation.coeffs() == q.rotation.coeffs();
}

} // namespace spt::detail
