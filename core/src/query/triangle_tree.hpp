#pragma once
// Builds the exact level's triangle tree (ExactData::tri_nodes, tri_order).
#include "query/exact_data.hpp"

namespace spt::detail {

/// Most triangles in a leaf: more than one only when all are compact and lie on one flat patch
/// (docs/queries.md, "How exact decides").
constexpr uint32_t kLeafTriangles = 4;

/// Fills e.tri_nodes and e.tri_order from e.positions and e.triangles, leaving out
/// zero-area triangles (counted in e.degenerate_triangles).
void build_triangle_tree(ExactData& e);

/// Brings the tree's boxes and spheres up to date after e.positions moved (a deformed pose),
/// keeping its shape and each node's axes: a leaf's box from its triangles' corners, an inner
/// node's from its children's box corners, bottom up. Every triangle stays inside every box and
/// sphere above it.
void refit_triangle_tree(ExactData& e);

} // namespace spt::detail
