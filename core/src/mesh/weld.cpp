// Welds vertices closer than a tolerance through a hash grid.
#include "mesh/weld.hpp"
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
// cell's vertices are chained through `next`. No allocation per cell; grows with the
// welded vertices, not the input (an unindexed STL has six times as many).
class CellTable {
public:
    CellTable() { rehash(1024); }
    int32_t head(const Cell& c) const {
        for (size_t i = hash_cell(c) & mask_;; i = (i + 1) & mask_) {
            if (slots_[i].head < 0) return -1;
            if (slots_[i].cell == c) return slots_[i].head;
        }
    }
    // Makes `v` the head of its cell and returns the previous head (or -1).
    int32_t push(const Cell& c, int32_t v) {
        if (2 * (used_ + 1) > slots_.size()) rehash(slots_.size() * 2);
        for (size_t i = hash_cell(c) & mask_;; i = (i + 1) & mask_) {
            if (slots_[i].head < 0) {
                slots_[i] = {c, v};
                ++used_;
                return -1;
            }
            if (slots_[i].cell == c) return std::exchange(slots_[i].head, v);
        }
    }

private:
    struct Slot {
        Cell cell;
        int32_t head = -1;
    };
    void rehash(size_t cap) {
        std::vector<Slot> old = std::move(slots_);
        slots_.assign(cap, Slot{});
        mask_ = cap - 1;
        for (const Slot& s : old)
            if (s.head >= 0)
                for (size_t i = hash_cell(s.cell) & mask_;; i = (i + 1) & mask_)
                    if (slots_[i].head < 0) {
                        slots_[i] = s;
                        break;
                    }
    }
    std::vector<Slot> slots_;
    size_t mask_ = 0, used_ = 0;
};

} // namespace

std::vector<uint32_t> weld_positions(const std::vector<Eigen::Vector3d>& positions, double tolerance,
                                     std::vector<Eigen::Vector3d>& welded) {
    std::vector<uint32_t> map(positions.size());
    welded.clear();
    // Cells twice the tolerance: a match lies in this cell, or in a neighbour on a side
    // where the point is within the tolerance of the cell's boundary (3.4 cells on average).
    // A cell also at least 2^-60 of the largest coordinate, so every cell index fits int64
    // (a larger cell is only slower: matches are still in the cell or a neighbour).
    double largest = 0;
    for (const Eigen::Vector3d& p : positions) largest = std::max(largest, p.cwiseAbs().maxCoeff());
    double cell = std::max(tolerance > 0 ? 2 * tolerance : 1.0, std::ldexp(largest, -60));
    if (!(cell > 0) || !std::isfinite(cell)) cell = 1.0;
    const double tol2 = tolerance * tolerance;
    CellTable table;
    std::vector<int32_t> next;
    for (size_t i = 0; i < positions.size(); ++i) {
        const Eigen::Vector3d& p = positions[i];
        int64_t k[3];
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            const double f = p[a] / cell, fl = std::floor(f);
            k[a] = int64_t(fl);
            lo[a] = (f - fl) * cell <= tolerance ? -1 : 0;
            hi[a] = (fl + 1 - f) * cell <= tolerance ? 1 : 0;
        }
        int64_t found = -1;
        for (int dx = lo[0]; dx <= hi[0] && found < 0; ++dx)
            for (int dy = lo[1]; dy <= hi[1] && found < 0; ++dy)
                for (int dz = lo[2]; dz <= hi[2] && found < 0; ++dz)
                    for (int32_t w = table.head({k[0] + dx, k[1] + dy, k[2] + dz}); w >= 0; w = next[size_t(w)])
                        if ((welded[size_t(w)] - p).squaredNorm() <= tol2) {
                            found = w;
                            break;
                        }
        if (found < 0) {
            found = int64_t(welded.size());
            welded.push_back(p);
            next.push_back(table.push({k[0], k[1], k[2]}, int32_t(found)));
        }
        map[i] = uint32_t(found);
    }
    return map;
}

} // namespace spt::detail
