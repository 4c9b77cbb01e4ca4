#pragma once
// A colliding pair's contact manifold from its sampling spheres: at most four points, the deepest
// first, then those that span the contact (docs/scenes.md, "Dynamics"). No Bullet here.
#include "spt/collision_model.hpp"
#include "spt/pose.hpp"
#include "spt/query.hpp"
#include "spt/query_scratch.hpp"
#include <vector>

namespace spt::detail {

/// One manifold point, world frame.
struct ManifoldContact {
    Eigen::Vector3d on_a = Eigen::Vector3d::Zero(), on_b = Eigen::Vector3d::Zero(); ///< surface points of a and b
    Eigen::Vector3d normal = Eigen::Vector3d::UnitX(); ///< unit, from a towards b
    double depth = 0; ///< penetration along normal, model units (< 0: apart, within the margin)
};

/// One sphere pair as contact_manifold reads it (working memory).
struct PairFrame {
    Eigen::Vector3d ca, cb; ///< world centres
    double ra = 0, rb = 0;  ///< radii
    double facing = 0;      ///< -n_a . n_b of the two surface normals, each facing the other sphere
};

/// What contact_manifold found.
struct Manifold {
    std::vector<ManifoldContact> points; ///< at most 4; empty: apart by more than the margin
    std::vector<SpherePair> pairs;       ///< the sphere pairs that overlap (kept when asked)
    QueryCounters counters;              ///< the queries' work
};

/// contact_manifold's working memory, one per thread (a pair's would hold thousands of entries
/// for each of thousands of pairs).
struct ManifoldWork {
    std::vector<ManifoldContact> candidates; ///< every pair's point before the reduction
    std::vector<PairFrame> frames;           ///< the pairs whose surfaces face each other
};

/// The manifold of A and B (world poses): the sphere pairs within `margin` (model units) of
/// touching whose surface normals face each other, one shared normal (their normals weighted by
/// depth and by how squarely they face; what is struck gives it: `a_moves`, `b_moves`),
/// each pair's depth along it, then at most 4 of them that span the contact and hold its deepest
/// (reduce_manifold, depth tolerance a quarter of the margin). For a deep overlap (surfaces
/// crossing) only the pairs the walk found up to its first deep one count.
/// `keep_pairs`: out.pairs gets the pairs. Writes `out`; `scratch` and `work` are working memory.
void contact_manifold(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb, double margin,
                      bool a_moves, bool b_moves, bool keep_pairs, QueryScratch& scratch, ManifoldWork& work,
                      Manifold& out);

/// At most 4 of `contacts` (sharing one normal) chosen as contact_manifold does: the one farthest
/// from their middle across the normal, the one farthest from it, the one making the largest
/// triangle with those two, the one farthest on the other side of their line; then the deepest
/// in place of the nearest chosen one if it is deeper than all of them by more than
/// `depth_tolerance` (model units). All of them when there are at most 4.
std::vector<ManifoldContact> reduce_manifold(const std::vector<ManifoldContact>& contacts, double depth_tolerance);

} // namespace spt::detail
