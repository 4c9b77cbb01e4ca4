// The kinematic response (paper §3-4-3): colliding pairs moved back along their relative
// motion by the scene's rule, velocities reflected about the contact normal. Not a solver.
#include "query/backtrack_from.hpp"
#include "query/query_run.hpp"
#include "query/scratch.hpp"
#include "base/parallel.hpp"
#include "scene/same_pose.hpp"
#include "spt/error.hpp"
#include "spt/simulation.hpp"
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <thread>

namespace spt {

void Simulation::respond(StepCounters& c) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<PairContact>& contacts = result_.contacts;
    // Pairs act in (a, b) order, each seeing the moves of those before it. A pair reads and
    // writes only its dynamic objects (static and path objects are never moved by a response),
    // so it depends only on the latest earlier pair sharing each of them: batch = one after the
    // latest of theirs, and the pairs of a batch share no dynamic object. The workers take the
    // pairs batch by batch and start one once the two it depends on are done: exactly the
    // outcome of the one-after-the-other order whatever the thread count, with no wait for the
    // rest of a batch to end (and no threads started a batch).
    std::vector<int> last(poses_.size(), -1), batch_of(poses_.size(), -1);
    std::vector<std::array<int, 2>> after(contacts.size(), {-1, -1});
    std::vector<std::vector<uint32_t>> batches;
    for (uint32_t k = 0; k < contacts.size(); ++k) {
        const uint32_t a = contacts[k].a, b = contacts[k].b;
        const bool da = dynamic(a), db = dynamic(b);
        if (!da && !db) continue;
        after[k] = {da ? last[a] : -1, db ? last[b] : -1};
        const int batch = 1 + std::max(da ? batch_of[a] : -1, db ? batch_of[b] : -1);
        for (const uint32_t i : {a, b})
            if (dynamic(i)) last[i] = int(k), batch_of[i] = batch;
        if (size_t(batch) == batches.size()) batches.emplace_back();
        batches[size_t(batch)].push_back(k);
    }
    std::vector<uint32_t> movers; // batch by batch: what a pair waits on comes before it
    for (const std::vector<uint32_t>& batch : batches) movers.insert(movers.end(), batch.begin(), batch.end());
    std::vector<uint8_t> acted(contacts.size(), 0);
    std::vector<std::atomic<uint8_t>> done(contacts.size());
    for (std::atomic<uint8_t>& d : done) d.store(0, std::memory_order_relaxed);
    std::atomic<bool> failed{false};
    detail::parallel_for(movers.size(), threads_, [&](size_t i, int w) {
        const uint32_t k = movers[i];
        // Taken in order, so each pair waited on is running or done: no cycle of waits.
        for (const int d : after[k])
            while (d >= 0 && !done[size_t(d)].load(std::memory_order_acquire)) {
                if (failed.load(std::memory_order_relaxed)) return; // parallel_for rethrows the failure
                std::this_thread::yield();
            }
        try {
            acted[k] = respond_pair(contacts[k], start_pairs_[k], scratch_[size_t(w)]); // one per contact
        } catch (...) {
            failed.store(true);
            throw;
        }
        done[k].store(1, std::memory_order_release);
    }, tasks_);
    for (uint8_t x : acted) c.responses += x;
    c.ns_response = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
}

bool Simulation::respond_pair(const PairContact& pc, const std::vector<SpherePair>& start_pairs,
                              QueryScratch& scratch) {
    QueryOptions q;
    q.level = scene_.level;
    const double e = scene_.response.restitution, dt = scene_.dt;
    const uint32_t a = pc.a, b = pc.b;
    const bool da = dynamic(a), db = dynamic(b);
    // Equal shares between two dynamic objects; all of it to the only dynamic one.
    const double wa = da ? (db ? 0.5 : 1.0) : 0.0, wb = db ? (da ? 0.5 : 1.0) : 0.0;
    const CollisionModel& ma = *scene_.objects[a].model;
    const CollisionModel& mb = *scene_.objects[b].model;
    // B's motion relative to A over the step; without one, B leaves along the contact normal.
    Eigen::Vector3d motion = (poses_[b].translation - previous_[b].translation) -
                             (poses_[a].translation - previous_[a].translation);
    const double size = ma.extent() + mb.extent();
    const bool still = !(motion.norm() > 1e-12 * size);
    if (still) motion = -pc.normal;
    // The backtrack's first look is an `all` query at these poses, whose pairs serve any direction:
    // depth's while no earlier pair has moved these two, else one run here, since a pair that
    // overlapped before the step backtracks twice from these poses (rule Exact, levels bounds and
    // spheres, where backtrack_from_pairs gives backtrack's answer bit for bit).
    const bool from_pairs = scene_.response.rule == BacktrackRule::Exact && q.level != QueryLevel::Exact;
    const bool unmoved = detail::same_pose(poses_[a], ghost_[a]) && detail::same_pose(poses_[b], ghost_[b]);
    const std::vector<SpherePair>* pairs = nullptr; // none: each backtrack makes its own first look
    std::vector<SpherePair> own; // the scratch's buffer, taken for the two backtracks and given back
    // A deep overlap (as depth found it at these poses, or found here) parts where its last pair
    // does, found by branch and bound: its pairs grow with the volume the shells share, and even
    // looks that keep only the largest exit root each walk the two models near contact.
    bool deep = from_pairs && unmoved && pc.deep;
    // A deep overlap's depth kept its deepest pair: any pair's exit is a start for the search.
    const SpherePair* seed = from_pairs && pc.deep && !start_pairs.empty() ? &start_pairs[0] : nullptr;
    if (from_pairs && unmoved && !pc.deep && !start_pairs.empty()) {
        pairs = &start_pairs;
    } else if (from_pairs && !still && !deep) {
        collide_all_unless_deep(ma, poses_[a], mb, poses_[b], q, scratch, deep);
        if (!deep) {
            own.swap(detail::buffers_of(scratch).pairs);
            pairs = &own;
        }
    }
    auto back_along = [&](const Eigen::Vector3d& m, double limit) {
        if (pairs && !pairs->empty())
            return detail::backtrack_from_pairs(ma, poses_[a], mb, poses_[b], m, q, *pairs, scratch, limit);
        if (deep)
            return detail::deep_backtrack(ma, poses_[a], mb, poses_[b], m, q, scratch, limit,
                                          detail::deep_allowance(ma, mb), seed);
        return backtrack(ma, poses_[a], mb, poses_[b], m, q, scene_.response.rule, scratch, limit);
    };
    // Further back than the step's own motion: the pair already overlapped where the step began
    // (pushed in by another pair's response, or never parted), so undoing the motion is not what
    // parts it; pushed along the motion it would come out of the far side (a pebble pressed into
    // a floor and then rising would sink through it). It leaves along the contact normal instead,
    // and the search along the motion stops as soon as it is past that limit. The slack is far
    // above the backtrack's rounding up (a millionth of a reach a look).
    BacktrackResult back = back_along(motion, still ? kNoBacktrackLimit : motion.norm() + 1e-4 * size);
    if (back.beyond) {
        motion = -pc.normal;
        back = back_along(motion, kNoBacktrackLimit);
    }
    if (pairs == &own) own.swap(detail::buffers_of(scratch).pairs); // its capacity back for the next query
    bool acted = false;
    if (back.distance > 0) {
        const Eigen::Vector3d away = motion.normalized() * back.distance; // B moves by -away relative to A
        poses_[b].translation -= wb * away;
        poses_[a].translation += wa * away;
        acted = true;
    }
    // Velocities: kinematic objects move with their paths, static ones not at all.
    auto velocity = [&](uint32_t i, bool dyn) -> Eigen::Vector3d {
        if (dyn) return velocity_[i];
        return (ghost_[i].translation - previous_[i].translation) / dt;
    };
    const double vn = (velocity(b, db) - velocity(a, da)).dot(pc.normal);
    if (vn < 0) { // approaching along the normal: reflect with restitution
        const Eigen::Vector3d impulse = -(1 + e) * vn * pc.normal;
        if (db) velocity_[b] += wb * impulse;
        if (da) velocity_[a] -= wa * impulse;
        acted = true;
    }
    return acted;
}

} // namespace spt
