#pragma once
/// Slab bound of a node's triangles: the region between two parallel planes,
/// |n . x - d| <= h. A bounding sphere cannot tell a flat patch from a ball; near
/// contact between two flat patches only a thin bound can prune the pair, and a
/// slab costs one dot product to test (the exact level's node pairs, docs/queries.md).
#include <Eigen/Core>
#include <vector>

namespace spt {

/// Unit normal `n`, offset `d`, half-thickness `h` (model units, object frame).
struct Slab {
    float n[3] = {0, 0, 1};
    float d = 0;
    float h = -1; ///< negative: empty, nothing to bound

    /// True if the sphere (centre c, radius r, same frame) lies wholly outside the slab.
    bool separates(const Eigen::Vector3f& c, float r) const {
        const float s = n[0] * c.x() + n[1] * c.y() + n[2] * c.z() - d;
        return s > h + r || s < -h - r;
    }
};

/// Thinnest-direction slab (principal axis of least spread) holding `points`,
/// rounded outwards so the float slab still holds every double point.
Slab fit_slab(const std::vector<Eigen::Vector3d>& points);

} // namespace spt
