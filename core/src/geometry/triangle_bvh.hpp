#pragma once
// Axis-aligned bounding-box tree over a mesh's triangles for closest-point queries.
#include "spt/mesh.hpp"
#include <vector>

namespace spt::detail {

/// Closest point of a triangle to p (Ericson, Real-Time Collision Detection 5.1.5).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c);

class TriangleBvh {
public:
    explicit TriangleBvh(const TriangleMesh& mesh);

    /// True if some triangle comes closer to p than sqrt(d2); stops at the first found.
    bool any_within(const Eigen::Vector3d& p, double d2) const;
    /// True if the segment from a to b crosses a triangle (excluding its first `skip` fraction).
    bool segment_hits(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double skip) const;

private:
    // The test any_within makes on one triangle: it comes closer to p than sqrt(d2).
    bool triangle_within(uint32_t triangle, const Eigen::Vector3d& p, double d2) const;
    // The test segment_hits makes on one triangle: the segment from a along d crosses it at a
    // fraction in (skip, 1] (Moller-Trumbore, both faces).
    bool triangle_crossed(uint32_t triangle, const Eigen::Vector3d& a, const Eigen::Vector3d& d, double skip) const;

    struct Node {
        Eigen::AlignedBox3d box;
        uint32_t first, count; // leaf: triangle range in order_; inner: count 0, first = right child
    };
    struct Keyed {
        uint64_t key; // Morton code of the triangle's centroid
        uint32_t triangle;
    };
    void build(uint32_t node, uint32_t b, uint32_t e, const std::vector<Keyed>& keyed);
    // Depth-first walk: skips nodes whose box `reject`s, calls `hit(triangle)` at leaves and
    // stops at the first triangle for which it returns true.
    template <class Reject, class Hit> bool find_triangle(Reject reject, Hit hit) const;
    const TriangleMesh& mesh_;
    std::vector<uint32_t> order_;
    std::vector<Node> nodes_;
};

} // namespace spt::detail
