#pragma once
/// Replaying an authoring recipe (spt/split_recipe.hpp) on the samples of a changed mesh:
/// the manual splits are redone by region, so a tree authored once survives the next
/// export of the model. What `spt convert NEW_MESH --recipe OLD.spt` does.
#include "spt/mesh.hpp"
#include "spt/sampling_tree.hpp"
#include <string>
#include <vector>

namespace spt {

/// What replaying a recipe did.
struct ReplayReport {
    size_t replayed = 0;              ///< steps that split their node again
    std::vector<std::string> skipped; ///< one sentence per step not replayed: which step and why
};

/// A tree named `name` whose root holds every sample, radius and bounds by core's defaults:
/// where manual authoring starts.
SamplingTree unsplit_tree(const std::string& name, const SampleSet& samples);

/// Replays `authored`'s recipe over `samples` (of `mesh`, for visible-only strokes), step by
/// step from an unsplit tree of the same name. A step whose node does not exist, or whose
/// strokes now select none or all of the node's samples, is reported in `report`, not guessed.
SamplingTree replay_recipe(const SamplingTree& authored, const SampleSet& samples, const TriangleMesh& mesh,
                           ReplayReport* report = nullptr);

} // namespace spt
