#pragma once
// What a model needs to tell a point inside it from one outside: solid grids for the
// sphere levels and the exact level, and the points by which the model itself is tested
// against the other model (one on each connected piece).
#include "query/solid_grid.hpp"
#include <Eigen/Core>
#include <vector>

namespace spt {

class CompactTree;
struct ExactData;

struct SolidData {
    SolidGrid of_spheres;                  // levels bounds and spheres: walled in by sampling spheres
    SolidGrid of_triangles;                // level exact: walled in by the triangles of closed parts
    std::vector<Eigen::Vector3f> anchors;  // local frame: a point on each connected piece of the model
    std::vector<uint32_t> anchor_vertex;   // with a mesh: the vertex each anchor is (exact level)
    // A deformed pose (CollisionModel::follow_surface): no grids, which were made for the bind
    // pose; the anchors are at the posed vertices, and a point is inside when it is inside the
    // posed closed triangles (inside_closed_parts), at every level.
    bool posed = false;

    /// Grids and anchors of a model: pieces are the mesh's vertex-connected components when
    /// `e` has triangles, else the subtrees of the sampling tree three levels down. `wall`:
    /// per sphere, 1 if it samples a closed part (empty: unknown, every sphere is a wall).
    static SolidData build(const CompactTree& tree, const ExactData& e, const std::vector<uint8_t>& wall = {});
    /// Bytes held.
    size_t memory_bytes() const;
};

/// Exact: is local point p inside the closed parts of `e`: is the winding number of their
/// triangles about p, counted along a ray by orientation predicates, nonzero (so a region two
/// overlapping parts share is inside, a hollow's cavity, walled by a part facing into it, is
/// not)? A point on a closed triangle counts as inside.
bool inside_closed_parts(const ExactData& e, const Eigen::Vector3d& p);

} // namespace spt
