// Angle-weighted vertex normals (vertex_normals.hpp).
#include "mesh/vertex_normals.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {

void angle_weighted_normals(const std::vector<Eigen::Vector3d>& positions, const std::vector<Triangle>& triangles,
                            double area_eps, const std::vector<uint8_t>& skip, std::vector<Eigen::Vector3d>& normals,
                            std::vector<uint8_t>& valid) {
    const size_t n = positions.size();
    normals.assign(n, Eigen::Vector3d::Zero());
    valid.assign(n, 0);
    for (size_t f = 0; f < triangles.size(); ++f) {
        if (!skip.empty() && skip[f]) continue;
        const auto& t = triangles[f];
        const Eigen::Vector3d& p0 = positions[t[0]];
        const Eigen::Vector3d& p1 = positions[t[1]];
        const Eigen::Vector3d& p2 = positions[t[2]];
        const Eigen::Vector3d fn = (p1 - p0).cross(p2 - p0);
        const double len = fn.norm();
        if (!(len > area_eps)) continue; // degenerate: no direction to contribute
        const Eigen::Vector3d unit = fn / len;
        // Edge k runs from corner k to corner k + 1; corner k's other edge is edge k + 2 reversed
        // (a - b is exactly -(b - a), and so are its length and direction).
        const Eigen::Vector3d edge[3] = {(p1 - p0).normalized(), (p2 - p1).normalized(), (p0 - p2).normalized()};
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d e1 = edge[k];
            const Eigen::Vector3d e2 = -edge[(k + 2) % 3];
            const double angle = std::acos(std::clamp(e1.dot(e2), -1.0, 1.0));
            normals[t[k]] += angle * unit;
        }
    }
    for (size_t i = 0; i < n; ++i) {
        const double len = normals[i].norm();
        if (len > 1e-12 && std::isfinite(len)) {
            normals[i] /= len;
            valid[i] = 1;
        } else {
            normals[i].setZero();
        }
    }
}

} // namespace spt::detail
