// Segment-triangle crossings by exact orientation predicates, and brute-force ray parity.
#include "geometry/ray_parity.hpp"
#include "geometry/predicates.hpp"
#include <algorithm>

namespace spt {

Crossing segment_crossing(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const int sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
    if (sp == sq && sp != 0) return Crossing::Misses;
    if (sp == 0 && sq == 0) return Crossing::Degenerate;
    if (sq == 0) return Crossing::Misses; // q is beyond every triangle: it meets this plane outside them
    const int u = orient3d(p, q, a, b), v = orient3d(p, q, b, c), w = orient3d(p, q, c, a);
    if ((u > 0 && v > 0 && w > 0) || (u < 0 && v < 0 && w < 0)) return sp == 0 ? Crossing::StartsOn : Crossing::Crosses;
    // The line meets an edge or a vertex of the triangle (one or two signs zero, the rest agreeing).
    if ((u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0))
        return sp == 0 ? Crossing::StartsOn : Crossing::Degenerate;
    return Crossing::Misses;
}

const std::array<Eigen::Vector3d, 8>& parity_directions() {
    static const std::array<Eigen::Vector3d, 8> d = [] {
        std::array<Eigen::Vector3d, 8> out = {
            Eigen::Vector3d(0.5373, 0.2861, 0.7934), Eigen::Vector3d(-0.3319, 0.8127, -0.4790),
            Eigen::Vector3d(0.7771, -0.5237, 0.3491), Eigen::Vector3d(-0.6142, -0.2213, 0.7575),
            Eigen::Vector3d(0.1187, -0.9033, -0.4124), Eigen::Vector3d(-0.8521, 0.3398, -0.3981),
            Eigen::Vector3d(0.4046, 0.6693, -0.6231), Eigen::Vector3d(-0.2674, -0.5868, -0.7643)};
        for (auto& v : out) v.normalize();
        return out;
    }();
    return d;
}

bool inside_by_parity(const std::vector<Eigen::Vector3d>& positions, const std::vector<std::array<uint32_t, 3>>& triangles,
                      const std::vector<uint32_t>& faces, const Eigen::Vector3d& p) {
    double reach = p.norm();
    for (uint32_t f : faces)
        for (uint32_t v : triangles[f]) reach = std::max(reach, positions[v].norm());
    const double length = 4 * reach + 1;
    for (const Eigen::Vector3d& dir : parity_directions()) {
        const Eigen::Vector3d q = p + length * dir;
        int parity = 0;
        bool degenerate = false;
        for (uint32_t f : faces) {
            const auto& t = triangles[f];
            const Crossing x = segment_crossing(p, q, positions[t[0]], positions[t[1]], positions[t[2]]);
            if (x == Crossing::StartsOn) return true;
            if (x == Crossing::Degenerate) {
                degenerate = true;
                break;
            }
            parity ^= x == Crossing::Crosses;
        }
        if (!degenerate) return parity != 0;
    }
    return false;
}

} // namespace spt
