#pragma once
/// A stepping simulation of a scene that runs the code of the listed effects only
/// (docs/scenes.md). Objects move by velocities and paths, collisions are found by the broad
/// phase and sampling-tree queries; `response` moves objects back along their motion (paper
/// §3-4-3), or `dynamics` feeds contact manifolds of sampling spheres to Bullet's constraint
/// solver (masses, friction, restitution, resting contact). Deterministic for any number of
/// threads. World frame, model units, seconds.
#include "spt/broad_phase.hpp"
#include "spt/deforming_model.hpp"
#include "spt/query_scratch.hpp"
#include "spt/scene.hpp"
#include "spt/task_system.hpp"
#include <memory>
#include <string>
#include <vector>

namespace spt {
namespace detail {
class DynamicsWorld;
}

/// Exact counts and times of one step; a stage that is off leaves its fields 0.
struct StepCounters {
    uint64_t candidate_pairs = 0; ///< pairs from the broad phase (contacts)
    uint64_t colliding_pairs = 0; ///< candidate pairs that collide (or, with ccd, touch within the step)
    uint64_t node_pairs = 0;      ///< node pairs of every contact, exact, depth, pairs and ccd query
    uint64_t sphere_tests = 0;    ///< sampling-sphere pair tests of the same queries
    uint64_t triangle_tests = 0;  ///< exact triangle tests (level or effect exact)
    uint64_t depth_queries = 0;   ///< deepest-pair queries (depth)
    uint64_t ccd_queries = 0;     ///< continuous queries, one per candidate pair that moved (ccd)
    uint64_t responses = 0;       ///< colliding pairs a dynamic object of which was moved or slowed (response)
    int64_t ns_broad = 0;         ///< nanoseconds of the broad phase
    int64_t ns_narrow = 0;        ///< nanoseconds of the contact, exact and pairs queries
    int64_t ns_depth = 0;         ///< nanoseconds of the depth queries
    int64_t ns_ccd = 0;           ///< nanoseconds of the continuous queries
    int64_t ns_response = 0;      ///< nanoseconds of the response
    int64_t ns_deform = 0;        ///< nanoseconds of posing the animated objects (deform)
    int64_t ns_dynamics = 0;      ///< nanoseconds of the rigid-body solver and integration (dynamics)
};

/// One point of a contact manifold (effect dynamics).
struct ContactPoint {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< world frame, on b's surface
    Eigen::Vector3d normal = Eigen::Vector3d::UnitX(); ///< world frame, unit, from a towards b
    double depth = 0;      ///< penetration along the normal, model units; < 0: apart by that much (speculative)
    double impulse = 0;    ///< normal impulse the solver applied this step, mass x model units / s
    int age = 0;           ///< steps the point has been kept (0: new this step; the solver warm-starts the others)
};

/// One colliding object pair of a step.
struct PairContact {
    uint32_t a = 0, b = 0;  ///< object indices, a < b
    bool has_depth = false; ///< depth, point and normal are set (effect depth)
    double depth = 0;       ///< deepest sphere penetration, model units (0: touching within the ccd tolerance)
    Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< world frame, middle of the deepest overlap
    Eigen::Vector3d normal = Eigen::Vector3d::UnitX(); ///< world frame, unit, from a towards b
    /// The overlap is deep (two spheres overlap by more than half their radii's sum: surfaces cross): depth, point
    /// and normal come from the deepest pair and its two active nodes, not every pair (docs/scenes.md)
    bool deep = false;
    bool has_toi = false;   ///< toi is set (effect ccd)
    double toi = 1;         ///< time of impact as a fraction of the step, [0, 1]
    std::vector<SpherePair> pairs; ///< every overlapping sphere pair (effect pairs), spheres of a's and b's trees
    /// Effect dynamics: the pair's contact manifold after the step, at most 4 points (deepest, then
    /// spread to span the contact); the pair is listed while it has points.
    std::vector<ContactPoint> manifold;
};

/// What one step did.
struct StepResult {
    int step = 0;        ///< 1 for the first step
    double time = 0;     ///< seconds at the end of the step (step * dt)
    StepCounters counters; ///< work done
    std::vector<PairContact> contacts; ///< colliding pairs, in (a, b) order
    uint64_t state_hash = 0; ///< state_hash() of the poses after the step
};

/// 64-bit FNV-1a over every pose's translation x, y, z and rotation w, x, y, z as double bits, in order.
uint64_t state_hash(const std::vector<Pose>& poses);

/// The scene in motion.
class Simulation {
public:
    /// Simulates `scene` with `effects` (normally scene.effects), each parallel stage split into
    /// `threads` jobs (>= 1; at most that many run at once) run on the host's `tasks` if given (it
    /// must outlive the simulation), else on the library's pool. Throws Error(BadInput) if
    /// `exact` is asked of an object without a mesh.
    Simulation(Scene scene, EffectSet effects, int threads = 1, TaskSystem* tasks = nullptr);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    /// Runs one step and returns what it did (valid until the next step). Throws Error(BadInput)
    /// naming the object if the motion would carry it beyond 1e16 or to infinity (the state
    /// stays that of the last step).
    const StepResult& step();
    /// The scene simulated. With the effects deform and contacts alone (no depth, pairs, response,
    /// ccd or exact), an animated object's model holds this step's pose only where the step's
    /// queries read it (DeformingModel::pose_lazily).
    const Scene& scene() const { return scene_; }
    /// The effects that run.
    EffectSet effects() const { return effects_; }
    /// Steps run so far.
    int steps_done() const { return steps_; }
    /// Poses after the last step (initial poses before the first), object order, world frame.
    const std::vector<Pose>& poses() const { return poses_; }
    /// Poses before the last step's response (`ghost`); equal to poses() without a response.
    const std::vector<Pose>& ghost_poses() const { return ghost_; }
    /// Linear velocities, world frame, model units / s (path and static objects: zero).
    const std::vector<Eigen::Vector3d>& velocities() const { return velocity_; }
    /// Object i's linear (model units / s) and angular (rad / s) velocity now, world frame: a
    /// moving object's own, a path object's path's (path_velocity at this time), a static one's
    /// zero; zero for all without the effect motion, which moves nothing.
    std::pair<Eigen::Vector3d, Eigen::Vector3d> object_velocity(size_t i) const;
    /// Broad-phase spheres of the last step (swept over the step with ccd).
    const std::vector<BroadSphere>& broad_spheres() const { return spheres_; }
    /// Kinetic plus potential energy of the moving objects now (mass x model units^2 / s^2):
    /// sum of m v^2 / 2 + w^T I w / 2 - m g.x over their centres of mass (g: the scene's gravity
    /// with effect gravity, else none). Objects without a mass (every one without effect dynamics)
    /// count with mass 1 and no inertia.
    double mechanical_energy() const;
    /// Object i's mass (dynamics: its own or density x volume; else 1), mass units.
    double mass(size_t i) const;

private:
    void move(double t1); // to the poses at time t1, the end of the step (seconds)
    void deform(double t); // animated objects' clip times and broad-phase spheres at scene time t (seconds)
    void pose_needed(const std::vector<CandidatePair>& pairs); // poses the animated objects of these pairs
    void run_contacts(StepCounters& c);
    void respond(StepCounters& c);
    void step_dynamics(double t1, StepCounters& c); // effect dynamics: the solver's step in place of move and contacts
    bool respond_pair(const PairContact& pc, const std::vector<SpherePair>& start_pairs, QueryScratch& scratch);
    bool dynamic(uint32_t i) const { return scene_.objects[i].motion == MotionKind::Velocity; }
    Scene scene_;
    EffectSet effects_;
    int threads_;
    TaskSystem* tasks_;
    int steps_ = 0;
    std::vector<Pose> poses_, previous_, ghost_;
    std::vector<Eigen::Vector3d> velocity_, angular_;
    std::vector<BroadSphere> spheres_;
    BroadPhase broad_;
    std::vector<QueryScratch> scratch_; // one per thread
    // Per object: its deforming model when it is animated and the effect deform runs (its
    // scene object's model then points into it), else null.
    std::vector<std::shared_ptr<DeformingModel>> deforming_;
    std::vector<double> clip_time_; // per object: its clip's time this step (animated objects)
    std::vector<uint8_t> posed_;    // per object: its model is at that time (posed when a query needs it)
    bool lazy_pose_ = false;        // posed lazily (DeformingModel::pose_lazily): contacts are all the step asks
    // Per contact of the step: the sphere pairs depth's `all` query found, which are the
    // response's first backtrack query when the pair's poses have not changed since; for a deep
    // overlap, its deepest pair alone, where the response's search starts.
    std::vector<std::vector<SpherePair>> start_pairs_;
    StepResult result_;
    std::unique_ptr<detail::DynamicsWorld> dynamics_; // effect dynamics: Bullet's world of the objects
    std::string dynamics_failure_; // why a step of Bullet's world was refused: every later one is too
};

} // namespace spt
