// Node slabs and largest radii, bottom up: a leaf's from its spheres, an inner node's from its children's.
#include "query/node_slab.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {

std::vector<float> node_slabs(const CompactTree& tree) {
    const auto& nodes = tree.nodes();
    std::vector<float> slab(4 * nodes.size(), -1.0f);
    auto centre = [&](size_t i) { return Eigen::Vector3f(nodes[i].center[0], nodes[i].center[1], nodes[i].center[2]); };
    // Children follow their parent: from the last node back, every child is done before its parent.
    for (size_t i = nodes.size(); i-- > 0;) {
        const CompactNode& node = nodes[i];
        const Eigen::Vector3f c = centre(i);
        Eigen::Vector3f sum = Eigen::Vector3f::Zero();
        float h = 0;
        if (node.is_active()) {
            // The samples' normals, each turned to agree with the first (a slab has no side).
            Eigen::Vector3f first = Eigen::Vector3f::Zero();
            for (uint32_t k = node.first; k < node.first + node.count; ++k) {
                const Eigen::Vector3f n(tree.nx()[k], tree.ny()[k], tree.nz()[k]);
                if (first.squaredNorm() == 0) first = n;
                sum += n.dot(first) >= 0 ? n : Eigen::Vector3f(-n);
            }
            if (!(sum.norm() > 0)) continue;
            const Eigen::Vector3f n = sum.normalized();
            for (uint32_t k = node.first; k < node.first + node.count; ++k)
                h = std::max(h, std::abs(n.dot(tree.sphere_center(node, k) - c)) + node.ss_radius);
            sum = n;
        } else {
            const uint32_t kids[2] = {uint32_t(i + 1), node.first};
            // The children's slab normals, each turned to agree with the first, by radius.
            Eigen::Vector3f first = Eigen::Vector3f::Zero();
            for (uint32_t ch : kids) {
                const float* s = &slab[4 * size_t(ch)];
                if (!(s[3] >= 0)) continue; // a ball: no say in the normal
                const Eigen::Vector3f m(s[0], s[1], s[2]);
                if (first.squaredNorm() == 0) first = m;
                sum += (m.dot(first) >= 0 ? nodes[ch].bv_radius : -nodes[ch].bv_radius) * m;
            }
            if (!(sum.norm() > 0)) continue;
            const Eigen::Vector3f n = sum.normalized();
            for (uint32_t ch : kids) {
                const float* s = &slab[4 * size_t(ch)];
                // A child's spheres lie in its ball and its slab: along n, within its radius, and
                // within its half-thickness plus its radius times the sine of the slabs' tilt.
                const float R = nodes[ch].bv_radius;
                const float reach = s[3] >= 0 ? std::min(R, s[3] + R * n.cross(Eigen::Vector3f(s[0], s[1], s[2])).norm()) : R;
                h = std::max(h, std::abs(n.dot(centre(ch) - c)) + reach);
            }
            sum = n;
        }
        h = h * (1 + 1e-5f) + 1e-6f * node.bv_radius; // the rounding of these sums
        if (!(h < node.bv_radius)) continue;            // no thinner than the ball: no use
        float* out = &slab[4 * i];
        out[0] = sum.x(), out[1] = sum.y(), out[2] = sum.z(), out[3] = h;
    }
    return slab;
}

std::vector<float> node_max_radii(const CompactTree& tree) {
    const auto& nodes = tree.nodes();
    std::vector<float> m(nodes.size(), 0.0f);
    for (size_t i = nodes.size(); i-- > 0;) // children follow their parent
        m[i] = nodes[i].is_active() ? nodes[i].ss_radius : std::max(m[i + 1], m[nodes[i].first]);
    return m;
}

} // namespace spt::detail
