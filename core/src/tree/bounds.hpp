#pragma once
// Bounding spheres over a contiguous run of sampling spheres.
#include "tree/miniball.hpp"
#include "spt/sampling_tree.hpp"
#include <Eigen/Geometry>

namespace spt {

/// Radius that `rule` gives a node holding `members`.
float node_radius(const std::vector<uint32_t>& members, const SampleSet& samples, const RadiusRule& rule);

/// Bounding sphere of the sampling spheres of `members` under `method`; `hint` as for bound_run.
void bound_samples(TreeNode& node, const std::vector<uint32_t>& members, const SampleSet& samples,
                   BoundsMethod method, const detail::Ball& hint = {});

namespace detail {

/// Sets node.center/bv_radius from n sampling spheres (centres c, radii r, surface points p).
/// `hint` (may be empty) is a ball whose centre is worth trying, e.g. the children's merged
/// ball, or the parent's ball for the two halves of a split (tight bounds only);
/// `centre_box`, if given, is the box of the n centres (saves a pass).
void bound_run(TreeNode& node, const Eigen::Vector3f* c, const float* r, const Eigen::Vector3f* p, size_t n,
               const Ball& hint, BoundsMethod method, const Eigen::AlignedBox3f* centre_box = nullptr);

} // namespace detail
} // namespace spt
