#pragma once
/// Per-query working memory. The caller owns one per thread and reuses it: a
/// query grows it only when it meets a larger model, so repeated queries
/// allocate nothing.
#include <cstdint>
#include <memory>
#include <vector>

namespace spt {

/// A colliding pair found by a query in mode `all`.
struct SpherePair {
    uint32_t a = 0, b = 0; ///< sphere indices (node indices at level `bounds`) in each CompactTree
    uint32_t node_a = 0, node_b = 0; ///< the active nodes holding them (CompactTree node indices)
    float depth = 0;       ///< reach - |c1 - c2|, model units
    float reach = 0;       ///< r1 + r2 (+ inflate), model units
};

/// An intersecting triangle pair found at level `exact` in mode `all`.
struct TrianglePair {
    uint32_t a = 0, b = 0; ///< triangle indices in each mesh
};

namespace detail {
struct ScratchBuffers;
struct ScratchAccess;
}

/// Working memory of one query at a time; give each thread its own.
class QueryScratch {
public:
    /// Empty buffers; the first query sizes them.
    QueryScratch();
    /// Frees the buffers.
    ~QueryScratch();
    QueryScratch(const QueryScratch&) = delete;
    QueryScratch& operator=(const QueryScratch&) = delete;
    /// Takes over the buffers; the source may only be destroyed or assigned to.
    QueryScratch(QueryScratch&&) noexcept;
    /// Takes over the buffers; the source may only be destroyed or assigned to.
    QueryScratch& operator=(QueryScratch&&) noexcept;

    /// Sphere (or leaf) pairs of the last query in mode `all`.
    const std::vector<SpherePair>& pairs() const;
    /// Triangle pairs of the last `exact` query in mode `all`.
    const std::vector<TrianglePair>& triangle_pairs() const;
private:
    friend struct detail::ScratchAccess; // the query code's view of the buffers (query/scratch.hpp)
    std::unique_ptr<detail::ScratchBuffers> b_;
};

} // namespace spt
