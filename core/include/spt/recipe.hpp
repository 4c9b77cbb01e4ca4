#pragma once
/// Replaying an authoring recipe (spt/split_recipe.hpp) on the samples of a changed mesh:
/// the manual splits are redone by region, so a tree authored once survives the next
/// export of the model. What `spt convert NEW_MESH --recipe OLD.spt` does. A split made at a
/// pose of an animated mesh (RecipeStep::pose) is redone with the samples at that pose.
#include "spt/mesh.hpp"
#include "spt/sampling_tree.hpp"
#include <memory>
#include <string>
#include <vector>

namespace spt {

struct AnimatedMesh; // animation.hpp
struct SptDocument;  // spt_file.hpp

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
/// A step made at a clip's pose needs the overload below: here it is Error(BadInput).
SamplingTree replay_recipe(const SamplingTree& authored, const SampleSet& samples, const TriangleMesh& mesh,
                           ReplayReport* report = nullptr);

/// As above, over `doc`'s samples (its trees are not read), each step selecting where its
/// recorded pose puts them: the samples follow `animated`, the mesh `doc` was made from, posed by
/// the step's clip at its time (DeformingModel), and visible-only strokes test against the mesh
/// at that pose. Steps at the bind pose replay as above. A step's clip that `animated` lacks is
/// Error(BadInput) naming the clips it has.
SamplingTree replay_recipe(const SamplingTree& authored, const SptDocument& doc,
                           std::shared_ptr<const AnimatedMesh> animated, ReplayReport* report = nullptr);

/// True when some step of some tree of `doc` was made at a clip's pose: replaying it needs the
/// new mesh's animation (import_animated_mesh).
bool recipe_has_poses(const SptDocument& doc);

} // namespace spt
