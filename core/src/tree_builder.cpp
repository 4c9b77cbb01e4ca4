#include "spt/tree_builder.hpp"
#include <Eigen/Geometry>
#include <algorithm>
#include <array>

namespace spt {
namespace {

using Box = Eigen::AlignedBox3f;

struct Builder {
    const SampleSet& samples;
    const BuildOptions& options;
    std::vector<uint32_t> perm;
    std::vector<TreeNode> out;

    Box box_of(size_t b, size_t e) const {
        Box box;
        for (size_t i = b; i < e; ++i) box.extend(samples.points[perm[i]]);
        return box;
    }

    // Index in [b, e) where the right part starts; b < result < e.
    size_t split_median(size_t b, size_t e, const Box& box) {
        int axis;
        box.sizes().maxCoeff(&axis);
        const size_t mid = b + (e - b) / 2;
        std::nth_element(perm.begin() + long(b), perm.begin() + long(mid), perm.begin() + long(e),
                         [&](uint32_t x, uint32_t y) {
                             const float a = samples.points[x][axis], c = samples.points[y][axis];
                             return a != c ? a < c : x < y;
                         });
        return mid;
    }

    size_t split_volume(size_t b, size_t e, const Box& box) {
        constexpr int kBins = 16;
        float best_cost = INFINITY;
        int best_axis = -1, best_plane = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const float lo = box.min()[axis], extent = box.sizes()[axis];
            if (!(extent > 0)) continue;
            std::array<Box, kBins> bins;
            std::array<size_t, kBins> counts{};
            const float scale = kBins / extent;
            for (size_t i = b; i < e; ++i) {
                const auto& p = samples.points[perm[i]];
                const int k = std::min(kBins - 1, int((p[axis] - lo) * scale));
                bins[k].extend(p);
                ++counts[k];
            }
            // Sweep: cost of a plane is the sum of the children's bounding-sphere volumes (r^3).
            std::array<float, kBins> left_cost{};
            std::array<size_t, kBins> left_n{};
            Box acc;
            size_t n = 0;
            for (int k = 0; k < kBins - 1; ++k) {
                if (counts[k]) acc.extend(bins[k]);
                n += counts[k];
                const float r = acc.isEmpty() ? 0 : acc.diagonal().norm() / 2;
                left_cost[k] = r * r * r;
                left_n[k] = n;
            }
            acc.setEmpty();
            for (int k = kBins - 1; k > 0; --k) {
                if (counts[k]) acc.extend(bins[k]);
                const size_t nl = left_n[k - 1];
                if (nl == 0 || nl == e - b) continue;
                const float r = acc.diagonal().norm() / 2;
                const float cost = left_cost[k - 1] + r * r * r;
                if (cost < best_cost) best_cost = cost, best_axis = axis, best_plane = k;
            }
        }
        if (best_axis < 0) return split_median(b, e, box);
        const float lo = box.min()[best_axis], scale = kBins / box.sizes()[best_axis];
        auto mid = std::partition(perm.begin() + long(b), perm.begin() + long(e), [&](uint32_t s) {
            return std::min(kBins - 1, int((samples.points[s][best_axis] - lo) * scale)) < best_plane;
        });
        return size_t(mid - perm.begin());
    }

    void build(size_t b, size_t e, NodeId id) {
        TreeNode node;
        node.id = id;
        const size_t n = e - b;
        if (n <= options.leaf_size || node_depth(id) >= kMaxNodeDepth) {
            node.samples.assign(perm.begin() + long(b), perm.begin() + long(e));
            std::sort(node.samples.begin(), node.samples.end());
            out.push_back(std::move(node));
            return;
        }
        const Box box = box_of(b, e);
        size_t mid = options.strategy == SplitStrategy::Median ? split_median(b, e, box) : split_volume(b, e, box);
        if (mid <= b || mid >= e) mid = split_median(b, e, box);
        node.active = false;
        out.push_back(std::move(node));
        build(b, mid, left_child(id));
        build(mid, e, right_child(id));
    }
};

} // namespace

SamplingTree build_tree(std::string name, const SampleSet& samples, const BuildOptions& options) {
    if (samples.size() == 0) return SamplingTree(std::move(name), 0u);
    BuildOptions fixed = options;
    fixed.leaf_size = std::max<uint32_t>(1, options.leaf_size);
    Builder builder{samples, fixed, std::vector<uint32_t>(samples.size()), {}};
    for (uint32_t i = 0; i < samples.size(); ++i) builder.perm[i] = i;
    builder.build(0, samples.size(), root_id());
    SamplingTree tree(std::move(name), std::move(builder.out));
    tree.assign_radii(samples, options.radius);
    tree.compute_bounds(samples, options.bounds);
    return tree;
}

} // namespace spt
