// The narrow phase on spt's threads (parallel_dispatcher.hpp).
#include "dynamics/parallel_dispatcher.hpp"
#include "base/parallel.hpp"
#include <BulletCollision/BroadphaseCollision/btOverlappingPairCache.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <chrono>

namespace spt::detail {

ParallelDispatcher::ParallelDispatcher(btCollisionConfiguration* configuration, int threads, TaskSystem* tasks,
                                       std::vector<QueryScratch>* scratch)
    : btCollisionDispatcher(configuration), threads_(threads), tasks_(tasks), scratch_(scratch), work_(size_t(threads)) {}

void ParallelDispatcher::dispatchAllCollisionPairs(btOverlappingPairCache* cache, const btDispatcherInfo&, btDispatcher*) {
    const auto t0 = std::chrono::steady_clock::now();
    tested_.clear();
    pairs_.clear();
    btBroadphasePairArray& listed = cache->getOverlappingPairArray();
    for (int i = 0; i < listed.size(); ++i) {
        btBroadphasePair& pair = listed[i];
        auto* o0 = static_cast<btCollisionObject*>(pair.m_pProxy0->m_clientObject);
        auto* o1 = static_cast<btCollisionObject*>(pair.m_pProxy1->m_clientObject);
        if (!needsCollision(o0, o1)) continue; // both asleep, or filtered
        if (!pair.m_algorithm) {
            const btCollisionObjectWrapper w0(nullptr, o0->getCollisionShape(), o0, o0->getWorldTransform(), -1, -1);
            const btCollisionObjectWrapper w1(nullptr, o1->getCollisionShape(), o1, o1->getWorldTransform(), -1, -1);
            pair.m_algorithm = findAlgorithm(&w0, &w1, nullptr, BT_CONTACT_POINT_ALGORITHMS);
        }
        auto* algorithm = static_cast<ManifoldAlgorithm*>(pair.m_algorithm); // the only one registered
        tested_.push_back(algorithm);
        pairs_.push_back({algorithm->a(), algorithm->b()});
    }
    if (before) before(pairs_);
    parallel_for(tested_.size(), threads_, [&](size_t k, int w) { tested_[k]->collide((*scratch_)[size_t(w)], work_[size_t(w)]); }, tasks_);
    ns_narrow = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace spt::detail
