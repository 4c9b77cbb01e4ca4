#pragma once
// Caps sampling-sphere radii so that no sphere pokes out of the mesh by more than an allowance.
#include "spt/mesh.hpp"
#include <Eigen/Core>
#include <memory>
#include <vector>

namespace spt {

namespace detail {
class TriangleBvh;
}

/// Limits sampling-sphere radii so that no sphere pokes out of the mesh by more than a
/// protrusion allowance: a sphere wider than a thin part, or than a sharp edge allows,
/// would report contacts that are not there. On an open part (faces joined by edges with a
/// boundary or non-manifold edge: a sheet, an open box, a soup) inside and outside are not
/// defined, and a sphere behind the surface would invent a solid there: its radius is
/// capped at half the allowance, so it pokes out of the back by at most the allowance.
class RadiusLimiter {
public:
    /// Indexes `mesh` (kept by reference); `protrusion` in model units, > 0.
    RadiusLimiter(const TriangleMesh& mesh, double protrusion);
    ~RadiusLimiter();
    RadiusLimiter(const RadiusLimiter&) = delete;
    RadiusLimiter& operator=(const RadiusLimiter&) = delete;
    /// Largest r <= r_max (within 1%) whose sphere at (p, n) protrudes at most the allowance;
    /// p in the mesh's object frame; `vertex` is a mesh vertex of the sample's face (or the
    /// sample's own vertex).
    float limit(const Eigen::Vector3d& p, const Eigen::Vector3f& n, float r_max, uint32_t vertex) const;
    /// True if `vertex` belongs to an open part (TriangleMesh::on_open_part; unknown counts as open).
    bool on_open_part(uint32_t vertex) const { return vertex >= open_part_.size() || open_part_[vertex]; }
    /// The protrusion allowance, model units.
    double protrusion() const { return protrusion_; }
    /// The mesh being indexed.
    const TriangleMesh& mesh() const { return mesh_; }

private:
    bool protrudes(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double r) const;
    const TriangleMesh& mesh_;
    std::unique_ptr<detail::TriangleBvh> bvh_;
    double protrusion_;
    std::vector<uint8_t> open_part_; // per vertex: one of its faces is on an open part (TriangleMesh::on_open_part)
};

} // namespace spt
