#pragma once
/// Sample points: the surface points whose sampling spheres stand for the surface.
/// A sampling sphere of radius r at sample (p, n) has centre p - r*n: it touches
/// the surface at p and lies inside the object (paper §3-1).
#include "spt/mesh.hpp"
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace spt {

/// Marks a sample source as a face (triangle) index instead of a vertex index.
constexpr uint32_t kFaceSampleBit = 0x80000000u;

/// All sample points of a mesh, in the mesh's object frame (float32 model units).
struct SampleSet {
    std::vector<Eigen::Vector3f> points;  ///< surface points
    std::vector<Eigen::Vector3f> normals; ///< outward unit normals (octahedral-snapped)
    std::vector<uint32_t> sources;        ///< vertex index, or triangle index | kFaceSampleBit
    std::vector<float> spacing;           ///< local mesh spacing around each point, model units (bfloat16-snapped)
    std::vector<float> max_radius;        ///< largest radius whose sphere pokes out of the mesh by at most the
                                          ///< protrusion allowance, model units (bfloat16-snapped, rounded down)

    /// Number of samples.
    size_t size() const { return points.size(); }
    /// True if sample i lies on a face rather than at a vertex.
    bool is_face_sample(size_t i) const { return (sources[i] & kFaceSampleBit) != 0; }
    /// Vertex or triangle index of sample i, without the face bit.
    uint32_t source_index(size_t i) const { return sources[i] & ~kFaceSampleBit; }
    /// Appends one sample; normal, spacing and max_radius are snapped to the stored precision.
    void add(const Eigen::Vector3f& p, const Eigen::Vector3f& n, uint32_t source, float spacing,
             float max_radius = INFINITY);
};

/// Centre of the sampling sphere of radius r at surface point p with outward normal n.
inline Eigen::Vector3f sphere_center(const Eigen::Vector3f& p, const Eigen::Vector3f& n, float r) {
    return p - r * n;
}

/// How a node's sampling-sphere radius is chosen.
struct RadiusRule {
    float fixed = 0;     ///< > 0: every node uses this radius (model units)
    float scale = 1.0f;  ///< otherwise: scale x median sample spacing of the node, capped by the
                         ///< smallest SampleSet::max_radius among its samples
    /// Radius the rule gives one sample on its own (model units).
    float for_sample(float spacing, float max_radius) const {
        return fixed > 0 ? fixed : std::min(scale * spacing, max_radius);
    }
};

/// Auto-built active nodes hold samples whose own radii (RadiusRule::for_sample) lie within
/// this ratio, so a node's radius is never below 1/ratio of any member's own radius.
constexpr float kRadiusClassRatio = 1.5f;

/// Radius class of a sample radius: samples of one class are within kRadiusClassRatio.
inline int radius_class(float r) {
    return r > 0 ? int(std::floor(std::log(r) / std::log(kRadiusClassRatio))) : -1000000;
}

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
    /// `vertex` is a mesh vertex of the sample's face (or the sample's own vertex).
    float limit(const Eigen::Vector3f& p, const Eigen::Vector3f& n, float r_max, uint32_t vertex) const;
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

/// How far the radius search looks, relative to the radius the rule asks for: room for a
/// node's median spacing to exceed a member's own. Beyond it max_radius is not explored.
constexpr float kRadiusSearchHeadroom = 2.0f;

/// One sample per vertex with a valid normal; spacing = mean length of its edges,
/// max_radius from `limiter`, searched up to kRadiusSearchHeadroom x rule.for_sample.
SampleSet sample_vertices(const TriangleMesh& mesh, const RadiusLimiter& limiter, const RadiusRule& rule = {});

/// Adds face samples (face normals) on `triangle`, refining adaptively until every point of
/// it lies within reach of a face sample whose sphere leaves it at most `eps` uncovered,
/// assuming each sample's radius is `radius_factor` x rule.for_sample(spacing, max_radius).
void add_face_samples(SampleSet& samples, const RadiusLimiter& limiter, uint32_t triangle, double eps,
                      const RadiusRule& rule, float radius_factor);

/// Largest in-plane distance between face samples that keeps the uncovered depth
/// under spheres of radius r within eps: sqrt(h^2 + r^2) - r <= eps.
double max_face_sample_gap(double radius, double eps);

/// bfloat16 storage of a non-negative length: nearest, or rounded towards zero.
uint16_t encode_length(float v, bool round_down);
/// Inverse of encode_length.
float decode_length(uint16_t code);

/// Octahedral 2x16-bit encoding of a unit normal, as stored in .spt files.
uint32_t encode_normal(const Eigen::Vector3f& n);
/// Inverse of encode_normal; returns a unit vector.
Eigen::Vector3f decode_normal(uint32_t code);

} // namespace spt
