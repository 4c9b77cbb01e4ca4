#pragma once
/// Automatic construction of sampling trees (the paper's future work, §4).
#include "spt/sampling_tree.hpp"
#include "spt/task_system.hpp"
#include <atomic>

namespace spt {

/// How the builder chooses a split.
enum class SplitStrategy {
    Median, ///< median of the longest axis of the node's sample box
    Volume, ///< binned plane minimising the children's sphere volumes weighted by sample count (median near leaves)
};

/// Options for build_tree.
struct BuildOptions {
    uint32_t leaf_size = 8;               ///< split until an active node holds at most this many samples
    SplitStrategy strategy = SplitStrategy::Volume; ///< how a node is split
    RadiusRule radius;                    ///< sampling-sphere radius rule
    BoundsMethod bounds = BoundsMethod::Tight;    ///< how bounding spheres are made
    /// Keep each active node's samples within one radius class (kRadiusClassRatio), so the
    /// node radius is at least 1/ratio of every member's own: what tolerance sampling assumes.
    bool radius_coherent = false;
    /// Threads the builder may use (1: the calling thread only); the tree is the same on any count.
    int threads = 1;
    /// A host's threads to run that work on (spt/task_system.hpp); null: the library's pool.
    TaskSystem* tasks = nullptr;
    /// Another thread sets it to stop the build: looked at as each node of 1,024 samples or
    /// more is split and before the radii and the bounds; throws Cancelled. Null: never stops.
    const std::atomic<bool>* cancel = nullptr;
};

/// Builds a tree over all samples; deterministic for equal input. Active nodes hold at most
/// leaf_size samples (and one radius class if radius_coherent). Throws Cancelled (options.cancel).
SamplingTree build_tree(std::string name, const SampleSet& samples, const BuildOptions& options = {});

} // namespace spt
