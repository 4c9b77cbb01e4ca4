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
        Eigen::Vector3d add[3];
        if (!face_corner_normals(positions[t[0]], positions[t[1]], positions[t[2]], area_eps, add)) continue;
        for (int k = 0; k < 3; ++k) normals[t[k]] += add[k];
    }
    for (size_t i = 0; i < n; ++i) valid[i] = finish_normal(normals[i]);
}

} // namespace spt::detail
