// Sampling trees as draw data: sphere colours by level or node, subtree sphere ranges, bounding spheres.
#include "spt/render/tree_overlay.hpp"
#include <algorithm>
#include <cmath>

namespace spt::render {
namespace {

// A node of the layout found by walking the tree's ids from the root: the layout is depth-first,
// so a node's first child comes right after it and its right child is at `first` (a
// cost of the path, not of the tree: the editor asks this for every hidden or selected node).
struct LayoutNode {
    const TreeNode* node = nullptr;
    uint32_t index = 0;
};

// True when layout node `c` can be tree node `n`: the same sphere count. A layout that is not of
// the tree asked (stale) then gives no range rather than a wrong one.
bool same_node(const CompactNode& c, const TreeNode& n) { return c.count == (n.active ? n.samples.size() : 0); }

// The child of `at` on the left (or right) side, or none (none too where the layout disagrees).
LayoutNode child_of(const CompactTree& compact, const SamplingTree& tree, LayoutNode at, bool right) {
    const auto& nodes = compact.nodes();
    if (nodes[at.index].is_active()) return {};
    const TreeNode* left = tree.find(left_child(at.node->id));
    const TreeNode* child = right ? tree.find(right_child(at.node->id)) : left;
    if (!child) return {};
    const uint32_t index = right && left ? nodes[at.index].first : at.index + 1;
    if (index <= at.index || index >= nodes.size()) return {};
    if (!same_node(nodes[index], *child)) return {};
    return {child, index};
}

// Node `id` in the layout, or none.
LayoutNode find_in_layout(const CompactTree& compact, const SamplingTree& tree, NodeId id) {
    LayoutNode at{tree.find(root_id()), 0};
    if (id == 0 || !at.node || compact.nodes().empty() || !tree.find(id)) return {};
    if (!same_node(compact.nodes()[0], *at.node)) return {};
    for (int level = node_depth(id) - 1; at.node && level >= 0; --level)
        at = child_of(compact, tree, at, ((id >> level) & 1) != 0);
    return at;
}

// The first (or last) active node of the subtree under `at`, in layout order.
LayoutNode outermost_leaf(const CompactTree& compact, const SamplingTree& tree, LayoutNode at, bool last) {
    while (at.node && !at.node->active) {
        LayoutNode next = child_of(compact, tree, at, last);
        if (!next.node) next = child_of(compact, tree, at, !last);
        if (!next.node) return {};
        at = next;
    }
    return at;
}

Color hsv(float h, float s, float v) {
    const float c = v * s;
    const float hp = std::fmod(h, 1.0f) * 6.0f;
    const float x = c * (1.0f - std::fabs(std::fmod(hp, 2.0f) - 1.0f));
    float r = 0, g = 0, b = 0;
    if (hp < 1) r = c, g = x;
    else if (hp < 2) r = x, g = c;
    else if (hp < 3) g = c, b = x;
    else if (hp < 4) g = x, b = c;
    else if (hp < 5) r = x, b = c;
    else r = c, b = x;
    const float m = v - c;
    return {r + m, g + m, b + m, 1};
}

} // namespace

Color level_color(int depth) {
    // Ten distinguishable colours (Tableau 10), cycled for deep trees.
    static const Color palette[10] = {
        {0.306f, 0.475f, 0.655f, 1}, {0.949f, 0.557f, 0.169f, 1}, {0.882f, 0.341f, 0.349f, 1},
        {0.463f, 0.718f, 0.698f, 1}, {0.349f, 0.631f, 0.310f, 1}, {0.929f, 0.788f, 0.282f, 1},
        {0.690f, 0.478f, 0.631f, 1}, {1.000f, 0.616f, 0.655f, 1}, {0.612f, 0.459f, 0.373f, 1},
        {0.729f, 0.690f, 0.675f, 1}};
    return palette[size_t(std::max(depth, 0)) % 10];
}

Color node_color(NodeId id) {
    // splitmix64 finaliser: neighbouring ids get unrelated values.
    auto mix = [](uint64_t z) {
        z += 0x9e3779b97f4a7c15ull;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    };
    // The two children of a split contrast at a glance: the left child (2i) takes a hue from its
    // parent's id, the right child (2i + 1) the opposite hue; cousins get unrelated hues.
    const uint64_t family = mix(id > root_id() ? parent_of(id) : id);
    float hue = float(family & 0xffffff) / float(0x1000000);
    if (id > root_id() && (id & 1)) hue += 0.5f;
    const uint64_t own = mix(id);
    const float sat = 0.55f + 0.3f * float((own >> 24) & 0xff) / 255.0f;
    return hsv(hue, sat, 0.92f);
}

Color highlight_color() { return {1.0f, 0.78f, 0.05f, 1}; }

Color heat_zero_color() { return {0.62f, 0.62f, 0.62f, 1}; }

HeatScale heat_scale(const std::vector<uint32_t>& counts) {
    HeatScale s;
    for (uint32_t c : counts) {
        if (c == 0) continue;
        s.low = s.low == 0 ? c : std::min(s.low, c);
        s.high = std::max(s.high, c);
    }
    s.log = s.low > 0 && double(s.high) / double(s.low) > kHeatLogRatio;
    return s;
}

namespace {

// Where `count` (low <= count <= high) sits on the scale, 0 to 1.
double heat_position(const HeatScale& s, double count) {
    if (s.high <= s.low) return 1;
    if (s.log) return std::log(count / double(s.low)) / std::log(double(s.high) / double(s.low));
    return (count - double(s.low)) / double(s.high - s.low);
}

// The count at position t of the scale (inverse of heat_position).
double heat_count_at(const HeatScale& s, double t) {
    if (s.log) return double(s.low) * std::pow(double(s.high) / double(s.low), t);
    return double(s.low) + t * double(s.high - s.low);
}

// Viridis (matplotlib's perceptually uniform map) at t in [0, 1], from nine of its stops.
Color viridis(double t) {
    static const float stops[9][3] = {{0.267f, 0.005f, 0.329f}, {0.279f, 0.175f, 0.483f}, {0.230f, 0.322f, 0.546f},
                                      {0.173f, 0.449f, 0.558f}, {0.128f, 0.567f, 0.551f}, {0.153f, 0.683f, 0.498f},
                                      {0.361f, 0.786f, 0.388f}, {0.668f, 0.862f, 0.196f}, {0.993f, 0.906f, 0.144f}};
    const double x = std::clamp(t, 0.0, 1.0) * 8.0;
    const int i = std::min(int(x), 7);
    const float f = float(x - i);
    return {stops[i][0] + f * (stops[i + 1][0] - stops[i][0]), stops[i][1] + f * (stops[i + 1][1] - stops[i][1]),
            stops[i][2] + f * (stops[i + 1][2] - stops[i][2]), 1};
}

} // namespace

Color heat_color(const HeatScale& scale, uint32_t count) {
    if (count == 0 || scale.high == 0) return heat_zero_color();
    const double c = std::clamp(double(count), double(scale.low), double(scale.high));
    return viridis(heat_position(scale, c));
}

std::vector<HeatLegendRow> heat_legend(const HeatScale& scale, const std::vector<uint32_t>& counts, int rows) {
    std::vector<HeatLegendRow> out;
    HeatLegendRow zero;
    zero.color = heat_zero_color();
    out.push_back(zero);
    if (scale.high > 0) {
        // Row bounds evenly spaced on the scale, rounded to whole counts, each row at least one count wide.
        uint32_t from = scale.low;
        const int n = std::max(rows, 1);
        for (int r = 1; r <= n && from <= scale.high; ++r) {
            const uint32_t to = r == n ? scale.high
                                       : std::clamp(uint32_t(std::floor(heat_count_at(scale, double(r) / n))), from,
                                                    scale.high);
            HeatLegendRow row;
            row.from = from, row.to = to;
            row.color = heat_color(scale, uint32_t(std::lround(heat_count_at(
                                              scale, 0.5 * (heat_position(scale, from) + heat_position(scale, to))))));
            out.push_back(row);
            from = to + 1;
        }
    }
    for (uint32_t c : counts)
        for (HeatLegendRow& row : out)
            if (c >= row.from && c <= row.to) {
                ++row.samples;
                break;
            }
    return out;
}

std::vector<SphereInstance> sampling_spheres(const CompactTree& compact, const SamplingTree& tree, ColorBy by,
                                             const Eigen::Vector3d& frame_origin, const std::vector<uint32_t>* counts) {
    const auto nodes = tree.nodes();
    std::vector<SphereInstance> out(compact.sphere_count());
    const Eigen::Vector3d origin = compact.origin() - frame_origin;
    const HeatScale scale = by == ColorBy::Contacts && counts ? heat_scale(*counts) : HeatScale{};
    const uint32_t* sample = compact.sample_index();
    for (const CompactNode& c : compact.nodes()) {
        if (!c.is_active()) continue;
        const NodeId id = c.tree_node < nodes.size() ? nodes[c.tree_node]->id : root_id();
        const Color color = by == ColorBy::Level ? level_color(node_depth(id)) : node_color(id);
        for (uint32_t k = c.first; k < c.first + c.count; ++k) {
            out[k].sphere.center = (origin + compact.sphere_center(c, k).cast<double>()).cast<float>();
            out[k].sphere.radius = c.ss_radius;
            if (by != ColorBy::Contacts) {
                out[k].color = color;
            } else {
                const uint32_t s = sample[k];
                out[k].color = heat_color(scale, counts && s < counts->size() ? (*counts)[s] : 0);
            }
        }
    }
    return out;
}

SphereRange sphere_range(const CompactTree& compact, const SamplingTree& tree, NodeId id) {
    const LayoutNode at = find_in_layout(compact, tree, id);
    const LayoutNode first = outermost_leaf(compact, tree, at, false), last = outermost_leaf(compact, tree, at, true);
    if (!first.node || !last.node) return {};
    const CompactNode &a = compact.nodes()[first.index], &b = compact.nodes()[last.index];
    if (b.first + b.count < a.first) return {};
    return {a.first, b.first + b.count - a.first};
}

std::vector<SphereRange> shown_ranges(const CompactTree& compact, const SamplingTree& tree,
                                      const std::vector<NodeId>& hidden, uint32_t set_size) {
    std::vector<SphereRange> cut;
    for (NodeId id : hidden) {
        const SphereRange r = sphere_range(compact, tree, id);
        if (r.count > 0) cut.push_back(r);
    }
    std::sort(cut.begin(), cut.end(), [](const SphereRange& a, const SphereRange& b) { return a.first < b.first; });
    std::vector<SphereRange> shown;
    uint32_t from = 0;
    for (const SphereRange& r : cut) { // subtrees nest or are disjoint: a nested one starts before `from` ends
        if (r.first > from) shown.push_back({from, std::min(r.first, set_size) - from});
        from = std::max(from, std::min(r.first + r.count, set_size));
    }
    if (from < set_size) shown.push_back({from, set_size - from});
    return shown;
}

std::vector<SphereItem> clip_to_ranges(const std::vector<SphereItem>& items, const std::vector<SphereRange>& shown) {
    std::vector<SphereItem> out;
    for (const SphereItem& item : items) {
        const uint64_t first = item.first, end = first + item.count; // count may be UINT32_MAX: all
        for (const SphereRange& r : shown) {
            const uint64_t a = std::max<uint64_t>(first, r.first), b = std::min<uint64_t>(end, uint64_t(r.first) + r.count);
            if (a >= b) continue;
            SphereItem part = item;
            part.first = uint32_t(a), part.count = uint32_t(b - a);
            out.push_back(part);
        }
    }
    return out;
}

std::vector<WireSphere> bounding_sphere(const CompactTree& compact, const SamplingTree& tree, NodeId id,
                                        const Color& color) {
    const LayoutNode at = find_in_layout(compact, tree, id);
    if (!at.node) return {};
    const CompactNode& n = compact.nodes()[at.index];
    WireSphere w;
    w.sphere.center = (compact.origin() + Eigen::Vector3d(n.center[0], n.center[1], n.center[2])).cast<float>();
    w.sphere.radius = n.bv_radius;
    w.color = color;
    return {w};
}

bool is_inner_node(const SamplingTree& tree, NodeId id) {
    const TreeNode* n = tree.find(id);
    return n && !n->active;
}

std::vector<SphereItem> highlighted_node(SphereSetHandle set, uint32_t set_size, SphereRange node, bool show_all,
                                         bool own_colors) {
    // The spheres before and after the node's range, dimmed, then the range highlighted: each
    // sphere drawn once (llvmpipe's cost is per sphere), the range last as a second item over
    // all of them would be.
    const uint32_t first = std::min(node.first, set_size);
    const uint32_t end = first + std::min(node.count, set_size - first);
    std::vector<SphereItem> items;
    auto dimmed = [&](uint32_t from, uint32_t to) {
        SphereItem item;
        item.spheres = set, item.first = from, item.count = to - from;
        item.fade = kDimmedFade;
        items.push_back(item);
    };
    if (show_all && first > 0) dimmed(0, first);
    if (show_all && end < set_size) dimmed(end, set_size);
    if (end > first) {
        SphereItem item;
        item.spheres = set, item.first = first, item.count = end - first;
        if (!own_colors) item.color = highlight_color();
        items.push_back(item);
    }
    return items;
}

std::vector<WireSphere> bounding_spheres(const SamplingTree& tree, const Eigen::Vector3d& origin, NodeId id, int levels,
                                         const Color& color, const Eigen::Affine3f& pose) {
    std::vector<WireSphere> out;
    const TreeNode* top = tree.find(id);
    if (!top) return out;
    const int top_depth = node_depth(id);
    std::vector<NodeId> stack{id};
    while (!stack.empty()) {
        const NodeId n = stack.back();
        stack.pop_back();
        const TreeNode* node = tree.find(n);
        if (!node) continue;
        const int below = node_depth(n) - top_depth;
        WireSphere w;
        w.sphere.center = pose * Eigen::Vector3f((origin + node->center.cast<double>()).cast<float>());
        w.sphere.radius = node->bv_radius;
        w.color = n == id ? color : level_color(node_depth(n));
        out.push_back(w);
        if (!node->active && below < levels) {
            stack.push_back(right_child(n));
            stack.push_back(left_child(n));
        }
    }
    return out;
}

} // namespace spt::render
