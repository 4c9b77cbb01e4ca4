// Welds vertices closer than a tolerance through a hash grid.
#include "mesh/weld.hpp"
#include "base/cancel.hpp"
#include "base/huge_pages.hpp"
#include <algorithm>
#include <cmath>
#include <utility>

namespace spt::detail {
namespace {

struct Cell {
    int64_t x, y, z;
    bool operator==(const Cell& o) const { return x == o.x && y == o.y && z == o.z; }
};

uint64_t hash_cell(const Cell& c) {
    uint64_t h = uint64_t(c.x) * 0x9E3779B97F4A7C15ull;
    h ^= uint64_t(c.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= uint64_t(c.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return h ^ (h >> 29);
}

// Open-addressing table from a cell to the first welded vertex in it; the rest of the
// cell's vertices are chained through `next`. A slot is eight bytes, the head and the top of
// the cell's hash, and the cell itself is read from `cell_of` (the cell of each welded
// vertex) only when that matches: nearly every probe of a large mesh misses the cache, and a
// small slot makes the table a quarter of the size a slot holding the cell would.
class CellTable {
public:
    /// A table sized for `expected` cells, so that it need not grow while they go in.
    explicit CellTable(size_t expected) {
        size_t cap = 1024;
        while (cap < 2 * expected) cap *= 2;
        allocate(cap);
    }
    /// Starts loading what head(c, h) reads first, and with `slot` what push(c, h) reads.
    void prefetch(uint64_t h, bool slot) const {
        __builtin_prefetch(&filled_[(h & filter_mask_) >> 6]);
        if (slot) __builtin_prefetch(&slots_[h & mask_]);
    }
    int32_t head(const Cell& c, uint64_t h, const std::vector<Cell>& cell_of) const {
        if (!(filled_[(h & filter_mask_) >> 6] >> (h & 63) & 1)) return -1; // no cell with this hash was marked
        const auto tag = uint32_t(h >> 32);
        for (size_t i = h & mask_;; i = (i + 1) & mask_) {
            const Slot s = slots_[i];
            if (s.head < 0) return -1;
            if (s.tag == tag && cell_of[size_t(s.head)] == c) return s.head;
        }
    }
    // Makes `v` the head of cell c (hash h) and returns the previous head (or -1);
    // cell_of[v] must already be c.
    int32_t push(const Cell& c, uint64_t h, int32_t v, const std::vector<Cell>& cell_of) {
        if (2 * (used_ + 1) > slots_.size()) rehash(slots_.size() * 2, cell_of);
        mark(h);
        const auto tag = uint32_t(h >> 32);
        for (size_t i = h & mask_;; i = (i + 1) & mask_) {
            if (slots_[i].head < 0) {
                slots_[i] = {v, tag};
                ++used_;
                return -1;
            }
            if (slots_[i].tag == tag && cell_of[size_t(slots_[i].head)] == c) return std::exchange(slots_[i].head, v);
        }
    }

private:
    struct Slot {
        int32_t head = -1;
        uint32_t tag = 0; // the top 32 bits of the cell's hash
    };
    // Empty slots and filter for `cap` slots (a power of two).
    void allocate(size_t cap) {
        slots_.assign(cap, Slot{});
        mask_ = cap - 1;
        filled_.assign(cap * kFilterBitsPerSlot / 64, 0);
        filter_mask_ = cap * kFilterBitsPerSlot - 1;
    }
    // Records in the filter that a cell with hash h is in the table.
    void mark(uint64_t h) { filled_[(h & filter_mask_) >> 6] |= uint64_t(1) << (h & 63); }
    void rehash(size_t cap, const std::vector<Cell>& cell_of) {
        auto old = std::move(slots_);
        allocate(cap);
        for (const Slot& s : old) {
            if (s.head < 0) continue;
            const uint64_t h = hash_cell(cell_of[size_t(s.head)]);
            mark(h);
            for (size_t i = h & mask_;; i = (i + 1) & mask_)
                if (slots_[i].head < 0) {
                    slots_[i] = s;
                    break;
                }
        }
    }
    // One bit per hash value modulo four times the slots, set for every cell put in: a probe
    // of a cell that holds nothing (nearly every probe of a mesh without copies) reads this
    // bitset, an eighth of the table's size and mostly in cache, instead of missing in the table.
    static constexpr size_t kFilterBitsPerSlot = 4;
    std::vector<Slot, HugePageAllocator<Slot>> slots_;
    std::vector<uint64_t, HugePageAllocator<uint64_t>> filled_;
    size_t mask_ = 0, used_ = 0, filter_mask_ = 0;
};

// The cell of p, and on each axis whether the cell below (lo = -1) or above (hi = 1) may
// also hold a vertex within the tolerance.
struct CellSpan {
    int64_t k[3];
    int lo[3], hi[3];
    CellSpan(const Eigen::Vector3d& p, double cell, double tolerance) {
        for (int a = 0; a < 3; ++a) {
            const double f = p[a] / cell, fl = std::floor(f);
            k[a] = int64_t(fl);
            lo[a] = (f - fl) * cell <= tolerance ? -1 : 0;
            hi[a] = (fl + 1 - f) * cell <= tolerance ? 1 : 0;
        }
    }
    Cell at(int dx, int dy, int dz) const { return {k[0] + dx, k[1] + dy, k[2] + dz}; }
};

// How many points ahead the table is prefetched: nearly every probe of a large mesh misses
// the cache, and the probes of one point do not wait on those of the points before it.
constexpr size_t kPrefetchAhead = 16;

} // namespace

std::vector<uint32_t> weld_positions(const std::vector<Eigen::Vector3d>& positions, double tolerance,
                                     std::vector<Eigen::Vector3d>& welded, const std::atomic<bool>* cancel) {
    std::vector<uint32_t> map(positions.size());
    welded.clear();
    // Cells four times the tolerance: a match lies in this cell, or in a neighbour on a side
    // where the point is within the tolerance of the cell's boundary (half the points per
    // axis: 3.4 cells on average; cells twice the tolerance would always take 8). Far below
    // the spacing of a mesh's vertices, a cell holds one vertex or none.
    // A cell also at least 2^-60 of the largest coordinate, so every cell index fits int64
    // (a larger cell is only slower: matches are still in the cell or a neighbour).
    double largest = 0;
    for (const Eigen::Vector3d& p : positions) largest = std::max(largest, p.cwiseAbs().maxCoeff());
    double cell = std::max(tolerance > 0 ? 4 * tolerance : 1.0, std::ldexp(largest, -60));
    if (!(cell > 0) || !std::isfinite(cell)) cell = 1.0;
    const double tol2 = tolerance * tolerance;
    CellTable table(positions.size());
    std::vector<int32_t> next;
    std::vector<Cell> cell_of; // of each welded vertex
    for (size_t i = 0; i < positions.size(); ++i) {
        if ((i & 65535u) == 0 && cancel_requested(cancel)) return map;
        if (i + kPrefetchAhead < positions.size()) {
            const CellSpan ahead(positions[i + kPrefetchAhead], cell, tolerance);
            for (int dx = ahead.lo[0]; dx <= ahead.hi[0]; ++dx)
                for (int dy = ahead.lo[1]; dy <= ahead.hi[1]; ++dy)
                    for (int dz = ahead.lo[2]; dz <= ahead.hi[2]; ++dz)
                        table.prefetch(hash_cell(ahead.at(dx, dy, dz)), dx == 0 && dy == 0 && dz == 0);
        }
        const Eigen::Vector3d& p = positions[i];
        const CellSpan span(p, cell, tolerance);
        const int *lo = span.lo, *hi = span.hi;
        int64_t found = -1;
        // An exact copy of a kept vertex (an STL corner, a vertex split at a seam) is matched
        // in its own cell alone. That is the answer of the search below too: kept vertices lie
        // farther than the tolerance apart, so no other lies within the tolerance of this one.
        const Cell own = span.at(0, 0, 0);
        const uint64_t own_hash = hash_cell(own);
        for (int32_t w = table.head(own, own_hash, cell_of); w >= 0 && found < 0; w = next[size_t(w)])
            if (welded[size_t(w)] == p) found = w;
        for (int dx = lo[0]; dx <= hi[0] && found < 0; ++dx)
            for (int dy = lo[1]; dy <= hi[1] && found < 0; ++dy)
                for (int dz = lo[2]; dz <= hi[2] && found < 0; ++dz) {
                    const Cell c = span.at(dx, dy, dz);
                    for (int32_t w = table.head(c, hash_cell(c), cell_of); w >= 0; w = next[size_t(w)])
                        if ((welded[size_t(w)] - p).squaredNorm() <= tol2) {
                            found = w;
                            break;
                        }
                }
        if (found < 0) {
            found = int64_t(welded.size());
            welded.push_back(p);
            cell_of.push_back(own);
            next.push_back(table.push(own, own_hash, int32_t(found), cell_of));
        }
        map[i] = uint32_t(found);
    }
    return map;
}

} // namespace spt::detail
