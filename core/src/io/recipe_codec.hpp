#pragma once
// The authoring recipe of one tree in the .spt byte stream (versions 3 and 4; docs/spt-format.md).
#include "io/binary_io.hpp"
#include "spt/sampling_tree.hpp"

namespace spt::detail {

/// Bytes of one stored stroke.
constexpr size_t kStrokeBytes = 156;

/// Appends `recipe`: step count, then each step's node id, stroke count and strokes, and from
/// `version` 4 on its pose (clip name, time).
void put_recipe(Writer& w, const std::vector<RecipeStep>& recipe, uint32_t version);
/// Reads a recipe of file `version` for `tree` (already read): every step must name an inner node of it.
std::vector<RecipeStep> get_recipe(Reader& r, const SamplingTree& tree, uint32_t version);
/// True when some step was made at a clip's pose: the recipe needs version 4.
bool has_poses(const std::vector<RecipeStep>& recipe);

} // namespace spt::detail
