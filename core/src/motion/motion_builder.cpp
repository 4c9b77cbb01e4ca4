// Trees built for a recorded motion: the automatic builder, with the motion's split chooser
// asked first at every node.
#include "motion/motion_split.hpp"
#include "spt/error.hpp"
#include "spt/motion_tree.hpp"

namespace spt {

SamplingTree build_motion_tree(std::string name, const SampleSet& samples, const MotionRecording& recording,
                               const MotionBuildOptions& options) {
    const detail::MotionSplit chooser(samples, recording, options.random_weight);
    std::vector<uint32_t> all(samples.size());
    for (uint32_t i = 0; i < samples.size(); ++i) all[i] = i;
    return detail::build_over(std::move(name), samples, all, options.build, kMaxNodeDepth, &chooser);
}

EditResult build_motion_subtree(SamplingTree& tree, NodeId node, const SampleSet& samples,
                                const MotionRecording& recording, const MotionBuildOptions& options) {
    const detail::MotionSplit chooser(samples, recording, options.random_weight);
    return detail::TreeGraft::build_subtree(tree, node, samples, options.build, &chooser);
}

} // namespace spt
