#pragma once
/// The paper's node numbering (§3-4-1): the root is 1, the children of node i are
/// 2i (left) and 2i+1 (right), the parent is i/2. Depth is the bit length minus one.
#include <cstdint>

namespace spt {

/// A node's paper id: 1 for the root, 2i and 2i+1 for the children of i.
using NodeId = uint64_t;

/// Deepest level a node id can name (ids stay within 64 bits).
constexpr int kMaxNodeDepth = 62;

/// Id of the root node.
constexpr NodeId root_id() { return 1; }
/// Id of the left child (the paper's "parent ∩ selection").
constexpr NodeId left_child(NodeId id) { return id << 1; }
/// Id of the right child (the paper's "parent − left").
constexpr NodeId right_child(NodeId id) { return (id << 1) | 1; }
/// Id of the parent; 0 for the root.
constexpr NodeId parent_of(NodeId id) { return id >> 1; }
/// Depth of a node: 0 for the root.
constexpr int node_depth(NodeId id) { return 63 - __builtin_clzll(id); }
/// True if id names a left child.
constexpr bool is_left_child(NodeId id) { return id > 1 && (id & 1) == 0; }

} // namespace spt
