#pragma once
/// Sample points: the surface points whose sampling spheres stand for the surface.
/// A sampling sphere of radius r at sample (p, n) has centre p - r*n: it touches
/// the surface at p and lies inside the object (paper §3-1).
#include "spt/mesh.hpp"
#include <Eigen/Core>
#include <cstdint>
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
    std::vector<float> spacing;           ///< local sample spacing around each point, model units

    /// Number of samples.
    size_t size() const { return points.size(); }
    /// True if sample i lies on a face rather than at a vertex.
    bool is_face_sample(size_t i) const { return (sources[i] & kFaceSampleBit) != 0; }
    /// Vertex or triangle index of sample i, without the face bit.
    uint32_t source_index(size_t i) const { return sources[i] & ~kFaceSampleBit; }
    /// Appends one sample; the normal is snapped to the stored precision.
    void add(const Eigen::Vector3f& p, const Eigen::Vector3f& n, uint32_t source, float spacing);
};

/// Centre of the sampling sphere of radius r at surface point p with outward normal n.
inline Eigen::Vector3f sphere_center(const Eigen::Vector3f& p, const Eigen::Vector3f& n, float r) {
    return p - r * n;
}

/// Options for choosing sample points on a mesh.
struct SamplingOptions {
    /// Largest allowed uncovered depth below the spheres (model units); unset: vertices only.
    std::optional<double> tolerance;
};

/// One sample per vertex with a valid normal; spacing = mean length of its edges.
SampleSet sample_vertices(const TriangleMesh& mesh);

/// Adds face samples (with face normals) on `triangles` so that every point of each
/// triangle is within `max_gap[t]` of a face sample of that triangle.
void add_face_samples(SampleSet& samples, const TriangleMesh& mesh,
                      const std::vector<uint32_t>& triangles, const std::vector<double>& max_gap);

/// Largest in-plane distance between face samples that keeps the uncovered depth
/// under spheres of radius r within eps: sqrt(h^2 + r^2) - r <= eps.
double max_face_sample_gap(double radius, double eps);

/// Octahedral 2x16-bit encoding of a unit normal, as stored in .spt files.
uint32_t encode_normal(const Eigen::Vector3f& n);
/// Inverse of encode_normal; returns a unit vector.
Eigen::Vector3f decode_normal(uint32_t code);

} // namespace spt
