// Lays a SamplingTree out depth-first with per-leaf sphere blocks for queries.
#include "spt/compact_tree.hpp"
#include "base/float_round.hpp"
#include "geometry/sample_disc.hpp"
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace spt {
namespace {

// std::lround's value, without a library call per coordinate (NaN: 0, lround's out-of-range
// result truncated to 8 bits).
int8_t to_snorm8(float v) { return int8_t(detail::round_half_away(std::clamp(v, -1.0f, 1.0f) * 127.0f)); }

} // namespace

CompactTree::CompactTree(const SamplingTree& tree, const SampleSet& samples) : origin_(samples.origin) {
    const auto all = tree.nodes();
    const uint32_t none = uint32_t(all.size());
    // What the depth-first walk needs of each node, copied in id order (the map's order, so the
    // nodes are read once, in turn): the walk then reads small records, not scattered map nodes.
    struct Source {
        CompactNode node; // all but first and count
        NodeId id;
        const uint32_t* samples;
        uint32_t count;
        bool active;
    };
    std::vector<Source> src(all.size());
    size_t total = 0;
    for (size_t i = 0; i < all.size(); ++i) {
        const TreeNode& n = *all[i];
        CompactNode c{};
        c.center[0] = n.center.x(), c.center[1] = n.center.y(), c.center[2] = n.center.z();
        c.bv_radius = n.bv_radius;
        c.ss_radius = n.ss_radius;
        c.tree_node = uint32_t(i);
        src[i] = {c, n.id, n.samples.data(), uint32_t(n.samples.size()), n.active};
        total += n.samples.size();
    }
    // Children by index in id order. The children's ids of successive nodes increase too, so
    // one forward walk finds them all.
    std::vector<uint32_t> left(all.size(), none), right(all.size(), none);
    for (size_t i = 0, j = 0; i < src.size(); ++i) {
        if (src[i].active) continue;
        const NodeId l = left_child(src[i].id);
        while (j < src.size() && src[j].id < l) ++j;
        if (j < src.size() && src[j].id == l) left[i] = uint32_t(j);
        const size_t k = j < src.size() && src[j].id == l ? j + 1 : j;
        if (k < src.size() && src[k].id == right_child(src[i].id)) right[i] = uint32_t(k);
    }
    const size_t padded = total + 8;
    centers_.assign(3 * total + 8, 0);
    nx_.assign(padded, 0), ny_.assign(padded, 0), nz_.assign(padded, 0);
    sample_index_.assign(total, 0);
    nodes_.reserve(all.size());
    // Explicit stack: a one-sided tree can be 62 levels deep, recursion is fine, but
    // iteration keeps the right-child fix-up in one place.
    std::vector<std::pair<uint32_t, int64_t>> stack; // (node index, parent slot awaiting right index)
    const auto root = std::lower_bound(src.begin(), src.end(), root_id(), [](const Source& n, NodeId v) { return n.id < v; });
    if (root != src.end() && root->id == root_id()) stack.push_back({uint32_t(root - src.begin()), -1});
    size_t sphere = 0;
    while (!stack.empty()) {
        auto [index, patch] = stack.back();
        stack.pop_back();
        if (index == none) continue;
        const Source& n = src[index];
        if (patch >= 0) nodes_[size_t(patch)].first = uint32_t(nodes_.size());
        CompactNode c = n.node;
        const size_t slot = nodes_.size();
        if (n.active) {
            c.first = uint32_t(sphere);
            c.count = n.count;
            float* block = centers_.data() + 3 * sphere;
            for (uint32_t k = 0; k < c.count; ++k) {
                const uint32_t s = n.samples[k];
                const Eigen::Vector3f ctr = samples.sphere_center(s, c.ss_radius);
                block[k] = ctr.x(), block[c.count + k] = ctr.y(), block[2 * c.count + k] = ctr.z();
                nx_[sphere] = to_snorm8(samples.normals[s].x());
                ny_[sphere] = to_snorm8(samples.normals[s].y());
                nz_[sphere] = to_snorm8(samples.normals[s].z());
                sample_index_[sphere] = s;
                if (samples.is_two_sided(s)) {
                    if (two_sided_.empty()) two_sided_.assign(total, 0);
                    two_sided_[sphere] = 1;
                }
                ++sphere;
            }
            nodes_.push_back(c);
        } else {
            nodes_.push_back(c);
            stack.push_back({right[index], int64_t(slot)});
            stack.push_back({left[index], -1});
        }
    }
    sphere_count_ = sphere;
    if (!two_sided_.empty()) build_node_discs();
}

// Bottom up (children follow their parent).
void CompactTree::build_node_discs() {
    node_disc_.assign(4 * nodes_.size(), -1.0f);
    for (size_t i = nodes_.size(); i-- > 0;) fit_node_disc(uint32_t(i));
}

// A leaf's disc from its spheres' discs, an inner node's from its children's. A node thicker
// than half its radius is left a ball: its disc would prune little, and the walk would pay the
// test on every pair.
void CompactTree::fit_node_disc(uint32_t i) {
    float* disc = node_disc_.data() + 4 * size_t(i);
    disc[0] = disc[1] = disc[2] = disc[3] = -1.0f;
    auto centre = [&](const CompactNode& n) { return Eigen::Vector3f(n.center[0], n.center[1], n.center[2]); };
    // A part of a node: centre, normal, radius and half-thickness of a disc.
    struct Part {
        Eigen::Vector3f c, n;
        float r, t;
    };
    const CompactNode& node = nodes_[i];
    const uint32_t count = node.is_active() ? node.count : 2;
    if (count == 0) return;
    for (uint32_t p = 0; p < count; ++p) {
        if (node.is_active()) {
            const uint32_t k = node.first + p;
            if (!two_sided_[k] || !(Eigen::Vector3f(nx_[k], ny_[k], nz_[k]).squaredNorm() > 0))
                return; // a ball (QueryRun::shapes_touch)
        } else if (!(node_disc_[4 * size_t(p == 0 ? i + 1 : node.first) + 3] >= 0)) {
            return;
        }
    }
    auto part = [&](uint32_t p) -> Part {
        if (node.is_active()) {
            const uint32_t k = node.first + p;
            return {sphere_center(node, k), Eigen::Vector3f(nx_[k], ny_[k], nz_[k]).normalized(), node.ss_radius,
                    detail::kDiscHalfThickness * node.ss_radius};
        }
        const uint32_t child = p == 0 ? i + 1 : node.first;
        const float* d = node_disc_.data() + 4 * size_t(child);
        return {centre(nodes_[child]), Eigen::Vector3f(d[0], d[1], d[2]), nodes_[child].bv_radius, d[3]};
    };
    // Gathered on the stack (a pose allocates nothing); a larger active node's parts are made
    // again for the second pass.
    constexpr uint32_t kGathered = 32;
    Part gathered[kGathered];
    const bool kept = count <= kGathered;
    if (kept)
        for (uint32_t p = 0; p < count; ++p) gathered[p] = part(p);
    auto part_at = [&](uint32_t p) { return kept ? gathered[p] : part(p); };
    // Normals as axes: each turned to agree with the first, weighted by its radius.
    const Part first = part_at(0);
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    for (uint32_t p = 0; p < count; ++p) {
        const Part q = part_at(p);
        sum += (q.n.dot(first.n) >= 0 ? q.r : -q.r) * q.n;
    }
    if (!(sum.norm() > 0)) return;
    const Eigen::Vector3f n = sum.normalized(), c = centre(node);
    // A part reaches off the plane by its centre's offset, its radius times the sine of its
    // tilt, and its thickness; plus a relative margin for the rounding of these sums.
    float h = 0;
    for (uint32_t p = 0; p < count; ++p) {
        const Part q = part_at(p);
        h = std::max(h, std::abs(n.dot(q.c - c)) + q.r * n.cross(q.n).norm() + q.t);
    }
    h = h * (1 + 1e-5f) + 1e-6f * node.bv_radius;
    if (!(h <= 0.5f * node.bv_radius)) return;
    for (int k = 0; k < 3; ++k) disc[k] = n[k];
    disc[3] = h;
}

size_t CompactTree::memory_bytes() const {
    return nodes_.capacity() * sizeof(CompactNode) + centers_.capacity() * sizeof(float) +
           (nx_.capacity() + ny_.capacity() + nz_.capacity()) + two_sided_.capacity() +
           node_disc_.capacity() * sizeof(float) + sample_index_.capacity() * sizeof(uint32_t) +
           active_.capacity() * sizeof(uint32_t) + boxes_.capacity() * sizeof(double) +
           spheres_below_.capacity() * sizeof(uint32_t); // the last three: a deformed pose's
}

} // namespace spt
