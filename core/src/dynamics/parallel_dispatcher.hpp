#pragma once
// Bullet's dispatcher with the narrow phase spread over spt's threads: algorithms are made and
// pairs listed on the calling thread, in the pair cache's order; then each pair's collide() runs
// on a worker with that worker's query scratch. Every pair writes only its own manifold, so the
// manifolds, and the solver's input, are the same for any thread count.
#include "dynamics/manifold_algorithm.hpp"
#include "spt/broad_phase.hpp"
#include "spt/task_system.hpp"
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <functional>
#include <vector>

namespace spt::detail {

class ParallelDispatcher : public btCollisionDispatcher {
public:
    /// Runs the narrow phase as `threads` jobs on `tasks` (null: the library's pool), worker w
    /// with scratch[w] (at least `threads` of them) and its own manifold working memory. `before`: called with the step's pairs (scene
    /// indices, lower first) before any is tested (poses the animated objects they need).
    ParallelDispatcher(btCollisionConfiguration* configuration, int threads, TaskSystem* tasks,
                       std::vector<QueryScratch>* scratch);
    void dispatchAllCollisionPairs(btOverlappingPairCache* cache, const btDispatcherInfo& info, btDispatcher*) override;
    /// Called before the narrow phase with the pairs it tests.
    std::function<void(const std::vector<CandidatePair>&)> before;
    /// The pairs the last narrow phase tested, in the order it listed them.
    const std::vector<ManifoldAlgorithm*>& tested() const { return tested_; }
    /// Nanoseconds of the last narrow phase.
    int64_t ns_narrow = 0;

private:
    int threads_;
    TaskSystem* tasks_;
    std::vector<QueryScratch>* scratch_;
    std::vector<ManifoldWork> work_; // one per worker
    std::vector<ManifoldAlgorithm*> tested_;
    std::vector<CandidatePair> pairs_;
};

} // namespace spt::detail
