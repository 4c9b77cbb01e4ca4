#pragma once
// The reference that every tree query is tested against: no hierarchy, every pair.
#include "spt/query.hpp"

namespace spt {

/// Reference: every sphere pair (or leaf pair at `bounds`, triangle pair at `exact`)
/// tested with no tree, same definitions. For tests and the benchmark's brute-force row.
QueryResult collide_brute_force(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                                const QueryOptions& options, QueryScratch& scratch);

} // namespace spt
