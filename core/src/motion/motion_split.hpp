#pragma once
// The split chooser of a build from motion (spt/motion_tree.hpp).
#include "spt/motion.hpp"
#include "tree/split_chooser.hpp"
#include <vector>

namespace spt::detail {

// Chooses, at nodes the recorded motion brings near a partner, the binned plane that minimises
// sum over the children of (share of recorded steps the child is entered + w * its volume over
// the parent's) * its samples. A child is entered at a step when one of its samples' sampling
// spheres lies within (child radius - distance of the sample from the child's centre) of a partner.
class MotionSplit : public SplitChooser {
public:
    MotionSplit(const SampleSet& samples, const MotionRecording& recording, double random_weight, uint32_t leaf_size);
    Answer choose(const uint32_t* members, size_t n, NodeId id, std::vector<uint8_t>& left) const override;

private:
    const SampleSet& samples_;
    double random_weight_;
    size_t leaf_size_;
    uint32_t steps_ = 0;                  // recorded steps with a reach
    std::vector<uint32_t> first_;         // per sample: its first entry (CSR), then the total
    std::vector<uint32_t> entry_step_;    // per entry: index into the reaches
    std::vector<float> entry_gap_;        // per entry: its gap, model units
};

} // namespace spt::detail
