#pragma once
/// Collision queries between two sampling trees (paper §3-4-2 and beyond).
/// A query runs in A's frame: B's pose relative to A is computed in double, then
/// B's node centres and sphere blocks are moved into A's frame as the walk reaches
/// them (lazy update), in float because the values are object-local.
/// Collision means the models meet: at level `spheres` two sampling spheres
/// overlap (|c1 - c2| < r1 + r2, touching is not a collision), at `bounds` two
/// leaf bounding spheres overlap, at `exact` two triangles share a point; and, with
/// QueryOptions::solids, a piece of one object lies inside a closed part of the other
/// (docs/queries.md, "Solids and surfaces").
#include "spt/collision_model.hpp"
#include "spt/pose.hpp"
#include "spt/query_scratch.hpp"
#include <cstdint>
#include <optional>
#include <string_view>

namespace spt {

/// How much of the model decides a collision.
enum class QueryLevel {
    Bounds,  ///< leaf bounding spheres only
    Spheres, ///< sampling spheres (the paper)
    Exact,   ///< triangles, exact predicates; needs the mesh in both models
};

/// The level the command line, scenes and Python call `name` ("bounds", "spheres", "exact"), or none.
std::optional<QueryLevel> query_level_named(std::string_view name);
/// The name of `level` as the command line, scenes and Python spell it.
const char* query_level_name(QueryLevel level);

/// What a query reports.
enum class QueryMode {
    Any,     ///< stop at the first colliding pair
    All,     ///< every colliding pair (in the scratch)
    Deepest, ///< the pair with the largest penetration, with contact point and normal
};

/// Options of one query.
struct QueryOptions {
    QueryLevel level = QueryLevel::Spheres; ///< what decides a collision
    QueryMode mode = QueryMode::Any;        ///< what is reported
    /// Skip sampling spheres whose normal faces away from the other node (see docs/queries.md):
    /// a sphere with unit normal n is skipped when n . u < -cull_cos, u the unit direction from
    /// its node's bounding-sphere centre to the other node's.
    bool normal_culling = false;
    float cull_cos = 0.5f; ///< cos of 60 degrees: skips normals within 60 degrees of pointing straight away
    /// Added to every sum of radii (model units): a query of the model grown by this much.
    float inflate = 0;
    /// Closed parts are solids: an object wholly inside another's closed part collides though
    /// no surfaces meet. false: surfaces only, as FCL answers. Open parts are surfaces always.
    bool solids = true;
};

/// Work done by one query.
struct QueryCounters {
    uint64_t node_pairs = 0;     ///< node pairs taken from the stack
    uint64_t bound_tests = 0;    ///< bounding-sphere overlap tests
    uint64_t sphere_tests = 0;   ///< sampling-sphere pair tests
    uint64_t triangle_tests = 0; ///< exact triangle-triangle tests
};

/// The deepest contact (A's sphere against B's), in the world frame. A collision found by
/// containment alone has depth 0 and the contained point as its point.
struct Contact {
    double depth = 0;                                   ///< r1 + r2 - |c1 - c2|, model units
    Eigen::Vector3d point = Eigen::Vector3d::Zero();    ///< middle of the overlap
    Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  ///< unit, from A's sphere centre towards B's
    uint32_t a = 0, b = 0;                              ///< sphere (or, at `bounds`, node) indices
};

/// Result of a query; the pairs of mode `all` are in the scratch.
struct QueryResult {
    bool collide = false;   ///< the models collide at the query's level
    Contact deepest;        ///< valid when collide and mode is Deepest (Any: the pair found)
    QueryCounters counters; ///< work done
};

/// Collision query of A at pose_a against B at pose_b (world poses, model units).
/// Const and thread-safe given one scratch per thread; allocates nothing once the
/// scratch has seen models of this size.
QueryResult collide(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                    const QueryOptions& options, QueryScratch& scratch);

/// Same, with B's pose given in A's frame (A at the identity); contacts are in A's frame.
QueryResult collide_relative(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                             const QueryOptions& options, QueryScratch& scratch);

} // namespace spt
