#pragma once
// A moving object's mass, centre of mass and principal axes of inertia (effect dynamics).
#include "spt/pose.hpp"
#include "spt/scene.hpp"
#include <string>

namespace spt::detail {

struct RigidMass {
    double mass = 0;                                              ///< mass units
    Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();  ///< about the centre of mass, body axes
    Pose object_from_body; ///< body frame (centre of mass, principal axes) to the object frame
};

/// From objects[].mass, or density x the closed mesh's volume; inertia from the closed mesh
/// (scaled to the mass), or, for a model without one and a given mass, of a uniform box around its
/// sampling spheres. Throws Error(BadInput) naming object `index` of `scene_file` when it has no
/// mass: an open mesh or a `.spt` model without its closed mesh, and no 'mass'.
RigidMass rigid_mass(const SceneObject& o, const std::string& scene_file, size_t index);

} // namespace spt::detail
