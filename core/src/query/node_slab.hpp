#pragma once
// Per-node bounds beyond the balls. Slabs around the sampling tree's nodes for the distance query: a node's spheres spread over a
// face lie in a slab far thinner than their bounding ball, and the gap to that slab bounds the
// distance of a node pair far more tightly where faces are sampled densely.
#include "spt/compact_tree.hpp"
#include <vector>

namespace spt::detail {

/// Per node of `tree`, 4 floats: a unit normal n and a half-thickness h such that every
/// sampling sphere below the node lies within h of the plane through the node's centre with
/// normal n (local frame, model units); h < 0 when no slab is thinner than the node's ball.
std::vector<float> node_slabs(const CompactTree& tree);

/// Per node of `tree`, the largest sampling-sphere radius below it (model units). No two spheres
/// below a pair of nodes overlap by more than the sum of theirs: the deepest overlap's bound where
/// the nodes' balls, deep in each other, bound nothing. Unchanged by a pose (radii stay).
std::vector<float> node_max_radii(const CompactTree& tree);

} // namespace spt::detail
