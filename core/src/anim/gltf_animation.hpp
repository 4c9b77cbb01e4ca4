#pragma once
// What assimp 5.2.5 loses of a glTF 2.0 file's animation, read from the file itself: a sampler's
// interpolation (STEP comes through as plain keys, CUBICSPLINE as its values without tangents)
// and the skin weights it drops without a word (0 and NaN, so a vertex with a NaN weight is
// renormalised instead of refused).
#include "io/gltf_file.hpp"
#include "anim/rig_import.hpp"
#include "spt/animation.hpp"

namespace spt::detail {

// Throws BadInput naming the file, mesh and vertex for a skin weight (WEIGHTS_n of a mesh that a
// skinned node holds) that is NaN, infinite or negative, or a vertex whose weights sum to 0.
void check_gltf_skin_weights(GltfFile& file);

// Replaces `clips` (assimp's, in file order) by the file's own animations: each channel's node
// found in `rig` by the name assimp gives it ("nodes[i]" when it has none), each sampler's
// interpolation, keys and tangents as the file has them, weights channels on every mesh in
// `morphs` that the channel's node holds. Names, durations and joints_animated as rig_import
// computes them; BadInput naming clip, node and key for times out of order or not finite and
// values that are not numbers.
void apply_gltf_animation(GltfFile& file, const Rig& rig, const std::vector<MorphMesh>& morphs, std::vector<Clip>& clips);

} // namespace spt::detail
