#pragma once
// The builds from motion of one tree in the .spt byte stream (version 6; docs/spt-format.md).
#include "io/binary_io.hpp"
#include "spt/sampling_tree.hpp"

namespace spt::detail {

/// First format version that stores builds from motion.
constexpr uint32_t kMotionBuildsVersion = 6;

/// Appends `builds`: their count, then each one's node, scene, object, steps, leaf size and place
/// among the recipe steps.
void put_motion_builds(Writer& w, const std::vector<MotionBuildStep>& builds);
/// Reads the builds from motion of `tree` (already read, recipe included): each must name an inner
/// node of it and a place within its recipe, in order.
std::vector<MotionBuildStep> get_motion_builds(Reader& r, const SamplingTree& tree);

} // namespace spt::detail
