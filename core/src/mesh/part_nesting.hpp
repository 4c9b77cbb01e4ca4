#pragma once
// Which closed parts of a mesh hold which: a hollow's inner wall faces into its cavity.
#include "spt/mesh.hpp"
#include <vector>

namespace spt::detail {

/// For each part (faces of `m`; open parts, by m.on_open_part, count 0 and hold nothing): how
/// many other closed parts hold it wholly, by ray parity from one of its vertices (exact) and
/// no face of it meeting theirs (exact triangle tests). A part poking through another (an eye
/// through a head's socket) is held by neither: a solid of its own, not a cavity's wall.
std::vector<int> nesting_depths(const TriangleMesh& m, const std::vector<std::vector<uint32_t>>& parts);

} // namespace spt::detail
