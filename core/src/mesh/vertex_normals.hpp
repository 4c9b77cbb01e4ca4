#pragma once
// Angle-weighted vertex normals: what import computes for a mesh, and what a deformed pose of it
// computes again (anim/), so that both follow one rule.
#include "spt/mesh.hpp"
#include <algorithm>
#include <cmath>
#include <vector>

namespace spt::detail {

// Twice the area at or below which a face of a mesh with this bounding-box diagonal is degenerate
// (import's rule; a pose of the mesh keeps it).
inline double degenerate_twice_area(double diagonal) { return 1e-14 * diagonal * diagonal; }

// Face (p0, p1, p2)'s unit normal into `unit` (zero when its corners are in line); true when the
// face has a share in its corners' vertex normals, its twice-area above `area_eps`.
inline bool face_unit_normal(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                             double area_eps, Eigen::Vector3d& unit) {
    const Eigen::Vector3d fn = (p1 - p0).cross(p2 - p0);
    const double len = fn.norm();
    unit = len > 0 ? Eigen::Vector3d(fn / len) : Eigen::Vector3d::Zero();
    return len > area_eps;
}

// What face (p0, p1, p2) adds to its corners' normals: its unit normal times its angle at each
// corner; false for a face of twice-area at most `area_eps` (no direction to contribute).
inline bool face_corner_normals(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                                double area_eps, Eigen::Vector3d out[3]) {
    Eigen::Vector3d unit;
    if (!face_unit_normal(p0, p1, p2, area_eps, unit)) return false;
    // Edge k runs from corner k to corner k + 1; corner k's other edge is edge k + 2 reversed
    // (a - b is exactly -(b - a), and so are its length and direction).
    const Eigen::Vector3d edge[3] = {(p1 - p0).normalized(), (p2 - p1).normalized(), (p0 - p2).normalized()};
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d e1 = edge[k];
        const Eigen::Vector3d e2 = -edge[(k + 2) % 3];
        out[k] = std::acos(std::clamp(e1.dot(e2), -1.0, 1.0)) * unit;
    }
    return true;
}

// A vertex's summed normal made unit; false (and zero) where the sum has no direction.
inline bool finish_normal(Eigen::Vector3d& n) {
    const double len = n.norm();
    if (len > 1e-12 && std::isfinite(len)) {
        n /= len;
        return true;
    }
    n.setZero();
    return false;
}

// Unit outward normal per vertex, the sum over its faces of the face's unit normal times the
// face's angle at the vertex; `valid` is 1 where that sum has a direction. Faces of twice-area
// at most `area_eps` contribute nothing; `skip` (per face, may be empty) leaves faces out.
void angle_weighted_normals(const std::vector<Eigen::Vector3d>& positions, const std::vector<Triangle>& triangles,
                            double area_eps, const std::vector<uint8_t>& skip, std::vector<Eigen::Vector3d>& normals,
                            std::vector<uint8_t>& valid);

} // namespace spt::detail
