#pragma once
// Builds the exact level's triangle tree (ExactData::tri_nodes, tri_order).
#include "query/exact_data.hpp"

namespace spt::detail {

/// Fills e.tri_nodes and e.tri_order from e.positions and e.triangles, leaving out
/// zero-area triangles (counted in e.degenerate_triangles).
void build_triangle_tree(ExactData& e);

} // namespace spt::detail
