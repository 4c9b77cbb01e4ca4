#pragma once
// Caps sampling-sphere radii so that no sphere pokes out of the mesh by more than an allowance.
#include "spt/mesh.hpp"
#include "geometry/vertex_faces.hpp"
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <vector>

namespace spt {

namespace detail {
class TriangleBvh;
}

/// Where a face sample lies: face `face`, at a + s (b - a) + t (c - a) of its corners a, b, c.
struct FacePoint {
    uint32_t face;
    double s, t;
};

/// Limits sampling-sphere radii so that no sphere pokes out of the mesh by more than a
/// protrusion allowance: a sphere wider than a thin part, or than a sharp edge allows,
/// would report contacts that are not there. On an open part (faces joined by edges with a
/// boundary or non-manifold edge: a sheet, an open box, a soup) inside and outside are not
/// defined, and a sphere behind the surface would invent a solid there: a sample there is
/// two-sided, its sphere centred on the surface with a radius of at most its own cap.
class RadiusLimiter {
public:
    /// Indexes `mesh` (kept by reference); `protrusion` in model units, > 0; `two_sided_radius`
    /// (model units, > 0; default `protrusion`) caps the radius of two-sided spheres, which poke
    /// out of either side of the surface by exactly their radius.
    RadiusLimiter(const TriangleMesh& mesh, double protrusion, double two_sided_radius = 0);
    ~RadiusLimiter();
    RadiusLimiter(const RadiusLimiter&) = delete;
    RadiusLimiter& operator=(const RadiusLimiter&) = delete;
    /// Largest r <= r_max (within 1%) whose sphere at (p, n) protrudes at most the allowance;
    /// p in the mesh's object frame. `two_sided`: the sample is on an open part and its sphere
    /// is centred at p, so every point of it is within r of the surface: the largest of
    /// two_sided_radius() x 2^(-k/2), k >= 0, that is at most r_max (a short ladder of radii).
    /// `vertex`: the mesh vertex p is (~0u if none), whose faces the segment test can skip; where
    /// -n does not enter the solid at it (folded faces), the answer is min(allowance, r_max).
    /// `inside_face`: for a sample on a face, a point inside that face (its centroid): the segment
    /// test starts a little towards it, so that a sample on the face's edge is not tested from a
    /// point where the centre's direction only grazes the solid (object frame, model units).
    /// `on_face`: where a face sample lies, so that it is found again at the other poses (add_pose).
    /// With other poses, a one-sided sphere's r is also the largest (within 1%) that protrudes at
    /// most the allowance at each, its sample carried with the surface: a vertex's, with the
    /// vertex and its posed normal; a face's, with its face at the same s and t.
    float limit(const Eigen::Vector3d& p, const Eigen::Vector3f& n, float r_max, bool two_sided,
                uint32_t vertex = ~0u, const Eigen::Vector3d* inside_face = nullptr,
                const FacePoint* on_face = nullptr) const;
    /// Limits every later one-sided sphere at `posed` too: the mesh at another pose (the same
    /// triangles and vertices, moved; normals as at that pose, as posed_mesh gives them), so
    /// that a deforming object's spheres keep the allowance at its clips' poses, not only at the
    /// bind pose (docs/sampling.md, "The promise on a deforming object"). Kept by reference.
    void add_pose(const TriangleMesh& posed);
    /// True if `vertex` belongs to an open part (one of its faces does; TriangleMesh::on_open_part,
    /// unknown counts as open).
    bool on_open_part(uint32_t vertex) const { return vertex >= open_part_.size() || open_part_[vertex]; }
    /// True if triangle `face` is on an open part (TriangleMesh::on_open_part; unknown counts as open).
    bool face_on_open_part(uint32_t face) const {
        return mesh_.on_open_part.size() != mesh_.triangles.size() || mesh_.on_open_part[face];
    }
    /// The protrusion allowance, model units.
    double protrusion() const { return protrusion_; }
    /// The largest radius of a two-sided sphere, model units.
    double two_sided_radius() const { return two_sided_radius_; }
    /// The mesh being indexed.
    const TriangleMesh& mesh() const { return mesh_; }

private:
    // limit at this pose alone.
    float limit_here(const Eigen::Vector3d& p, const Eigen::Vector3d& n, float r_max, uint32_t vertex,
                     const Eigen::Vector3d* inside_face) const;
    bool protrudes(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double r, uint32_t vertex,
                   const Eigen::Vector3d& start) const;
    // Whether the way from vertex v's point along -n enters its closed part's solid: the signed
    // solid angle of the faces around v, seen from a point a little along that way, is positive.
    bool enters_solid(uint32_t v, const Eigen::Vector3d& n) const;
    const TriangleMesh& mesh_;
    std::unique_ptr<detail::TriangleBvh> bvh_;
    double protrusion_;
    double two_sided_radius_;
    Eigen::AlignedBox3d reach_;      // the mesh's box grown by the allowance: no sphere may leave it
    detail::VertexFaces fan_;        // per vertex, its faces of closed parts (copies left out)
    std::vector<uint8_t> open_part_; // per vertex: one of its faces is on an open part (TriangleMesh::on_open_part)
    std::vector<std::unique_ptr<RadiusLimiter>> poses_; // add_pose: the mesh at other poses
};

} // namespace spt
