#pragma once
/// Trees built for a recorded motion (spt/motion.hpp): the builder of tree_builder.hpp, whose
/// split planes are chosen, where the motion comes near a partner, to minimise the expected work
/// of a query over the recorded steps (a surface-area-heuristic cost in which a child's chance of
/// being entered is the share of recorded steps at which its bounding sphere meets a partner),
/// so the samples that collide most end up in small nodes near the root. Parts of the object the
/// motion never brings near a partner are built as build_tree builds them.
#include "spt/motion.hpp"
#include "spt/tree_builder.hpp"

namespace spt {

/// Options of a build from motion.
struct MotionBuildOptions {
    /// Leaf size, radius rule, bounds, threads and cancel, as build_tree takes them; also how the
    /// parts the motion never reaches are built.
    BuildOptions build;
    /// Weight of the random-pose term (a child's bounding-sphere volume over its parent's, the
    /// Volume strategy's cost) beside the motion's (the share of recorded steps a child is entered):
    /// keeps the tree good at poses the motion did not record. A build tries this weight and a
    /// quarter of it, and the automatic build, and keeps what works least on the motion.
    double random_weight = 1;
    /// Recorded steps (evenly spread) on which the candidates are compared; 0: every step.
    int compare_steps = 48;
};

/// Which candidate a build from motion kept, and what each costs on the motion: node pairs plus
/// sphere tests / kSphereTestsPerNodePair per query, mean over the compared steps' queries.
struct MotionBuildReport {
    double work_motion = 0;        ///< the motion-built candidate kept among the weights tried
    double random_weight = 0;      ///< its weight
    double work_automatic = 0;     ///< the automatic build of the same node
    bool kept_automatic = false;   ///< the automatic build worked least: the motion changed nothing worth having
};

/// Sphere tests that cost about one node pair: the weight of the builds' comparison. Fitted to the
/// automatic trees' times on the walk and the robot arm (docs/editor.md): a node pair about 17 ns,
/// a sphere test 0.3 to 0.55 ns (8-wide blocks).
constexpr double kSphereTestsPerNodePair = 40;

/// Builds a tree named `name` over all samples of `recording.model.document`'s sample set
/// `samples` for the recorded motion; deterministic for equal input and any thread count.
/// Error(BadInput) if `samples` is not the recording's sample set (its size differs).
SamplingTree build_motion_tree(std::string name, const SampleSet& samples, const MotionRecording& recording,
                               const MotionBuildOptions& options = {}, MotionBuildReport* report = nullptr);

/// Builds under active node `node` of `tree` for the motion, as SamplingTree::build_subtree builds
/// automatically (the rest of the tree unchanged but for the path's bounds). The motion is recorded
/// on `tree`'s object (record_motion).
EditResult build_motion_subtree(SamplingTree& tree, NodeId node, const SampleSet& samples,
                                const MotionRecording& recording, const MotionBuildOptions& options = {},
                                MotionBuildReport* report = nullptr);

/// Adds to `doc` a tree named `name` built for the motion of `object` in the scene file
/// `scene_path` (run for `steps` steps, 0: the scene's count, with an automatic tree of `options.build`
/// as the object's model), and records the build in the tree (MotionBuildStep at the root, its scene written
/// as `scene_in_file`: relative to the folder of the .spt file the document goes to). `mesh` is the
/// mesh the document was made from (with its clips for an animated object; null: spheres only). A
/// tree of that name is replaced only if `replace` (else Error(CannotWrite)). What `spt convert MESH
/// --motion SCENE --object NAME` does.
const SamplingTree& add_motion_tree(SptDocument& doc, std::shared_ptr<const AnimatedMesh> mesh,
                                    const std::string& scene_path, const std::string& scene_in_file,
                                    const std::string& object, const std::string& name, MotionBuildOptions options,
                                    int steps = 0, bool replace = false);

/// Redoes `recorded`'s builds from motion on `tree` (over `doc`'s samples, `mesh` the mesh it was
/// made from), in order, each scene path resolved against `folder` when relative, each motion
/// recorded with an automatic tree as add_motion_tree records it. What replaying a recipe does with them.
void replay_motion_builds(SamplingTree& tree, const std::vector<MotionBuildStep>& recorded, const SptDocument& doc,
                          std::shared_ptr<const AnimatedMesh> mesh, const std::string& folder, const BuildOptions& build);

} // namespace spt
