#pragma once
// A node id that a later section of a .spt file refers to (a recipe step's split, a build from
// motion): read and checked against the tree read before it, one rule and one message for both.
#include "io/binary_io.hpp"
#include "spt/sampling_tree.hpp"
#include <string>

namespace spt::detail {

/// Reads a node id (`field`) that must name an inner node of `tree`; fails naming the offset, as
/// "`what` N: tree 'T' has no inner node of that id".
inline uint64_t get_inner_node_id(Reader& r, const SamplingTree& tree, const char* field, const std::string& what) {
    const size_t at = r.offset();
    const auto id = r.get<uint64_t>(field);
    const TreeNode* n = tree.find(id);
    if (!n || n->active)
        r.fail(at, what + " " + std::to_string(id) + ": tree '" + tree.name() + "' has no inner node of that id");
    return id;
}

} // namespace spt::detail
