// Automatic sampling-tree construction: median or binned volume splits down to a leaf size.
#include "spt/tree_builder.hpp"
#include "sampling/radius_class.hpp"
#include "tree/bounds.hpp"
#include "tree/split_chooser.hpp"
#include "base/cancel.hpp"
#include "base/parallel.hpp"
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace spt {
namespace {

// The builder partitions these records in place, so every pass reads memory in order.
struct Item {
    float p[3];
    uint32_t sample; // read as a fourth float by Bounds3::extend4, which ignores it
    int radius_class; // of the sample's own radius under the build's rule
};

// Four lanes, the fourth ignored: one vector min and max per point (the binned sweep extends
// a box per point and axis). Min and max are exact, so the lanes agree with scalar code.
struct Bounds3 {
    alignas(16) float lo[4] = {INFINITY, INFINITY, INFINITY, INFINITY};
    alignas(16) float hi[4] = {-INFINITY, -INFINITY, -INFINITY, -INFINITY};
    // p: three coordinates and one more readable float (an Item's p and the word after it).
    void extend4(const float* p) {
#if defined(__SSE2__)
        const __m128 v = _mm_loadu_ps(p);
        _mm_store_ps(lo, _mm_min_ps(_mm_load_ps(lo), v));
        _mm_store_ps(hi, _mm_max_ps(_mm_load_ps(hi), v));
#else
        extend(p);
#endif
    }
    void extend(const float* p) {
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
    }
    // Also merges the ignored fourth lanes, which no reader looks at.
    void extend(const Bounds3& b) {
#if defined(__SSE2__)
        _mm_store_ps(lo, _mm_min_ps(_mm_load_ps(lo), _mm_load_ps(b.lo)));
        _mm_store_ps(hi, _mm_max_ps(_mm_load_ps(hi), _mm_load_ps(b.hi)));
#else
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
#endif
    }
    bool empty() const { return lo[0] > hi[0]; }
    // Half the diagonal: the radius of a sphere around the box.
    float radius() const {
        if (empty()) return 0;
        const float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
        return 0.5f * std::sqrt(dx * dx + dy * dy + dz * dz);
    }
};

// The unclamped bin of a point on each axis, int((p - lo) * scale) per lane: the same float
// operations as one axis at a time, three axes in one vector step.
struct AxisBins {
    alignas(16) float lo[4];
    alignas(16) float scale[4];
    AxisBins(const float* box_lo, const float* axis_scale)
        : lo{box_lo[0], box_lo[1], box_lo[2], 0}, scale{axis_scale[0], axis_scale[1], axis_scale[2], 0} {}
    // p: as for Bounds3::extend4; its fourth word is ignored.
    void operator()(const float* p, int* k) const {
#if defined(__SSE2__)
        // The fourth word (a sample index, often a denormal float) is zeroed: no slow arithmetic.
        const __m128 keep = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
        const __m128 v = _mm_and_ps(_mm_loadu_ps(p), keep);
        const __m128 t = _mm_mul_ps(_mm_sub_ps(v, _mm_load_ps(lo)), _mm_load_ps(scale));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(k), _mm_cvttps_epi32(t));
#else
        for (int a = 0; a < 3; ++a) k[a] = int((p[a] - lo[a]) * scale[a]);
#endif
    }
};

// Subtrees of at least this many samples may be built on a thread of their own.
constexpr size_t kParallelSubtree = 1 << 15;
// Nodes of at least this many samples look at the cancel flag before they are split: a check
// costs nothing beside such a split, and a node below it is built in well under a millisecond.
constexpr size_t kCancelCheckSamples = 1024;

struct Builder {
    const BuildOptions& options;
    std::vector<Item>& items; // builders of disjoint subtrees share it, each in its own range
    std::vector<TreeNode> out; // depth first: an inner node's left child follows it
    std::vector<uint32_t> right_of; // per node of `out`: its right child's index, or NodeArray::kNone
    int max_depth = kMaxNodeDepth; // deepest id the built nodes may have
    // Nodes shallower than this build their right child on another thread (as a builder of its
    // own, spliced in after the left child): the nodes, and their order, do not change.
    int parallel_depth = 0;
    // Set by split_volume when it knows the exact boxes of the two parts it made (left, right).
    std::array<Bounds3, 2> parts;
    bool parts_known = false;
    const detail::SplitChooser* chooser = nullptr; // asked first at every split (build from motion)

    // Appends a node to `out`; returns its index.
    size_t emit(TreeNode&& node) {
        out.push_back(std::move(node));
        right_of.push_back(NodeArray::kNone);
        return out.size() - 1;
    }

    // Emits an inner node and builds its children over [b, mid) and [mid, e); `boxes`, if
    // given, are the children's boxes.
    // `ask`: the chooser (if any) is asked at the children's nodes; false once it said nothing below
    // a node concerns it.
    void build_children(TreeNode&& node, size_t b, size_t mid, size_t e, const std::array<Bounds3, 2>* boxes = nullptr,
                        bool ask = true) {
        const NodeId id = node.id;
        node.active = false;
        const size_t at = emit(std::move(node));
        const Bounds3* left_box = boxes ? &(*boxes)[0] : nullptr;
        const Bounds3* right_box = boxes ? &(*boxes)[1] : nullptr;
        if (node_depth(id) < parallel_depth && std::min(mid - b, e - mid) >= kParallelSubtree) {
            Builder right{options, items, {}, {}, max_depth, parallel_depth, {}, false, chooser};
            detail::parallel_for(2, 2, [&](size_t k, int) {
                if (k == 0) build(b, mid, left_child(id), left_box, ask);
                else right.build(mid, e, right_child(id), right_box, ask);
            }, options.tasks);
            const auto base = uint32_t(out.size());
            right_of[at] = base;
            for (uint32_t r : right.right_of) right_of.push_back(r == NodeArray::kNone ? r : r + base);
            std::move(right.out.begin(), right.out.end(), std::back_inserter(out));
            return;
        }
        build(b, mid, left_child(id), left_box, ask);
        right_of[at] = uint32_t(out.size());
        build(mid, e, right_child(id), right_box, ask);
    }

    // The built nodes in breadth-first order, children left to right: increasing ids, the
    // order SamplingTree keeps them in.
    std::vector<TreeNode> in_id_order() {
        std::vector<TreeNode> sorted;
        sorted.reserve(out.size());
        std::vector<uint32_t> queue{0};
        queue.reserve(out.size());
        for (size_t k = 0; k < queue.size(); ++k) {
            const uint32_t i = queue[k];
            if (right_of[i] != NodeArray::kNone) queue.push_back(i + 1), queue.push_back(right_of[i]);
            sorted.push_back(std::move(out[i]));
        }
        return sorted;
    }

    // The built nodes with their children's indices (valid while `out` is not resized).
    NodeArray links() {
        NodeArray array;
        array.node.reserve(out.size()), array.left.reserve(out.size()), array.right.reserve(out.size());
        for (size_t i = 0; i < out.size(); ++i) {
            array.node.push_back(&out[i]);
            const bool inner = right_of[i] != NodeArray::kNone;
            array.left.push_back(inner ? uint32_t(i + 1) : NodeArray::kNone);
            array.right.push_back(right_of[i]);
        }
        return array;
    }

    Bounds3 box_of(size_t b, size_t e) const {
        Bounds3 box;
        for (size_t i = b; i < e; ++i) box.extend4(items[i].p);
        return box;
    }

    // Index in [b, e) where the right part starts.
    size_t split_median(size_t b, size_t e, const Bounds3& box) {
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (box.hi[a] - box.lo[a] > box.hi[axis] - box.lo[axis]) axis = a;
        const size_t mid = b + (e - b) / 2;
        std::nth_element(items.begin() + long(b), items.begin() + long(mid), items.begin() + long(e),
                         [axis](const Item& x, const Item& y) {
                             return x.p[axis] != y.p[axis] ? x.p[axis] < y.p[axis] : x.sample < y.sample;
                         });
        return mid;
    }

    size_t split_volume(size_t b, size_t e, const Bounds3& box) {
        constexpr int kBins = 16;
        std::array<std::array<Bounds3, kBins>, 3> bins;
        std::array<std::array<uint32_t, kBins>, 3> counts{};
        float scale[3];
        for (int a = 0; a < 3; ++a) {
            const float extent = box.hi[a] - box.lo[a];
            scale[a] = extent > 0 ? kBins / extent : 0;
        }
        auto bin_of = [&](const Item& it, int a) {
            return std::min(kBins - 1, int((it.p[a] - box.lo[a]) * scale[a]));
        };
        const AxisBins axis_bins(box.lo, scale);
        // Large nodes choose their plane from an even subsample: the cost estimate barely
        // changes, and the top levels stop dominating the build time. The partition is exact.
        // Neighbouring items mostly fall in the same bin: alternate items go to two sets of
        // bins, merged below, so consecutive updates do not wait on each other.
        const size_t stride = std::max<size_t>(1, (e - b) / 1024);
        std::array<std::array<Bounds3, kBins>, 3> odd_bins;
        std::array<std::array<uint32_t, kBins>, 3> odd_counts{};
        auto add = [&](const Item& it, std::array<std::array<Bounds3, kBins>, 3>& to,
                       std::array<std::array<uint32_t, kBins>, 3>& n) {
            int k[4];
            axis_bins(it.p, k);
            for (int a = 0; a < 3; ++a) {
                const int ka = std::min(kBins - 1, k[a]);
                to[a][ka].extend4(it.p);
                ++n[a][ka];
            }
        };
        size_t i = b;
        for (; i + stride < e; i += 2 * stride) {
            add(items[i], bins, counts);
            add(items[i + stride], odd_bins, odd_counts);
        }
        if (i < e) add(items[i], bins, counts);
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < kBins; ++k) bins[a][k].extend(odd_bins[a][k]), counts[a][k] += odd_counts[a][k];
        // A plane costs the children's bounding-sphere volumes (r^3), each weighted by its
        // sample count: the expected sphere tests if a query lands in a child in proportion
        // to its volume. Unweighted volumes peel off slivers and deepen the tree.
        float best_cost = INFINITY;
        int best_axis = -1, best_plane = 0;
        size_t total = 0;
        for (uint32_t c : counts[0]) total += c;
        for (int a = 0; a < 3; ++a) {
            if (scale[a] == 0) continue;
            std::array<float, kBins> left_cost{};
            std::array<size_t, kBins> left_n{};
            Bounds3 acc;
            size_t n = 0;
            for (int k = 0; k < kBins - 1; ++k) {
                acc.extend(bins[a][k]);
                n += counts[a][k];
                const float r = acc.radius();
                left_cost[k] = float(n) * r * r * r;
                left_n[k] = n;
            }
            acc = Bounds3();
            for (int k = kBins - 1; k > 0; --k) {
                acc.extend(bins[a][k]);
                const size_t nl = left_n[k - 1];
                if (nl == 0 || nl == total) continue;
                const float r = acc.radius();
                const float cost = left_cost[k - 1] + float(total - nl) * r * r * r;
                if (cost < best_cost) best_cost = cost, best_axis = a, best_plane = k;
            }
        }
        if (best_axis < 0) return split_median(b, e, box);
        auto mid = std::partition(items.begin() + long(b), items.begin() + long(e),
                                  [&](const Item& it) { return bin_of(it, best_axis) < best_plane; });
        if (stride == 1) {
            // Every item was binned: the parts' boxes are the unions of their bins.
            parts = {};
            for (int k = 0; k < kBins; ++k) parts[k < best_plane ? 0 : 1].extend(bins[best_axis][k]);
            parts_known = true;
        }
        return size_t(mid - items.begin());
    }

    // Builds the node `id` over [b, e); `known`, if given, is the box of the items.
    void build(size_t b, size_t e, NodeId id, const Bounds3* known = nullptr, bool ask = true) {
        if (e - b >= kCancelCheckSamples) detail::stop_if_cancelled(options.cancel, "building", "the tree");
        TreeNode node;
        node.id = id;
        // Active nodes must be radius-coherent. Grouping by radius class a few levels above
        // the leaves (rather than peeling classes off full leaves) keeps the leaves full.
        if (options.radius_coherent && node_depth(id) < max_depth && e - b <= 4 * size_t(options.leaf_size)) {
            int hi = items[b].radius_class, lo = hi;
            for (size_t i = b; i < e; ++i)
                hi = std::max(hi, items[i].radius_class), lo = std::min(lo, items[i].radius_class);
            if (hi != lo) {
                const int cut = lo + (hi - lo + 1) / 2;
                const auto mid = std::partition(items.begin() + long(b), items.begin() + long(e),
                                                [cut](const Item& it) { return it.radius_class >= cut; });
                build_children(std::move(node), b, size_t(mid - items.begin()), e);
                return;
            }
        }
        if (e - b <= options.leaf_size || node_depth(id) >= max_depth) {
            node.samples.reserve(e - b);
            for (size_t i = b; i < e; ++i) node.samples.push_back(items[i].sample);
            std::sort(node.samples.begin(), node.samples.end());
            emit(std::move(node));
            return;
        }
        const Bounds3 box = known ? *known : box_of(b, e);
        // Near the leaves a few samples remain and the binned sweep costs more than it can
        // save; the median of the longest axis is as good there.
        const bool small = e - b <= 4 * size_t(options.leaf_size);
        parts_known = false;
        if (chooser && ask) {
            std::vector<uint32_t> members(e - b);
            for (size_t i = b; i < e; ++i) members[i - b] = items[i].sample;
            std::vector<uint8_t> left;
            const detail::SplitChooser::Answer answer = chooser->choose(members.data(), members.size(), id, left);
            ask = answer != detail::SplitChooser::Answer::NotBelow;
            if (answer == detail::SplitChooser::Answer::Split) {
                // Left items first, each side in the order it had: the same on any thread count.
                std::vector<Item> parted;
                parted.reserve(e - b);
                for (size_t i = b; i < e; ++i)
                    if (left[i - b]) parted.push_back(items[i]);
                const size_t mid = b + parted.size();
                for (size_t i = b; i < e; ++i)
                    if (!left[i - b]) parted.push_back(items[i]);
                if (mid > b && mid < e) {
                    std::copy(parted.begin(), parted.end(), items.begin() + long(b));
                    build_children(std::move(node), b, mid, e);
                    return;
                }
            }
        }
        size_t mid = options.strategy == SplitStrategy::Median || small ? split_median(b, e, box)
                                                                        : split_volume(b, e, box);
        if (mid <= b || mid >= e) mid = split_median(b, e, box), parts_known = false;
        // Copied: the children's splits overwrite `parts`.
        const std::array<Bounds3, 2> boxes = parts;
        build_children(std::move(node), b, mid, e, parts_known ? &boxes : nullptr, ask);
    }
};


} // namespace

// A tree whose root (id 1) holds `members` (sorted sample indices), at most max_depth deep.
SamplingTree detail::build_over(std::string name, const SampleSet& samples, const std::vector<uint32_t>& members,
                                const BuildOptions& options, int max_depth, const SplitChooser* chooser) {
    BuildOptions fixed = options;
    fixed.leaf_size = std::max<uint32_t>(1, options.leaf_size);
    std::vector<Item> items(members.size());
    Builder builder{fixed, items, {}, {}, max_depth, detail::parallel_levels(options.threads), {}, false, chooser};
    for (size_t k = 0; k < members.size(); ++k) {
        const uint32_t i = members[k];
        const auto& p = samples.points[i];
        const float own = options.radius.for_sample(samples.spacing[i], samples.max_radius.empty() ? INFINITY
                                                                                            : samples.max_radius[i]);
        builder.items[k] = {{p.x(), p.y(), p.z()}, i, samples.is_two_sided(i) ? two_sided_radius_class(own) : radius_class(own)};
    }
    const size_t expected = 2 * members.size() / std::max<uint32_t>(1, fixed.leaf_size / 2) + 1;
    builder.out.reserve(expected), builder.right_of.reserve(expected);
    builder.build(0, members.size(), root_id());
    // Radii and bounds on the builder's array, where children are indices rather than look-ups.
    detail::stop_if_cancelled(options.cancel, "building", "the tree");
    NodeArray array = builder.links();
    assign_radii(array, samples, options.radius);
    detail::stop_if_cancelled(options.cancel, "building", "the tree");
    compute_bounds(array, samples, options.bounds, options.threads, options.tasks);
    return SamplingTree(std::move(name), builder.in_id_order());
}

SamplingTree build_tree(std::string name, const SampleSet& samples, const BuildOptions& options) {
    if (samples.size() == 0) return SamplingTree(std::move(name), 0u);
    std::vector<uint32_t> all(samples.size());
    for (uint32_t i = 0; i < samples.size(); ++i) all[i] = i;
    return detail::build_over(std::move(name), samples, all, options, kMaxNodeDepth, nullptr);
}

EditResult SamplingTree::build_subtree(NodeId id, const SampleSet& samples, const BuildOptions& options) {
    return detail::TreeGraft::build_subtree(*this, id, samples, options, nullptr);
}

EditResult detail::TreeGraft::build_subtree(SamplingTree& tree, NodeId id, const SampleSet& samples,
                                            const BuildOptions& options, const SplitChooser* chooser) {
    const TreeNode* n = tree.find(id);
    if (!n) return {false, "node " + std::to_string(id) + " does not exist"};
    if (!n->active) return {false, "node " + std::to_string(id) + " is already split; merge it first"};
    const uint32_t leaf = std::max<uint32_t>(1, options.leaf_size);
    if (n->samples.size() <= leaf || node_depth(id) >= kMaxNodeDepth)
        return {false, "node " + std::to_string(id) + " holds " + std::to_string(n->samples.size()) +
                           " samples, no more than the leaf size " + std::to_string(leaf)};
    // Built as a tree of its own (root 1), radii and bounds included, then renumbered under id.
    const int base = node_depth(id);
    const SamplingTree sub = build_over(tree.name_, samples, n->samples, options, kMaxNodeDepth - base, chooser);
    for (const TreeNode* t : sub.nodes()) {
        TreeNode moved = *t;
        const int d = node_depth(t->id);
        moved.id = (id << d) | (t->id - (NodeId(1) << d));
        tree.put(std::move(moved));
    }
    if (parent_of(id) != 0) tree.refresh_path(parent_of(id), samples, options.bounds);
    return {};
}

} // namespace spt
