#pragma once
// The authoring recipe of one tree in the .spt byte stream (versions 3 to 5; docs/spt-format.md).
#include "io/binary_io.hpp"
#include "spt/sampling_tree.hpp"

namespace spt::detail {

/// Bytes of one stored stroke.
constexpr size_t kStrokeBytes = 156;

/// Appends `recipe`: step count, then each step's node id, stroke count and strokes (from
/// `version` 5 on with their kind and shape), and from `version` 4 on its pose (clip name, time).
void put_recipe(Writer& w, const std::vector<RecipeStep>& recipe, uint32_t version);
/// Reads a recipe of file `version` for `tree` (already read): every step must name an inner node of it.
std::vector<RecipeStep> get_recipe(Reader& r, const SamplingTree& tree, uint32_t version);
/// The oldest format version that holds `recipe`: 0 for none (versions 1 and 2 hold no recipe),
/// 3 for rectangles at the bind pose, 4 with a step at a clip's pose, 5 with a stroke of
/// another kind (lasso, brush, linked, invert, grow, shrink). The one place that knows which
/// feature needs which version; a later version adds its test here.
uint32_t recipe_version(const std::vector<RecipeStep>& recipe);
/// Why a file of `version` (3 or later) whose recipes need another version is refused: each
/// document has one encoding, the oldest version that holds it.
std::string recipe_version_mismatch(uint32_t version);

} // namespace spt::detail
