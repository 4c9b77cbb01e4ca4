#pragma once
// The buffers behind QueryScratch: grown to the largest models met, reused by every query.
#include "spt/query_scratch.hpp"
#include "geometry/obb.hpp"
#include <Eigen/Core>
#include <algorithm>
#include <utility>
#include <vector>

namespace spt::detail {

// A node pair on the traversal stack: its bounding spheres overlap. a and b are
// CompactNode indices, the top bit set for an active node; centres in A's frame.
struct NodePairVisit {
    uint32_t a, b;
    float ca[3], cb[3];
    float ra, rb; // radii the pair was tested with
    float d2;     // squared centre distance
    float cap;    // mode deepest: no pair below is deeper than this (its ancestors' bounds)
};

// A value per sphere (or node), computed at most once between two start() calls: a list of
// sphere pairs names each sphere many times.
template <class T>
struct SphereMemo {
    std::vector<T> value;
    std::vector<uint32_t> stamp;
    uint32_t epoch = 0;
    // Forgets every value; room for indices below n.
    void start(size_t n) {
        if (value.size() < n) value.resize(n), stamp.resize(n, 0);
        if (++epoch == 0) std::fill(stamp.begin(), stamp.end(), 0), epoch = 1;
    }
    // The value of index k, made by f() the first time it is asked for.
    template <class F>
    const T& get(uint32_t k, F&& f) {
        if (stamp[k] != epoch) stamp[k] = epoch, value[k] = f();
        return value[k];
    }
};

// Floats of moved leaves cached a query (256 KiB: the slots of a small model such as a scene's
// pebble, visited by many leaf pairs, stay in L2; a large model's leaves are moved per leaf pair).
constexpr size_t kLeafCacheFloats = 65536;

// Up to four nodes below an inner node of B, in A's frame, as the walk tests them in one step
// (query.cpp: centre and radius columns, node references, lanes in use).
struct NodeGroup {
    alignas(16) float x[4];
    alignas(16) float y[4];
    alignas(16) float z[4];
    alignas(16) float r[4];
    uint32_t ref[4];
    uint32_t count;
};

struct ScratchBuffers {
    std::vector<std::pair<uint32_t, uint32_t>> stack;  // triangle-tree walk (level exact)
    std::vector<NodePairVisit> visits;                 // sampling-tree walk
    std::vector<float> moved_b;              // one leaf of B in A's frame (x, y, z columns)
    // B's active nodes moved into A's frame at most once a query, a slot of three columns each,
    // when the slots of every node fit in L2 (kLeafCacheFloats); leaf_slot 0: moved per leaf pair.
    std::vector<float> leaf_cache;
    std::vector<uint32_t> leaf_stamp;        // the epoch of the query that filled a slot
    size_t leaf_slot = 0, leaf_column = 0;   // floats a slot and a column
    // Likewise B's inner nodes' groups, made at most once a query for a small model.
    std::vector<NodeGroup> b_groups;
    std::vector<uint32_t> b_group_stamp;
    bool group_cache = false;
    std::vector<Eigen::Vector3d> bverts;     // B's vertices in A's frame (lazy)
    std::vector<uint32_t> vert_stamp;
    std::vector<float> btri;                 // B's triangle bounding spheres in A's frame (lazy)
    std::vector<uint32_t> tri_stamp;
    std::vector<float> bplane;               // B's triangle planes in A's frame (lazy, the distance walk)
    std::vector<uint32_t> plane_stamp;
    std::vector<Obb> bboxes;                 // boxes of B's triangle-tree nodes in A's frame (lazy, box tests only)
    std::vector<uint32_t> bbox_stamp;
    struct MovedNode {
        Eigen::Vector3f centre, axis0; // a triangle-tree node's centre and its slab's axis
    };
    std::vector<MovedNode> bcentres;         // B's triangle-tree nodes in A's frame (lazy)
    std::vector<uint32_t> bcentre_stamp;
    std::vector<float> d2;                   // distance matrix of one leaf pair
    std::vector<float> ga, gb;               // culled spheres gathered (x, y, z blocks)
    std::vector<uint32_t> ia, ib;            // their sphere indices
    std::vector<SpherePair> pairs;
    std::vector<TrianglePair> tri_pairs;
    uint32_t epoch = 0;
    uint32_t deepest_node_a = 0, deepest_node_b = 0; // active nodes of the last deepest contact
    SphereMemo<Eigen::Vector3d> memo_b;           // a per-pair-list value of B's spheres
    // The deep backtrack's branch and bound (response.cpp): node pairs to visit with the root
    // their bounds part at; one leaf of B in A's frame, in double.
    struct ExitBound {
        double root;
        uint32_t a, b;
    };
    std::vector<ExitBound> exit_stack;
    std::vector<std::pair<double, uint32_t>> support_heap; // detail::spheres_support's room
    // The distances' branch and bound: heaps of node pairs by the least gap below them, in float
    // for the exact level's triangle trees (distance_exact.cpp), in double for the sphere levels
    // (distance.cpp).
    template <class Gap>
    struct GapBoundOf {
        Gap gap;
        uint32_t a, b;
        /// Later in the order (gap, then a, then b). Bit operations, not branches: a heap's pop
        /// compares two children whose order is a coin toss to a predictor (query/best_first.hpp).
        bool operator>(const GapBoundOf& o) const {
            return (gap > o.gap) | ((gap == o.gap) & ((a > o.a) | ((a == o.a) & (b > o.b))));
        }
    };
    using GapBound = GapBoundOf<float>;
    using SphereGapBound = GapBoundOf<double>;
    std::vector<GapBound> gap_heap;
    std::vector<SphereGapBound> sphere_gap_heap;
    std::vector<Eigen::Vector3d> exit_leaf_b;
    std::vector<Eigen::Vector3d> distance_leaf_b; // distance.cpp: B's leaf spheres in A's frame, a leaf pair
    SphereMemo<Eigen::Matrix<double, 3, 2>> memo_ca, memo_cb; // two values of A's and of B's spheres (a centre and a normal)
};

struct ScratchAccess {
    static ScratchBuffers& buffers(QueryScratch& s) { return *s.b_; }
};

/// The buffers behind `scratch`, for the query code.
inline ScratchBuffers& buffers_of(QueryScratch& scratch) { return ScratchAccess::buffers(scratch); }

} // namespace spt::detail
