#pragma once
// Effect dynamics: the scene's objects as bodies of Bullet's btDiscreteDynamicsWorld, whose
// collision algorithm for them is spt's (manifold_algorithm.hpp) and whose constraint solver,
// integration and sleeping are Bullet's own (docs/scenes.md, "Dynamics").
#include "spt/simulation.hpp"
#include <functional>
#include <memory>
#include <vector>

struct btContactSolverInfo;

namespace spt::detail {

struct BodyInfo;

/// Sets Bullet's solver as effect dynamics steps with: the scene's iterations, split impulse, no
/// bounce slower than `gravity` (|g|, 0 without gravity) makes in two steps. Shared with the
/// benchmark's plain Bullet world (bench/dynamics), so that only the contacts differ.
void configure_solver(btContactSolverInfo& solving, const Scene& scene, double gravity);

class DynamicsWorld {
public:
    /// Bodies for `scene`'s objects (models loaded; it must outlive the world): moving objects
    /// with their mass, centre of mass and inertia, path objects kinematic, static ones fixed.
    /// Throws Error(BadInput) naming an object that moves and has no mass (an open mesh or a
    /// `.spt` model without `mass`). Gravity acts when `gravity`; the narrow phase runs as
    /// `threads` jobs on `tasks` with scratch[w]; `keep_pairs`: contacts carry their sphere pairs.
    DynamicsWorld(const Scene& scene, bool gravity, bool keep_pairs, int threads, TaskSystem* tasks,
                  std::vector<QueryScratch>* scratch);
    ~DynamicsWorld();
    DynamicsWorld(const DynamicsWorld&) = delete;
    DynamicsWorld& operator=(const DynamicsWorld&) = delete;

    /// One step of the scene's dt ending at time t1 (seconds): path objects to their poses at t1,
    /// then Bullet's step. `before_narrow` gets the pairs the narrow phase will test. Fills the
    /// counters (broad phase, narrow phase, solver) and the contacts (pairs with manifold points,
    /// in (a, b) order; with `depth`, each one's deepest point).
    void step(double t1, bool depth, const std::function<void(const std::vector<CandidatePair>&)>& before_narrow,
              StepCounters& counters, std::vector<PairContact>& contacts);
    /// Object i's pose now, world frame.
    Pose pose(size_t i) const;
    /// Object i's linear velocity (of its frame's origin) and angular velocity now, world frame.
    std::pair<Eigen::Vector3d, Eigen::Vector3d> velocity(size_t i) const;
    /// Object i's mass (0 for static and path objects).
    double mass(size_t i) const;
    /// Kinetic plus potential energy of the moving bodies (Simulation::mechanical_energy).
    double energy(const Eigen::Vector3d& gravity) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace spt::detail
