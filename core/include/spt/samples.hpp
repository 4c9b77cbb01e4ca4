#pragma once
/// Sample points: the surface points whose sampling spheres stand for the surface.
/// A sampling sphere of radius r at sample (p, n) has centre p - r*n: it touches
/// the surface at p and lies inside the object (paper §3-1). A sample of an open part,
/// where inside and outside are not defined, is two-sided: its sphere is centred on the
/// surface at p (docs/sampling.md, "Open parts").
#include "spt/mesh.hpp"
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace spt {

/// Marks a sample source as a face (triangle) index instead of a vertex index.
constexpr uint32_t kFaceSampleBit = 0x80000000u;
/// Marks a sample source as two-sided (on an open part): its sphere is centred on the surface.
constexpr uint32_t kTwoSidedBit = 0x40000000u;
/// Vertex and triangle indices a sample source can hold (below both marking bits).
constexpr uint32_t kMaxSourceIndex = kTwoSidedBit - 1;

/// All sample points of a mesh. Points are float32 relative to a local origin (the centre of
/// the mesh's bounding box, in double), so a mesh far from its file's origin keeps float
/// precision; trees and query layouts built over the samples share that local frame.
struct SampleSet {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero(); ///< local origin in the object frame, model units
    std::vector<Eigen::Vector3f> points;  ///< surface points, local frame (object frame minus origin)
    std::vector<Eigen::Vector3f> normals; ///< outward unit normals (octahedral-snapped)
    std::vector<uint32_t> sources;        ///< vertex index, or triangle index | kFaceSampleBit; | kTwoSidedBit on
                                          ///< an open part
    std::vector<float> spacing;           ///< local mesh spacing around each point, model units (bfloat16-snapped)
    std::vector<float> max_radius;        ///< largest radius whose sphere pokes out of the mesh by at most the
                                          ///< protrusion allowance, model units (bfloat16-snapped, rounded down)

    /// Number of samples.
    size_t size() const { return points.size(); }
    /// Surface point of sample i in the object frame, model units.
    Eigen::Vector3d position(size_t i) const { return origin + points[i].cast<double>(); }
    /// True if sample i lies on a face rather than at a vertex.
    bool is_face_sample(size_t i) const { return (sources[i] & kFaceSampleBit) != 0; }
    /// True if sample i is on an open part: its sphere is centred on the surface, not behind it.
    bool is_two_sided(size_t i) const { return (sources[i] & kTwoSidedBit) != 0; }
    /// Vertex or triangle index of sample i, without the face and two-sided bits.
    uint32_t source_index(size_t i) const { return sources[i] & kMaxSourceIndex; }
    /// Centre of sample i's sampling sphere of radius r, local frame: p - r*n, or p if two-sided.
    Eigen::Vector3f sphere_center(size_t i, float r) const {
        return is_two_sided(i) ? points[i] : Eigen::Vector3f(points[i] - r * normals[i]);
    }
    /// Appends every sample of `other`, whose origin must be this set's.
    void append(const SampleSet& other);
    /// Appends one sample at local point p; normal, spacing and max_radius are snapped to the
    /// stored precision.
    void add(const Eigen::Vector3f& p, const Eigen::Vector3f& n, uint32_t source, float spacing,
             float max_radius = INFINITY);
};

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

} // namespace spt
