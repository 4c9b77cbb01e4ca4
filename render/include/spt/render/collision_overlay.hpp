#pragma once
/// Filling a CollisionOverlay without the collision query: every overlapping pair
/// of two sphere sets by brute force. A reference and a stand-in until the query
/// reports pairs itself; the overlay takes pairs from anywhere.
#include "spt/compact_tree.hpp"
#include "spt/render/frame.hpp"
#include <vector>

namespace spt::render {

/// The sampling spheres of `compact` moved into the object frame by its origin, then into the world by `pose` (rigid).
std::vector<Sphere> world_spheres(const CompactTree& compact, const Eigen::Affine3f& pose);

/// The pair record of spheres a and b: depth = ra + rb - |cb - ca|, normal from a
/// towards b (+Y if the centres coincide), contact midway through the overlap on the
/// line of centres.
SpherePair make_sphere_pair(const Sphere& a, const Sphere& b);

/// Every (i, j) with a[i] and b[j] overlapping (depth > 0), ordered by i then j.
/// O(|a| |b|): for tests and small overlays.
std::vector<SpherePair> overlapping_pairs(const std::vector<Sphere>& a, const std::vector<Sphere>& b);

} // namespace spt::render
