#pragma once
/// Broad phase over bounding spheres (world frame, model units): sort and sweep along the
/// axis of largest spread, keeping last step's order so that sorting a slowly moving scene
/// is linear. Candidate pairs are exactly the pairs whose spheres overlap (|c1 - c2| < r1 + r2),
/// leaving out pairs of two static objects.
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

/// Sort and sweep with memory between calls (temporal coherence); one per simulation.
class BroadPhase {
public:
    /// Overlapping pairs of `spheres`, sorted by (a, b); static-static pairs left out.
    const std::vector<CandidatePair>& find(const std::vector<BroadSphere>& spheres);

private:
    std::vector<uint32_t> order_;  // object indices sorted by interval start on the sweep axis
    std::vector<double> lo_, hi_, x_, y_, z_, r_; // sorted order
    std::vector<uint8_t> static_;
    std::vector<CandidatePair> pairs_;
};

/// Every overlapping pair by testing all pairs (the reference the broad phase is tested against).
std::vector<CandidatePair> all_overlapping_pairs(const std::vector<BroadSphere>& spheres);

} // namespace spt
