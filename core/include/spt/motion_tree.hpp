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
    /// keeps the tree good at poses the motion did not record.
    double random_weight = 0.25;
};

/// Builds a tree named `name` over all samples of `recording.model.document`'s sample set
/// `samples` for the recorded motion; deterministic for equal input and any thread count.
/// Error(BadInput) if `samples` is not the recording's sample set (its size differs).
SamplingTree build_motion_tree(std::string name, const SampleSet& samples, const MotionRecording& recording,
                               const MotionBuildOptions& options = {});

/// Builds under active node `node` of `tree` for the motion, as SamplingTree::build_subtree builds
/// automatically (the rest of the tree unchanged but for the path's bounds). The motion is recorded
/// on `tree`'s object (record_motion).
EditResult build_motion_subtree(SamplingTree& tree, NodeId node, const SampleSet& samples,
                                const MotionRecording& recording, const MotionBuildOptions& options = {});

} // namespace spt
