#pragma once
// Four-wide box tree over a mesh's triangles: the radius limiter's ball-and-segment probe.
#include "spt/mesh.hpp"
#include <vector>

namespace spt::detail {

/// Closest point of a triangle to p (Ericson, Real-Time Collision Detection 5.1.5).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c);

/// What the radius limiter asks of the mesh, in the mesh's frame: does a triangle come
/// nearer to `centre` than sqrt(d2), or does the segment from `start` along `dir` cross a
/// triangle at a fraction in (skip, end]?
struct BallSegmentProbe {
    Eigen::Vector3d centre;
    double d2;
    Eigen::Vector3d start, dir;
    double skip, end;
    /// The mesh vertex the segment starts at, if any: the segment meets its faces' planes
    /// only at the start, which `skip` excludes, so they are not tested (~0u: none).
    uint32_t start_vertex = ~0u;
};

/// Box tree over a mesh's triangles, four children a node, boxes as floats relative to the
/// mesh's centre (rounded outwards), for the radius limiter's probes.
class TriangleBvh {
public:
    /// Indexes `mesh` (kept by reference).
    explicit TriangleBvh(const TriangleMesh& mesh);

    /// True if a triangle meets the probe's ball or segment (exact tests in double on the
    /// triangles; the boxes only prune, conservatively). Stops at the first found.
    bool touches(const BallSegmentProbe& probe) const;

    /// The triangle test of the probe's ball: triangle `t` comes nearer to c than sqrt(d2).
    bool triangle_within(uint32_t t, const Eigen::Vector3d& c, double d2) const;
    /// The triangle test of the probe's segment: it crosses triangle `t` at a fraction in
    /// (skip, end] (Moller-Trumbore, both faces).
    bool triangle_crossed(uint32_t t, const Eigen::Vector3d& a, const Eigen::Vector3d& d, double skip,
                          double end) const;

private:
    // Four children's boxes, as floats relative to origin_ rounded outwards, one lane a child;
    // lanes past `lanes` are unused (an empty box, and never visited).
    struct Node {
        float lo[3][4], hi[3][4];
        uint32_t child[4]; // count 0: a node's index; otherwise the leaf's first place in order_
        uint8_t count[4];  // triangles of a leaf, 0 for an inner child or an unused lane
        uint8_t lanes;     // lanes in use, the first ones
    };
    // The probe as the boxes' float tests read it: relative to origin_, widened to be conservative.
    struct FloatProbe {
        float centre[3], reach2;
        float seg_lo[3], seg_hi[3]; // the segment's box; empty (lo > hi) when there is no segment
    };
    // Makes the node over order_[b, e) (sorted records `key`: Morton code over index) and
    // returns its index; `box` gets its bounds, relative to origin_.
    uint32_t build(uint32_t b, uint32_t e, const std::vector<uint64_t>& key, Eigen::AlignedBox3d& box);
    Eigen::AlignedBox3d leaf_box(uint32_t b, uint32_t e) const;
    FloatProbe float_probe(const BallSegmentProbe& p) const;
    static void lanes_met(const Node& n, const FloatProbe& q, int* ball, int* seg);

    const TriangleMesh& mesh_;
    Eigen::Vector3d origin_ = Eigen::Vector3d::Zero(); // centre of the mesh's box: floats stay precise far from zero
    double extent_ = 0;                                // largest |coordinate - origin_| of a vertex
    std::vector<uint32_t> order_;
    std::vector<Node> nodes_; // the root first
};

} // namespace spt::detail
