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
    /// Closest point of the mesh to p among points closer than sqrt(max_d2); false if none.
    bool closest(const Eigen::Vector3d& p, double max_d2, Eigen::Vector3d& out, double& out_d2,
                 uint32_t* out_triangle = nullptr) const;

    /// True if some triangle comes closer to p than sqrt(d2); stops at the first found.
    bool any_within(const Eigen::Vector3d& p, double d2) const;
    /// True if the segment from a to b crosses a triangle (excluding its first `skip` fraction).
    bool segment_hits(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double skip) const;

private:
    struct Node {
        Eigen::AlignedBox3d box;
        uint32_t first, count; // leaf: triangle range in order_; inner: count 0, first = right child
    };
    void build(uint32_t node, uint32_t b, uint32_t e, std::vector<Eigen::Vector3d>& centroids);
    const TriangleMesh& mesh_;
    std::vector<uint32_t> order_;
    std::vector<Node> nodes_;
};

} // namespace spt::detail
