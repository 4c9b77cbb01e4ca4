#pragma once
// The authoring recipe of one tree in the .spt byte stream (version 3; docs/spt-format.md).
#include "io/binary_io.hpp"
#include "spt/sampling_tree.hpp"

namespace spt::detail {

/// Bytes of one stored stroke.
constexpr size_t kStrokeBytes = 156;

/// Appends `recipe`: step count, then each step's node id, stroke count and strokes.
void put_recipe(Writer& w, const std::vector<RecipeStep>& recipe);
/// Reads a recipe for `tree` (already read): every step must name an inner node of it.
std::vector<RecipeStep> get_recipe(Reader& r, const SamplingTree& tree);

} // namespace spt::detail
