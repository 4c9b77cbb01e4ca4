// TriangleMesh bounds, diagonal, distance from the origin and content hash.
#include "spt/mesh.hpp"
#include "base/hash.hpp"
#include "mesh/recentre.hpp"

namespace spt {

std::pair<Eigen::Vector3d, Eigen::Vector3d> TriangleMesh::bounds() const {
    if (positions.empty()) return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    Eigen::Vector3d lo = positions[0], hi = positions[0];
    for (const auto& p : positions) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return {lo, hi};
}

double TriangleMesh::diagonal() const {
    auto [lo, hi] = bounds();
    return (hi - lo).norm();
}

bool TriangleMesh::far_for_float() const {
    const auto [lo, hi] = bounds();
    return detail::far_for_float(lo, hi);
}

uint64_t TriangleMesh::content_hash() const {
    uint64_t h = detail::fnv1a(nullptr, 0);
    for (const auto& p : positions) {
        const float f[3] = {float(p.x()), float(p.y()), float(p.z())};
        h = detail::fnv1a(f, sizeof f, h);
    }
    for (const auto& t : triangles) h = detail::fnv1a(t.data(), sizeof(uint32_t) * 3, h);
    return h;
}

} // namespace spt
