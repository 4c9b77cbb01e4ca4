// The kinematic response (paper §3-4-3): colliding pairs moved back along their relative
// motion by the scene's rule, velocities reflected about the contact normal. Not a solver.
#include "spt/error.hpp"
#include "spt/simulation.hpp"
#include <chrono>

namespace spt {

void Simulation::respond(StepCounters& c) {
    const auto t0 = std::chrono::steady_clock::now();
    QueryScratch& scratch = scratch_[0];
    QueryOptions q;
    q.level = scene_.level;
    const double e = scene_.response.restitution, dt = scene_.dt;
    // Pairs in (a, b) order, one after the other: a pair sees the moves of the pairs before it.
    for (const PairContact& pc : result_.contacts) {
        const uint32_t a = pc.a, b = pc.b;
        const bool da = scene_.objects[a].motion == MotionKind::Velocity;
        const bool db = scene_.objects[b].motion == MotionKind::Velocity;
        if (!da && !db) continue; // static and path objects are never moved by a response
        // Equal shares between two dynamic objects; all of it to the only dynamic one.
        const double wa = da ? (db ? 0.5 : 1.0) : 0.0, wb = db ? (da ? 0.5 : 1.0) : 0.0;
        const CollisionModel& ma = *scene_.objects[a].model;
        const CollisionModel& mb = *scene_.objects[b].model;
        // B's motion relative to A over the step; without one, B leaves along the contact normal.
        Eigen::Vector3d motion = (poses_[b].translation - previous_[b].translation) -
                                 (poses_[a].translation - previous_[a].translation);
        const double scale = 1e-12 * (ma.extent() + mb.extent());
        if (!(motion.norm() > scale)) motion = -pc.normal;
        const BacktrackResult back = backtrack(ma, poses_[a], mb, poses_[b], motion, q, scene_.response.rule, scratch);
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
        c.responses += acted;
    }
    c.ns_response = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace spt
