#pragma once
/// Many poses of one pair in one call (motion planners ask thousands at a time): the queries of
/// query.hpp spread over the library's thread pool or a host's task system, results in pose order
/// and the same for any number of threads. B's poses in A's frame (A at the identity), model units.
#include "spt/distance.hpp"
#include "spt/query.hpp"
#include "spt/task_system.hpp"
#include <cstdint>
#include <vector>

namespace spt {

/// How a batch runs.
struct BatchOptions {
    int threads = 0;             ///< jobs at once (0: the machine's cores); the results do not depend on it
    TaskSystem* tasks = nullptr; ///< a host's threads (spt/task_system.hpp); null: the library's pool
    /// Each query run this many times (>= 1) when times are asked for; a pose's time is their median.
    int repeat = 1;
};

/// collide_relative of A against B at every pose of `b_in_a`, in pose order. Mode `all` keeps no
/// pairs (a batch has no scratch to hand back): its answer and counters are those of the query.
/// With `ns` (may be null), each pose's time in nanoseconds (median of options.repeat runs, timed on
/// the thread that ran it). Throws what collide_relative throws; the poses not yet begun are not run.
std::vector<QueryResult> query_batch(const CollisionModel& a, const CollisionModel& b, const std::vector<Pose>& b_in_a,
                                     const QueryOptions& query, const BatchOptions& options = {},
                                     std::vector<int64_t>* ns = nullptr);

/// distance_relative of A against B at every pose of `b_in_a`, in pose order, as query_batch runs
/// queries (the same answers on any thread count; `ns` as there).
std::vector<DistanceResult> distance_batch(const CollisionModel& a, const CollisionModel& b,
                                           const std::vector<Pose>& b_in_a, const DistanceOptions& distance,
                                           const BatchOptions& options = {}, std::vector<int64_t>* ns = nullptr);

} // namespace spt
