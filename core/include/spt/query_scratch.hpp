#pragma once
/// Per-query working memory. The caller owns one per thread and reuses it: a
/// query grows it only when it meets a larger model, so repeated queries
/// allocate nothing.
#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

namespace spt {

class CollisionModel;
struct Pose;
struct QueryOptions;
struct QueryResult;

/// A colliding pair found by a query in mode `all`.
struct SpherePair {
    uint32_t a = 0, b = 0; ///< sphere indices (node indices at level `bounds`) in each CompactTree
    uint32_t node_a = 0, node_b = 0; ///< the active nodes holding them (CompactTree node indices)
    float depth = 0;       ///< reach - |c1 - c2|, model units
    float reach = 0;       ///< r1 + r2 (+ inflate), model units
};

/// An intersecting triangle pair found at level `exact` in mode `all`.
struct TrianglePair {
    uint32_t a = 0, b = 0; ///< triangle indices in each mesh
};

namespace detail {
// A node pair on the traversal stack: its bounding spheres overlap. a and b are
// CompactNode indices, the top bit set for an active node; centres in A's frame.
struct NodePairVisit {
    uint32_t a, b;
    float ca[3], cb[3];
    float ra, rb; // radii the pair was tested with
    float d2;     // squared centre distance
};
} // namespace detail

/// Scratch buffers of one query at a time.
class QueryScratch {
public:
    /// Sphere (or leaf) pairs of the last query in mode `all`.
    const std::vector<SpherePair>& pairs() const { return pairs_; }
    /// Triangle pairs of the last `exact` query in mode `all`.
    const std::vector<TrianglePair>& triangle_pairs() const { return tri_pairs_; }

private:
    friend struct QueryRun;
    friend void prepare_scratch(QueryScratch&, const CollisionModel&, const CollisionModel&, bool);
    friend QueryResult collide_brute_force(const CollisionModel&, const CollisionModel&, const Pose&,
                                           const QueryOptions&, QueryScratch&);
    std::vector<std::pair<uint32_t, uint32_t>> stack_;   // triangle-tree walk (level exact)
    std::vector<detail::NodePairVisit> visits_;          // sampling-tree walk
    std::vector<float> moved_b_;               // one leaf of B in A's frame (x, y, z columns)
    std::vector<Eigen::Vector3d> bverts_;      // B's vertices in A's frame (lazy)
    std::vector<uint32_t> vert_stamp_;
    std::vector<float> btri_;                  // B's triangle bounding spheres in A's frame (lazy)
    std::vector<uint32_t> tri_stamp_;
    std::vector<float> d2_;                    // distance matrix of one leaf pair
    std::vector<float> ga_, gb_;               // culled spheres gathered (x, y, z blocks)
    std::vector<uint32_t> ia_, ib_;            // their sphere indices
    std::vector<SpherePair> pairs_;
    std::vector<TrianglePair> tri_pairs_;
    uint32_t epoch_ = 0;
};

} // namespace spt
