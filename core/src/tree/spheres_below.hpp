#pragma once
// How many sampling spheres lie below each node of a query layout: what a lazy pose cuts its
// regions by and what a tight refit decides its search by.
#include "spt/compact_tree.hpp"
#include <cstdint>
#include <vector>

namespace spt::detail {

/// Per node of `nodes` (CompactTree order), the number of spheres in its active nodes below it
/// (its own count for an active node).
inline std::vector<uint32_t> spheres_below(const std::vector<CompactNode>& nodes) {
    std::vector<uint32_t> below(nodes.size());
    for (size_t i = nodes.size(); i-- > 0;) // children follow their parent
        below[i] = nodes[i].is_active() ? nodes[i].count : below[i + 1] + below[nodes[i].first];
    return below;
}

} // namespace spt::detail
