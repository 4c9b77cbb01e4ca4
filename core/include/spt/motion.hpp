#pragma once
/// Authoring from motion (paper §3-3: the regions likely to collide for a kind of motion belong
/// high in the tree): a scene is run with one object's tree, and every step's pose of that object,
/// the objects it met and the samples whose sampling spheres took part in a contact are recorded.
/// The recording colours samples by contact (the editor's heat map), drives build_motion_tree
/// (spt/motion_tree.hpp) and measures trees on the motion (measure_motion_cost). Object frame of
/// the recorded object, model units, seconds.
#include "spt/animation.hpp"
#include "spt/query.hpp"
#include "spt/scene.hpp"
#include "spt/spt_file.hpp"
#include "spt/task_system.hpp"
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace spt {

/// The model recorded in place of the scene object's own: a tree of a document, with the mesh
/// the document was made from (and its clips, for an animated object).
struct MotionModel {
    std::shared_ptr<const SptDocument> document; ///< samples and trees (required)
    std::string tree;                            ///< the tree the scene runs with; empty: the first
    /// The mesh the document was made from, with its rig and clips when the scene animates the
    /// object. Null: the scene object's own mesh when it has one (its clips too), else spheres only.
    std::shared_ptr<const AnimatedMesh> mesh;
};

/// Another object the recorded one met in the broad phase at a step.
struct MotionPartner {
    uint32_t object = 0;      ///< index in the scene's objects
    Pose pose;                ///< its pose in the recorded object's frame (the recorded object at the identity)
    double clip_time = 0;     ///< its clip's time, seconds (animated partners under effect deform)
    bool contact = false;     ///< the two collided at this step (the scene's level)
};

/// One step of the motion.
struct MotionStep {
    int step = 0;             ///< 1 for the first step
    double time = 0;          ///< scene seconds at the end of the step
    Pose pose;                ///< the recorded object's world pose where the step's queries ran (before any response)
    double clip_time = 0;     ///< its clip's time, seconds (animated under effect deform; else 0)
    std::vector<MotionPartner> partners; ///< broad-phase partners, object order
};

/// Samples near a partner at one step: what build_motion_tree reads.
struct MotionReach {
    uint32_t step = 0; ///< index into MotionRecording::steps
    /// (sample, gap): sampling spheres within MotionRecording::reach of a partner's leaf bounding
    /// spheres, the gap in model units (0 when they overlap), sample order.
    std::vector<std::pair<uint32_t, float>> near;
};

/// What a run of a scene recorded of one object.
struct MotionRecording {
    std::string scene_file;      ///< the scene file, as its Scene names it
    std::string object;          ///< the recorded object's name
    uint32_t object_index = 0;   ///< its index in the scene
    std::string tree;            ///< the tree the scene ran with
    std::string clip;            ///< its clip's name when animated under effect deform; empty otherwise
    std::vector<MotionStep> steps; ///< one per step, in order
    /// Per sample of the document: at how many steps its sampling sphere overlapped a partner's
    /// (the heat map).
    std::vector<uint32_t> contact_steps;
    uint32_t most_contact_steps = 0; ///< the largest entry of contact_steps
    uint32_t steps_in_contact = 0;   ///< steps at which the object collided with some partner
    double reach = 0;                ///< how far MotionReach looks, model units
    std::vector<MotionReach> reaches; ///< at most MotionOptions::reach_steps steps, in step order
    /// The scene as run: the partners' models (shared), the recorded object's replaced by the recorded model.
    std::shared_ptr<const Scene> scene;
    MotionModel model;           ///< what was recorded
};

/// How record_motion runs.
struct MotionOptions {
    int steps = 0;           ///< steps to run; 0: the scene's own count
    int threads = 1;         ///< jobs for the simulation's parallel stages (>= 1)
    TaskSystem* tasks = nullptr; ///< a host's threads; null: the library's pool
    /// At most this many steps get a MotionReach: what the builder reads. Evenly spread over the
    /// steps that meet a partner (over all steps when an object of the scene deforms), the last included.
    int reach_steps = 64;
    /// MotionRecording::reach as a fraction of the object's diagonal; 0: the default (4%).
    double reach_fraction = 0;
    const std::atomic<bool>* cancel = nullptr; ///< set by another thread: stops between steps, throws Cancelled
    /// Called on the recording thread after each step with (steps done, steps in all).
    std::function<void(int done, int total)> progress;
};

/// Index of the object named `name` in `scene`; Error(BadInput) naming the scene and the objects it has.
uint32_t find_object(const Scene& scene, const std::string& name);

/// Runs `scene` (loaded: load_scene) for options.steps steps with its own effects, object `object`
/// given `model`'s tree, and records that object's motion. Error(BadInput) when the object is not
/// in the scene, the document was not made from the object's mesh, or the scene cannot run; Cancelled
/// when options.cancel is set. Deterministic: the same scene, model and steps record the same.
MotionRecording record_motion(const Scene& scene, const std::string& object, const MotionModel& model,
                              const MotionOptions& options = {});

/// Figures of one tree on a recorded motion.
struct MotionCost {
    double median_ns = 0;         ///< median over the steps of a step's queries' time (each query's best), nanoseconds
    double mean_ns = 0;           ///< mean of the same step times, nanoseconds
    double p90_ns = 0;            ///< the 90th percentile of the same step times, nanoseconds: the expensive steps
    double mean_node_pairs = 0;   ///< node pairs per query
    double mean_sphere_tests = 0; ///< sampling-sphere pair tests per query
    double collide_share = 0;     ///< share of the queries that collide
    size_t queries = 0;           ///< queries timed: one per step and partner
    std::vector<QueryCounters> counters; ///< per query, steps in order, partners in order within a step
    bool cancelled = false;       ///< stopped early; the figures are incomplete
};

/// Times each of `trees` (trees over `recording.model.document`'s samples; they need not be in it)
/// against every step's partners at the recorded poses (the object posed at the step's clip time
/// when animated), at `query`'s level and mode (`spt query`'s). The trees take turns within each of
/// `rounds` rounds, so that a machine's drift falls on all alike, and each query keeps its best time.
/// One figure per tree, in order. `cancel` (may be null) stops between steps; `progress` (may be
/// empty) gets the share done. Error(BadInput) if a tree is over other samples.
std::vector<MotionCost> measure_motion_cost(const MotionRecording& recording, const std::vector<const SamplingTree*>& trees,
                                            const QueryOptions& query, int rounds = 3,
                                            const std::atomic<bool>* cancel = nullptr,
                                            const std::function<void(double)>& progress = {});

} // namespace spt
