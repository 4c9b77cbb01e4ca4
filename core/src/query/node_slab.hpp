#pragma once
// Slabs around the sampling tree's nodes for the distance query: a node's spheres spread over a
// face lie in a slab far thinner than their bounding ball, and the gap to that slab bounds the
// distance of a node pair far more tightly where faces are sampled densely.
#include "spt/compact_tree.hpp"
#include <vector>

namespace spt::detail {

/// Per node of `tree`, 4 floats: a unit normal n and a half-thickness h such that every
/// sampling sphere below the node lies within h of the plane through the node's centre with
/// normal n (local frame, model units); h < 0 when no slab is thinner than the node's ball.
std::vector<float> node_slabs(const CompactTree& tree);

} // namespace spt::detail
