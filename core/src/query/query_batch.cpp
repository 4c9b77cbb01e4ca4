// Batches of one pair's queries on the thread pool: chunks of poses a job, one scratch a worker.
#include "spt/query_batch.hpp"
#include "base/parallel.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <chrono>

namespace spt {
namespace {

// Poses a job takes at once: a query is a microsecond or two, an item of the pool tens of nanoseconds.
constexpr size_t kPosesAChunk = 64;

// Runs answer(pose, scratch) for every pose in chunks on the pool, timing each on request.
template <class Result, class Answer>
std::vector<Result> run_batch(const std::vector<Pose>& b_in_a, const BatchOptions& options, std::vector<int64_t>* ns,
                              Answer&& answer) {
    if (options.threads < 0 || options.repeat < 1)
        throw Error(ErrorKind::Usage, "batch: threads must be >= 0 and repeat >= 1");
    const size_t n = b_in_a.size();
    std::vector<Result> out(n);
    if (ns) ns->assign(n, 0);
    const int threads = options.threads > 0 ? options.threads : hardware_threads();
    const size_t chunks = (n + kPosesAChunk - 1) / kPosesAChunk;
    std::vector<QueryScratch> scratch(size_t(std::max(1, std::min<int>(threads, int(std::max<size_t>(1, chunks))))));
    const int repeat = ns ? options.repeat : 1;
    detail::parallel_for(chunks, threads, [&](size_t c, int w) {
        std::vector<int64_t> runs_ns(static_cast<size_t>(repeat));
        for (size_t i = c * kPosesAChunk; i < std::min(n, (c + 1) * kPosesAChunk); ++i) {
            for (int64_t& t : runs_ns) {
                const auto t0 = std::chrono::steady_clock::now();
                out[i] = answer(b_in_a[i], scratch[size_t(w)]);
                t = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
            }
            if (ns) {
                std::nth_element(runs_ns.begin(), runs_ns.begin() + long(runs_ns.size() / 2), runs_ns.end());
                (*ns)[i] = runs_ns[runs_ns.size() / 2];
            }
        }
    }, options.tasks);
    return out;
}

} // namespace

std::vector<QueryResult> query_batch(const CollisionModel& a, const CollisionModel& b, const std::vector<Pose>& b_in_a,
                                     const QueryOptions& query, const BatchOptions& options, std::vector<int64_t>* ns) {
    return run_batch<QueryResult>(b_in_a, options, ns, [&](const Pose& p, QueryScratch& s) {
        return collide_relative(a, b, p, query, s);
    });
}

std::vector<DistanceResult> distance_batch(const CollisionModel& a, const CollisionModel& b,
                                           const std::vector<Pose>& b_in_a, const DistanceOptions& distance,
                                           const BatchOptions& options, std::vector<int64_t>* ns) {
    return run_batch<DistanceResult>(b_in_a, options, ns, [&](const Pose& p, QueryScratch& s) {
        return distance_relative(a, b, p, distance, s);
    });
}

} // namespace spt
