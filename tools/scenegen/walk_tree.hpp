#pragma once
// A tree with the feet split off at the root, as a person would select them in the editor
// for a walking motion (paper §3-3): the parts likely to collide sit high in the tree.
#include "spt/spt_file.hpp"

namespace spt::scenegen {

/// Adds a tree named `name` to `doc`: the root split into the samples within `foot_height` of the
/// lowest sample (the feet, left child) and the rest; each part then split at the median of its
/// longest axis until a node holds at most 8 samples. `at` (per sample, object frame; empty: the
/// document's own points) is the pose the selection is made at, as an author would make it with
/// the figure posed where a foot strikes.
void add_feet_first_tree(SptDocument& doc, const std::string& name, double foot_height,
                         const std::vector<Eigen::Vector3d>& at = {});

} // namespace spt::scenegen
