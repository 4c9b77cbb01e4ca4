#pragma once
// Per-node bounds beyond the balls. A node's spheres spread over a face lie in a flat disc far
// thinner than their bounding ball: it bounds a node pair's distance, and how late the pair can
// part along a direction, far more tightly where faces are sampled densely.
#include "spt/compact_tree.hpp"
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace spt::detail {

/// Floats per node in node_slabs' table.
constexpr size_t kSlabStride = 7;

/// Per node of `tree`, kSlabStride floats: a unit normal n; how far the node's spheres reach
/// along n and along -n from the node's centre; how far their centres lie from the line through
/// that centre along n; the largest sphere radius (local frame, model units). Spheres spread over
/// a face lie in a flat, round-edged disc far thinner than their bounding ball; with radii that
/// differ (smaller spheres near edges sit nearer the surface) the reaches along n are those of the
/// sphere surfaces, not of the centres. A reach along n < 0: no disc (the spheres' normals give no
/// direction).
std::vector<float> node_slabs(const CompactTree& tree);

/// Per node of `tree`, the largest sampling-sphere radius below it (model units). No two spheres
/// below a pair of nodes overlap by more than the sum of theirs: the deepest overlap's bound where
/// the nodes' balls, deep in each other, bound nothing. Unchanged by a pose (radii stay).
std::vector<float> node_max_radii(const CompactTree& tree);

/// How far a disc's spheres reach from its centre along a unit vector at cosine `a` and sine `b`
/// to its normal (NodeShape::support's bound): at most |a| times its reach that way (`out` along
/// the normal, `in` against it), b times its width and (1 - |a|) times its largest radius, and
/// never more than its ball's `radius`. Model units.
template <class T> T disc_support(T radius, T out, T in, T wide, T sphere, T a, T b) {
    const T abs_a = std::abs(a);
    return std::min(radius, abs_a * (a >= 0 ? out : in) + wide * b + (1 - abs_a) * sphere);
}

/// A node's sampling spheres as the walks see them: inside its ball of radius `radius` and, when
/// it has a disc (node_slabs: unit normal, reaches along it and against it, width, largest radius),
/// inside that. Model units, in the frame of the node_slabs table (the model's local frame).
struct NodeShape {
    float radius;
    Eigen::Vector3f normal = Eigen::Vector3f::Zero();
    float out = -1, in = 0, wide = 0, sphere = 0;
    /// The shape of node `i` with ball radius `radius`, from node_slabs' table `slab` (may be null).
    static NodeShape of(float radius, const float* slab, size_t i) {
        NodeShape s{radius};
        const float* row = slab ? slab + kSlabStride * i : nullptr;
        if (row && row[3] >= 0)
            s.normal = Eigen::Vector3f(row[0], row[1], row[2]), s.out = row[3], s.in = row[4], s.wide = row[5],
            s.sphere = row[6];
        return s;
    }
    /// The largest (x - c).u over every point x of the node's spheres, c its centre and u a unit
    /// vector. With u = a n + b e (e across n, a >= 0), a sphere's c.u + r = a (c.n + r) + b (c.e)
    /// + (1 - a) r: at most a times the reach along n, b times the width and (1 - a) times the
    /// largest radius; or the ball's support where that is less.
    float support(const Eigen::Vector3f& u) const {
        if (!(out >= 0)) return radius;
        const float a = normal.dot(u);
        return disc_support(radius, out, in, wide, sphere, a, std::sqrt(std::max(0.0f, 1 - a * a)));
    }
};

/// How far a model's sampling spheres reach along a direction, and the sphere that does.
struct SphereSupport {
    double reach = -std::numeric_limits<double>::infinity(); ///< the largest c.u + r (model units)
    uint32_t node = 0, sphere = 0;                           ///< its active node and sphere
};

/// The largest c.u + r over every sampling sphere of `tree` (centre c, radius r; local frame, u a
/// unit vector): how far the model reaches along u. Best first over the nodes, each bounded by its
/// disc (`slab`, node_slabs' table, may be null: the balls); exact. `heap` is the caller's room.
SphereSupport spheres_support(const CompactTree& tree, const float* slab, const Eigen::Vector3d& u,
                              std::vector<std::pair<double, uint32_t>>& heap);

} // namespace spt::detail
