// Node slabs and largest radii, bottom up: a leaf's from its spheres, an inner node's axis from its
// children's and its extent from every sphere below.
#include "query/node_slab.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace spt::detail {

std::vector<float> node_slabs(const CompactTree& tree) {
    const auto& nodes = tree.nodes();
    std::vector<float> slab(kSlabStride * nodes.size(), -1.0f);
    // Depth first: node i's subtree is nodes [i, end[i]), its leaves' spheres among them.
    std::vector<uint32_t> end(nodes.size());
    for (size_t i = nodes.size(); i-- > 0;) end[i] = nodes[i].is_active() ? uint32_t(i + 1) : end[nodes[i].first];
    std::vector<Eigen::Vector3f> axis(nodes.size(), Eigen::Vector3f::Zero());
    for (size_t i = nodes.size(); i-- > 0;) { // children follow their parent
        const CompactNode& node = nodes[i];
        Eigen::Vector3f sum = Eigen::Vector3f::Zero(), first = Eigen::Vector3f::Zero();
        if (node.is_active()) {
            // The samples' normals, each turned to agree with the first (a disc has no side).
            for (uint32_t k = node.first; k < node.first + node.count; ++k) {
                const Eigen::Vector3f n(tree.nx()[k], tree.ny()[k], tree.nz()[k]);
                if (first.squaredNorm() == 0) first = n;
                sum += n.dot(first) >= 0 ? n : Eigen::Vector3f(-n);
            }
        } else {
            // The children's axes, turned alike and weighted by their radii.
            for (uint32_t ch : {uint32_t(i + 1), node.first}) {
                const Eigen::Vector3f& m = axis[ch];
                if (m.squaredNorm() == 0) continue;
                if (first.squaredNorm() == 0) first = m;
                sum += (m.dot(first) >= 0 ? nodes[ch].bv_radius : -nodes[ch].bv_radius) * m;
            }
        }
        if (!(sum.norm() > 0)) continue;
        const Eigen::Vector3f n = sum.normalized(), c(node.center[0], node.center[1], node.center[2]);
        axis[i] = n;
        // Every centre below, measured: a bound built from the children's discs would grow with
        // each level (a model's subtrees cost N log N in all).
        float out_n = -std::numeric_limits<float>::infinity(), in_n = out_n, rho = 0, r = 0;
        for (uint32_t j = uint32_t(i); j < end[i]; ++j) {
            const CompactNode& leaf = nodes[j];
            if (!leaf.is_active()) continue;
            r = std::max(r, leaf.ss_radius);
            for (uint32_t k = leaf.first; k < leaf.first + leaf.count; ++k) {
                const Eigen::Vector3f d = tree.sphere_center(leaf, k) - c;
                const float along = n.dot(d);
                out_n = std::max(out_n, along + leaf.ss_radius);
                in_n = std::max(in_n, leaf.ss_radius - along);
                rho = std::max(rho, (d - along * n).squaredNorm());
            }
        }
        // Widened for the rounding of these sums and of the walks' floats.
        const float pad = 1e-6f * node.bv_radius, grow = 1 + 1e-5f;
        float* row = &slab[kSlabStride * i];
        row[0] = n.x(), row[1] = n.y(), row[2] = n.z();
        row[3] = std::max(0.0f, out_n * grow + pad), row[4] = std::max(0.0f, in_n * grow + pad);
        row[5] = std::sqrt(rho) * grow + pad, row[6] = r;
    }
    return slab;
}

SphereSupport spheres_support(const CompactTree& tree, const float* slab, const Eigen::Vector3d& u,
                              std::vector<std::pair<double, uint32_t>>& heap) {
    const auto& nodes = tree.nodes();
    SphereSupport best;
    if (nodes.empty()) return best;
    const Eigen::Vector3f uf = u.cast<float>();
    // A node's bound, widened by a hundred-thousandth of its radius for the floats' rounding.
    auto bound = [&](uint32_t i) {
        const CompactNode& n = nodes[i];
        const Eigen::Vector3d c(n.center[0], n.center[1], n.center[2]);
        return c.dot(u) + double(NodeShape::of(n.bv_radius, slab, i).support(uf)) + 1e-5 * double(n.bv_radius);
    };
    heap.clear();
    heap.push_back({bound(0), 0});
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end());
        const auto [reach, i] = heap.back();
        heap.pop_back();
        if (!(reach > best.reach)) break; // the largest bound left cannot beat the best
        const CompactNode& n = nodes[i];
        if (n.is_active()) {
            for (uint32_t k = n.first; k < n.first + n.count; ++k)
                if (const double r = tree.sphere_center(n, k).cast<double>().dot(u) + double(n.ss_radius); r > best.reach)
                    best = {r, i, k};
            continue;
        }
        for (const uint32_t child : {i + 1, n.first})
            if (const double b = bound(child); b > best.reach) heap.push_back({b, child}), std::push_heap(heap.begin(), heap.end());
    }
    return best;
}

std::vector<float> node_max_radii(const CompactTree& tree) {
    const auto& nodes = tree.nodes();
    std::vector<float> m(nodes.size(), 0.0f);
    for (size_t i = nodes.size(); i-- > 0;) // children follow their parent
        m[i] = nodes[i].is_active() ? nodes[i].ss_radius : std::max(m[i + 1], m[nodes[i].first]);
    return m;
}

} // namespace spt::detail
