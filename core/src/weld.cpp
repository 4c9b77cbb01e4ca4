#include "weld.hpp"
#include <cmath>
#include <unordered_map>

namespace spt::detail {
namespace {

struct CellKey {
    int64_t x, y, z;
    bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct CellHash {
    size_t operator()(const CellKey& k) const {
        return size_t(k.x * 73856093ll) ^ size_t(k.y * 19349663ll) ^ size_t(k.z * 83492791ll);
    }
};

} // namespace

std::vector<uint32_t> weld_positions(const std::vector<Eigen::Vector3d>& positions, double tolerance,
                                     std::vector<Eigen::Vector3d>& welded) {
    std::vector<uint32_t> map(positions.size());
    welded.clear();
    // Cells as large as the tolerance: a match is in this cell or a neighbour.
    const double cell = tolerance > 0 ? tolerance : 1.0;
    std::unordered_map<CellKey, std::vector<uint32_t>, CellHash> grid;
    grid.reserve(positions.size());
    const double tol2 = tolerance * tolerance;
    for (size_t i = 0; i < positions.size(); ++i) {
        const auto& p = positions[i];
        const CellKey k{int64_t(std::floor(p.x() / cell)), int64_t(std::floor(p.y() / cell)),
                        int64_t(std::floor(p.z() / cell))};
        int64_t found = -1;
        for (int dx = -1; dx <= 1 && found < 0; ++dx)
            for (int dy = -1; dy <= 1 && found < 0; ++dy)
                for (int dz = -1; dz <= 1 && found < 0; ++dz) {
                    auto it = grid.find({k.x + dx, k.y + dy, k.z + dz});
                    if (it == grid.end()) continue;
                    for (uint32_t w : it->second)
                        if ((welded[w] - p).squaredNorm() <= tol2) {
                            found = w;
                            break;
                        }
                }
        if (found < 0) {
            found = int64_t(welded.size());
            welded.push_back(p);
            grid[k].push_back(uint32_t(found));
        }
        map[i] = uint32_t(found);
    }
    return map;
}

} // namespace spt::detail
