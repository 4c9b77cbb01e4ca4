#pragma once
// A sampling sphere of a model at a world pose: its centre and its sample's surface normal.
#include "spt/collision_model.hpp"
#include "spt/pose.hpp"

namespace spt::detail {

/// World centre of sphere `sphere` of active node `node` of `m` at pose `p`, model units.
inline Eigen::Vector3d world_sphere_centre(const CollisionModel& m, const Pose& p, uint32_t node, uint32_t sphere) {
    const CompactTree& t = m.tree();
    return p.apply(m.origin() + t.sphere_center(t.nodes()[node], sphere).cast<double>());
}

/// Sphere `sphere`'s sample normal in the model's frame, from its snorm8 components (not renormalised).
inline Eigen::Vector3d sphere_normal(const CompactTree& t, uint32_t sphere) {
    return Eigen::Vector3d(t.nx()[sphere], t.ny()[sphere], t.nz()[sphere]) / 127.0;
}

} // namespace spt::detail
