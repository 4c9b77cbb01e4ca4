#pragma once
/// Automatic construction of sampling trees (the paper's future work, §4).
#include "spt/sampling_tree.hpp"

namespace spt {

/// How the builder chooses a split.
enum class SplitStrategy {
    Median, ///< median of the longest axis of the node's sample box
    Volume, ///< binned plane that minimises the children's bounding-sphere volumes
};

/// Options for build_tree.
struct BuildOptions {
    uint32_t leaf_size = 8;               ///< split until an active node holds at most this many samples
    SplitStrategy strategy = SplitStrategy::Volume;
    RadiusRule radius;                    ///< sampling-sphere radius rule
    BoundsMethod bounds = BoundsMethod::Tight;
};

/// Builds a tree over all samples; deterministic for equal input.
SamplingTree build_tree(std::string name, const SampleSet& samples, const BuildOptions& options = {});

} // namespace spt
