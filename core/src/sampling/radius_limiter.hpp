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
/// would report contacts that are not there. On an open sheet (a part with boundary or
/// non-manifold edges whose back side can be seen from outside) the sphere, centred
/// behind the surface, pokes out of the back by its diameter: there the radius is capped
/// at half the allowance.
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
    /// True if the back of the surface at (p, n) can be seen from outside the mesh: a ray
    /// from p into the back half-space (along -n or 45 degrees off it) leaves the mesh
    /// without crossing a face. Only vertices of parts with boundary or non-manifold edges are tested.
    bool back_exposed(const Eigen::Vector3d& p, const Eigen::Vector3d& n, uint32_t vertex) const;
    /// The protrusion allowance, model units.
    double protrusion() const { return protrusion_; }
    /// The mesh being indexed.
    const TriangleMesh& mesh() const { return mesh_; }

private:
    bool protrudes(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double r) const;
    const TriangleMesh& mesh_;
    std::unique_ptr<detail::TriangleBvh> bvh_;
    double protrusion_;
    double ray_length_ = 0;
    std::vector<uint8_t> open_part_; // per vertex: one of its faces is on an open part (TriangleMesh::on_open_part)
};

} // namespace spt
