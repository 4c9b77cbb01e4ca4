#pragma once
/// Broad phase over bounding spheres (world frame, model units): a uniform grid of cells twice
/// the largest radius up to 4 times the median, each sphere in the cell of its centre and tested
/// against its own and the neighbouring cells; larger spheres are tested against all. Candidate pairs are exactly
/// the pairs whose spheres overlap (|c1 - c2| < r1 + r2), leaving out pairs of two static objects.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace spt {

/// One object's sphere for the broad phase.
struct BroadSphere {
    Eigen::Vector3d center = Eigen::Vector3d::Zero(); ///< world frame, model units
    double radius = 0;                                ///< model units
    bool is_static = false;                           ///< two static objects are never paired
};

/// A candidate pair of object indices, a < b.
struct CandidatePair {
    uint32_t a = 0, b = 0; ///< indices into the sphere list
    /// Lexicographic order (the order find() returns).
    bool operator<(const CandidatePair& o) const { return a != o.a ? a < o.a : b < o.b; }
    /// Same pair.
    bool operator==(const CandidatePair& o) const { return a == o.a && b == o.b; }
};

/// True if the two spheres overlap as the broad phase decides it (strictly).
inline bool spheres_overlap(const BroadSphere& s, const BroadSphere& t) {
    // Written out so that the sweep's test rounds identically.
    const double dx = s.center.x() - t.center.x(), dy = s.center.y() - t.center.y(), dz = s.center.z() - t.center.z();
    const double r = s.radius + t.radius;
    return dx * dx + dy * dy + dz * dz < r * r;
}

/// The grid broad phase; keeps its buffers between calls (one per simulation).
class BroadPhase {
public:
    /// Overlapping pairs of `spheres`, sorted by (a, b); static-static pairs left out.
    const std::vector<CandidatePair>& find(const std::vector<BroadSphere>& spheres);

private:
    struct Cell {
        int64_t xyz[3]; // cell coordinates
        uint64_t key;   // packed coordinates
        uint32_t index; // sphere
    };
    std::vector<Cell> cells_;   // small spheres by cell
    std::vector<uint64_t> keys_;  // distinct cell keys, sorted
    std::vector<uint32_t> starts_; // first entry of each key's run in cells_, then cells_.size()
    std::vector<uint32_t> big_; // spheres larger than half a cell
    std::vector<double> radii_;
    std::vector<CandidatePair> pairs_;
};

/// Every overlapping pair by testing all pairs (the reference the broad phase is tested against).
std::vector<CandidatePair> all_overlapping_pairs(const std::vector<BroadSphere>& spheres);

} // namespace spt
