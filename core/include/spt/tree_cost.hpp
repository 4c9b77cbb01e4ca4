#pragma once
/// What a sampling tree costs at query time (the editor's cost panel): the same queries as
/// `spt query` at random and near-contact poses of B relative to A, timed as `spt query
/// --repeat` times them. The paper's claim to check: regions likely to collide belong high in
/// the tree. Object frame of A, model units, nanoseconds.
#include "spt/collision_model.hpp"
#include "spt/query.hpp"
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace spt {

/// How a cost run chooses and times its poses.
struct CostOptions {
    int random_poses = 100; ///< B's origin uniform in the ball of radius extent(A) + extent(B) around A's, random rotation
    int near_poses = 100;   ///< B at first contact along a random direction, then moved by up to ±1% of the larger diagonal
    int repeats = 5;        ///< each query run this many times; its time is their median (spt query --repeat)
    QueryOptions query;     ///< level and mode timed (default: spheres, any, as spt query)
    uint32_t seed = 1;      ///< the same seed gives the same poses
};

/// B's poses relative to A (A at the identity) for a cost run.
struct CostPoses {
    std::vector<Pose> random; ///< anywhere the two bounding spheres can meet
    std::vector<Pose> near;   ///< within ±1% of the larger diagonal of a contact
};

/// Figures of one set of poses.
struct CostFigures {
    double median_ns = 0;         ///< median over the poses of each query's median time, nanoseconds
    double mean_node_pairs = 0;   ///< node pairs per query (spt query's node_pairs)
    double mean_sphere_tests = 0; ///< sampling-sphere pair tests per query (spt query's sphere_tests)
    double collide_share = 0;     ///< share of the poses that collide, 0 to 1
    std::vector<QueryCounters> counters; ///< per pose, in pose order
};

/// What a tree costs against B.
struct TreeCost {
    CostFigures random;      ///< at the random poses
    CostFigures near;        ///< at the near-contact poses
    size_t memory_bytes = 0; ///< A's CollisionModel::memory_bytes()
    bool cancelled = false;  ///< stopped early by the cancel flag; the figures are incomplete
};

/// Poses for a cost run of `b` against `a`; near-contact poses are placed with `reference`
/// queries of a against b at options.query's level (contact found by bisection along each
/// direction). Deterministic for a seed.
CostPoses cost_poses(const CollisionModel& a, const CollisionModel& b, const CostOptions& options);

/// Runs `a` against `b` at `poses` as `spt query` does and returns the figures. `cancel` (may
/// be null) stops the run between queries; `progress` (may be empty) is told the share done.
TreeCost measure_cost(const CollisionModel& a, const CollisionModel& b, const CostPoses& poses,
                      const CostOptions& options, const std::atomic<bool>* cancel = nullptr,
                      const std::function<void(double)>& progress = {});

} // namespace spt
