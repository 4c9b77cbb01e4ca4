// SamplingTree: the paper's split and merge, radii, bounds and validation.
#include "spt/sampling_tree.hpp"
#include "tree/bounds.hpp"
#include "base/parallel.hpp"
#include <algorithm>
#include <cmath>
#include <functional>

namespace spt {

SamplingTree::SamplingTree(std::string name, uint32_t sample_count) : name_(std::move(name)) {
    TreeNode root;
    root.samples.resize(sample_count);
    for (uint32_t i = 0; i < sample_count; ++i) root.samples[i] = i;
    nodes_.emplace(root.id, std::move(root));
}

SamplingTree::SamplingTree(std::string name, std::vector<TreeNode> nodes) : name_(std::move(name)) {
    // Inserting in id order at the end skips the map's searches; of equal ids the last given wins.
    const auto by_id = [](const TreeNode& a, const TreeNode& b) { return a.id < b.id; };
    if (std::is_sorted(nodes.begin(), nodes.end(), by_id)) {
        for (TreeNode& n : nodes) nodes_.insert_or_assign(nodes_.end(), n.id, std::move(n));
        return;
    }
    std::vector<std::pair<NodeId, size_t>> order(nodes.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = {nodes[i].id, i};
    std::sort(order.begin(), order.end());
    for (const auto& [id, i] : order) nodes_.insert_or_assign(nodes_.end(), id, std::move(nodes[i]));
}

const TreeNode* SamplingTree::find(NodeId id) const {
    auto it = nodes_.find(id);
    return it == nodes_.end() ? nullptr : &it->second;
}

TreeNode* SamplingTree::find_mutable(NodeId id) {
    auto it = nodes_.find(id);
    return it == nodes_.end() ? nullptr : &it->second;
}

void SamplingTree::put(TreeNode node) { nodes_[node.id] = std::move(node); }

std::vector<const TreeNode*> SamplingTree::nodes() const {
    std::vector<const TreeNode*> out;
    out.reserve(nodes_.size());
    for (const auto& [id, n] : nodes_) out.push_back(&n);
    return out;
}

std::vector<const TreeNode*> SamplingTree::active_nodes() const {
    std::vector<const TreeNode*> out;
    for (const auto& [id, n] : nodes_)
        if (n.active) out.push_back(&n);
    return out;
}

int SamplingTree::depth() const {
    int d = 0;
    for (const auto& [id, n] : nodes_) d = std::max(d, node_depth(id));
    return d;
}

float node_radius(const std::vector<uint32_t>& members, const SampleSet& samples, const RadiusRule& rule) {
    if (rule.fixed > 0) return rule.fixed;
    if (members.empty()) return 0;
    // The median spacing makes neighbouring spheres overlap; the smallest allowed radius
    // keeps every sphere of the node from poking out of the mesh.
    // Leaves are small: their spacings fit on the stack (no allocation per leaf).
    const size_t n = members.size();
    float local[64];
    std::vector<float> heap(n > 64 ? n : 0);
    float* s = n > 64 ? heap.data() : local;
    float cap = INFINITY;
    for (size_t i = 0; i < n; ++i) {
        s[i] = samples.spacing[members[i]];
        if (!samples.max_radius.empty()) cap = std::min(cap, samples.max_radius[members[i]]);
    }
    std::nth_element(s, s + n / 2, s + n);
    const float r = std::min(rule.scale * s[n / 2], cap);
    return r > 0 ? r : 1e-6f;
}

void bound_samples(TreeNode& node, const std::vector<uint32_t>& members, const SampleSet& samples, BoundsMethod method,
                   const detail::Ball& hint) {
    std::vector<Eigen::Vector3f> c(members.size()), p(members.size());
    std::vector<float> r(members.size(), node.ss_radius);
    for (size_t i = 0; i < members.size(); ++i) {
        p[i] = samples.points[members[i]];
        c[i] = samples.sphere_center(members[i], node.ss_radius);
    }
    detail::bound_run(node, c.data(), r.data(), p.data(), members.size(), hint, method);
}

namespace {

// Writes an active node's sampling spheres (centres, radii) from c and r on and, if `p` is
// given, their surface points from p on: one entry per sample.
void put_spheres(const TreeNode& n, const SampleSet& samples, Eigen::Vector3f* c, float* r, Eigen::Vector3f* p) {
    for (size_t k = 0; k < n.samples.size(); ++k) {
        const uint32_t s = n.samples[k];
        if (p) p[k] = samples.points[s];
        c[k] = samples.sphere_center(s, n.ss_radius);
        r[k] = n.ss_radius;
    }
}

float radius_at(const NodeArray& tree, uint32_t i) { return i == NodeArray::kNone ? 0.0f : tree.node[i]->ss_radius; }

// Bounds every node of a NodeArray, children before parents. The samples are laid out leaf by
// leaf so that every node covers one contiguous run; the runs are placed before the pass, so
// subtrees near the root are bounded on threads of their own with the same result.
struct BoundsPass {
    NodeArray& tree;
    const SampleSet& samples;
    BoundsMethod method;
    std::vector<Eigen::Vector3f> c, p; // p only for the paper's bounds, the one method that reads it
    std::vector<float> r;
    std::vector<uint32_t> begin, end; // per node: its run of spheres
    std::vector<uint8_t> equal;       // per node: every radius of its run is the first
    int parallel_depth = 0;           // nodes this shallow bound their two subtrees at once
    TaskSystem* tasks = nullptr;      // a host's threads for that, or the library's pool

    // Subtrees of at least this many spheres may be bounded on a thread of their own.
    static constexpr uint32_t kParallelRun = 1 << 15;

    struct Result {
        detail::Ball ball;
        Eigen::AlignedBox3f box; // of the sphere centres below
    };

    // Places every node's run (children follow their parent: backwards, children come first).
    void place_runs() {
        const size_t n = tree.node.size();
        std::vector<uint32_t> count(n);
        for (size_t i = n; i-- > 0;) {
            const TreeNode& t = *tree.node[i];
            if (t.active) {
                count[i] = uint32_t(t.samples.size());
                continue;
            }
            count[i] = 0;
            for (uint32_t child : {tree.left[i], tree.right[i]})
                if (child != NodeArray::kNone) count[i] += count[child];
        }
        begin[0] = 0, end[0] = count[0];
        for (size_t i = 0; i < n; ++i) { // parents before children
            uint32_t at = begin[i];
            if (tree.node[i]->active) continue;
            for (uint32_t child : {tree.left[i], tree.right[i]})
                if (child != NodeArray::kNone) begin[child] = at, end[child] = at += count[child];
        }
        c.resize(count[0]), r.resize(count[0]);
        if (method == BoundsMethod::Paper) p.resize(count[0]);
    }

    Result visit(uint32_t i, int depth) {
        TreeNode& n = *tree.node[i];
        const uint32_t first = begin[i], last = end[i];
        Result out;
        detail::Ball hint;
        detail::RunFacts facts;
        if (n.active) {
            put_spheres(n, samples, c.data() + first, r.data() + first, p.empty() ? nullptr : p.data() + first);
            for (uint32_t k = first; k < last; ++k) out.box.extend(c[k]);
            equal[i] = !std::isnan(n.ss_radius);
        } else {
            equal[i] = 1;
            const uint32_t child[2] = {tree.left[i], tree.right[i]};
            Result sub[2];
            const bool both = child[0] != NodeArray::kNone && child[1] != NodeArray::kNone;
            if (depth < parallel_depth && both &&
                std::min(end[child[0]] - begin[child[0]], end[child[1]] - begin[child[1]]) >= kParallelRun)
                detail::parallel_for(2, 2, [&](size_t k, int) { sub[k] = visit(child[k], depth + 1); }, tasks);
            else
                for (int k = 0; k < 2; ++k)
                    if (child[k] != NodeArray::kNone) sub[k] = visit(child[k], depth + 1);
            for (int k = 0; k < 2; ++k)
                if (child[k] != NodeArray::kNone) {
                    hint = detail::merge_balls(hint, sub[k].ball);
                    out.box.extend(sub[k].box);
                    if (begin[child[k]] < end[child[k]]) equal[i] &= equal[child[k]] && r[begin[child[k]]] == r[first];
                }
        }
        facts.centre_box = &out.box;
        facts.equal_radii = equal[i];
        const SubtreeSearch search(*this, i);
        if (!n.active) facts.farthest = &search;
        const Eigen::Vector3f* points = p.empty() ? nullptr : p.data() + first;
        detail::bound_run(n, c.data() + first, r.data() + first, points, last - first, hint, method, facts);
        out.ball = {n.center.cast<double>(), double(n.bv_radius)};
        return out;
    }

    // Measures an inner node's radii from its subtree: a node whose bounding sphere cannot reach
    // past the farthest sphere found so far is not read. The result is the full pass's, as the
    // spheres skipped are provably nearer (by a margin far above the rounding of the tests).
    class SubtreeSearch : public detail::FarthestSearch {
    public:
        SubtreeSearch(const BoundsPass& pass, uint32_t node) : pass_(pass), node_(node) {}
        void radii(const Eigen::Vector3d* centre, size_t m, bool equal_radii, double* out) const override {
            const float r0 = pass_.r[pass_.begin[node_]];
            for (size_t k = 0; k < m; ++k) {
                double best = 0; // equal radii: largest squared distance; otherwise largest distance + radius
                descend(node_, centre[k], equal_radii, r0, best);
                out[k] = equal_radii ? std::sqrt(best) + r0 : best;
            }
        }

    private:
        void descend(uint32_t j, const Eigen::Vector3d& centre, bool equal_radii, float r0, double& best) const {
            const uint32_t b = pass_.begin[j], e = pass_.end[j];
            const NodeArray& t = pass_.tree;
            if (t.node[j]->active || e - b <= kScan) {
                best = std::max(best, detail::run_extent(centre, pass_.c.data() + b, pass_.r.data() + b, e - b, equal_radii));
                return;
            }
            uint32_t child[2] = {t.left[j], t.right[j]};
            double reach[2];
            for (int s = 0; s < 2; ++s) reach[s] = child[s] == NodeArray::kNone ? -1 : reach_of(*t.node[child[s]], centre);
            if (reach[1] > reach[0]) std::swap(child[0], child[1]), std::swap(reach[0], reach[1]);
            for (int s = 0; s < 2; ++s) {
                if (child[s] == NodeArray::kNone) continue;
                // Everything below lies within reach (minus its radius): skip unless it can matter.
                const double bound = equal_radii ? square(std::max(0.0, reach[s] - r0)) : reach[s];
                if (bound < best) continue;
                descend(child[s], centre, equal_radii, r0, best);
            }
        }
        // An upper bound on |centre - c_i| + r_i over the node's spheres, with a relative margin.
        static double reach_of(const TreeNode& n, const Eigen::Vector3d& centre) {
            const double d = (n.center.cast<double>() - centre).norm();
            return (d + n.bv_radius) * (1 + 1e-9);
        }
        static double square(double x) { return x * x; }
        static constexpr uint32_t kScan = 16; // runs this short are read whole
        const BoundsPass& pass_;
        uint32_t node_;
    };
};

// Appends node `id` and, depth first, the nodes below it; returns its index (kNone if missing).
uint32_t add_subtree(std::map<NodeId, TreeNode>& nodes, NodeId id, NodeArray& out) {
    const auto it = nodes.find(id);
    if (it == nodes.end()) return NodeArray::kNone;
    TreeNode* n = &it->second;
    const uint32_t i = out.add(n);
    if (!n->active) {
        const uint32_t l = add_subtree(nodes, left_child(id), out);
        out.left[i] = l;
        const uint32_t r = add_subtree(nodes, right_child(id), out);
        out.right[i] = r;
    }
    return i;
}

} // namespace

void assign_radii(NodeArray& tree, const SampleSet& samples, const RadiusRule& rule) {
    // Children follow their parent: walking backwards finishes children first.
    for (size_t i = tree.node.size(); i-- > 0;) {
        TreeNode& n = *tree.node[i];
        n.ss_radius = n.active ? node_radius(n.samples, samples, rule)
                               : std::max(radius_at(tree, tree.left[i]), radius_at(tree, tree.right[i]));
    }
}

void compute_bounds(NodeArray& tree, const SampleSet& samples, BoundsMethod method, int threads, TaskSystem* tasks) {
    if (tree.node.empty()) return;
    BoundsPass pass{tree, samples, method, {}, {}, {}, std::vector<uint32_t>(tree.node.size()),
                    std::vector<uint32_t>(tree.node.size()), std::vector<uint8_t>(tree.node.size())};
    pass.parallel_depth = detail::parallel_levels(threads);
    pass.tasks = tasks;
    pass.place_runs();
    pass.visit(0, 0);
}

void SamplingTree::assign_radii(const SampleSet& samples, const RadiusRule& rule) {
    NodeArray array;
    add_subtree(nodes_, root_id(), array);
    spt::assign_radii(array, samples, rule);
}

void SamplingTree::compute_bounds(const SampleSet& samples, BoundsMethod method) {
    NodeArray array;
    array.node.reserve(nodes_.size()), array.left.reserve(nodes_.size()), array.right.reserve(nodes_.size());
    add_subtree(nodes_, root_id(), array);
    spt::compute_bounds(array, samples, method);
}

void SamplingTree::refresh_path(NodeId from, const SampleSet& samples, BoundsMethod method) {
    // The path's nodes, bottom up. Each one is re-bound from every sampling sphere below it; the
    // spheres of a node on the path are a run of its parent's (depth first, left then right), so
    // they are gathered once from the top, not once a node (a split deep in an authored tree
    // would gather the whole tree at every level).
    std::vector<TreeNode*> path;
    for (NodeId id = from; id != 0; id = parent_of(id))
        if (TreeNode* n = find_mutable(id)) path.push_back(n);
    if (path.empty()) return;
    std::vector<Eigen::Vector3f> c, p; // p only for the paper's bounds, the one method that reads it
    std::vector<float> rad;
    const bool points = method == BoundsMethod::Paper;
    c.reserve(samples.size()), rad.reserve(samples.size()); // grown by doubling, a big tree's pages were most of a split
    if (points) p.reserve(samples.size());
    constexpr size_t kUnset = ~size_t(0);
    std::vector<std::pair<size_t, size_t>> run(path.size(), {kUnset, kUnset});
    const int from_depth = node_depth(from);
    std::function<void(const TreeNode&)> gather = [&](const TreeNode& t) {
        const size_t begin = c.size();
        if (t.active) {
            c.resize(begin + t.samples.size()), rad.resize(c.size());
            if (points) p.resize(c.size());
            put_spheres(t, samples, c.data() + begin, rad.data() + begin, points ? p.data() + begin : nullptr);
        } else {
            if (const TreeNode* l = find(left_child(t.id))) gather(*l);
            if (const TreeNode* r = find(right_child(t.id))) gather(*r);
        }
        const int up = from_depth - node_depth(t.id);
        if (up >= 0 && (from >> up) == t.id) // on the path: path[k] is `up` levels above `from`, less the missing
            for (size_t k = 0; k < path.size(); ++k)
                if (path[k] == &t) run[k] = {begin, c.size()};
    };
    for (size_t k = path.size(); k-- > 0;) // a missing ancestor (a broken tree) parts the path
        if (run[k].first == kUnset) gather(*path[k]);
    for (size_t k = 0; k < path.size(); ++k) {
        TreeNode* n = path[k];
        const NodeId id = n->id;
        if (!n->active) {
            const TreeNode* l = find(left_child(id));
            const TreeNode* r = find(right_child(id));
            n->ss_radius = std::max(l ? l->ss_radius : 0.0f, r ? r->ss_radius : 0.0f);
        }
        detail::Ball hint;
        if (!n->active)
            for (NodeId child : {left_child(id), right_child(id)})
                if (const TreeNode* ch = find(child)) hint = detail::merge_balls(hint, {ch->center.cast<double>(), ch->bv_radius});
        const size_t begin = run[k].first, count = run[k].second - begin;
        detail::bound_run(*n, c.data() + begin, rad.data() + begin, points ? p.data() + begin : nullptr, count, hint, method);
    }
}

EditResult SamplingTree::split(NodeId id, const std::vector<uint32_t>& selection, const SampleSet& samples,
                               const RadiusRule& rule, BoundsMethod bounds) {
    TreeNode* n = find_mutable(id);
    if (!n) return {false, "node " + std::to_string(id) + " does not exist"};
    if (!n->active) return {false, "node " + std::to_string(id) + " is already split; select an active node"};
    if (node_depth(id) >= kMaxNodeDepth)
        return {false, "node " + std::to_string(id) + " is at the deepest level ids allow (" +
                           std::to_string(kMaxNodeDepth) + ")"};
    std::vector<uint32_t> sel = selection;
    std::sort(sel.begin(), sel.end());
    TreeNode left, right;
    left.id = left_child(id);
    right.id = right_child(id);
    std::set_intersection(n->samples.begin(), n->samples.end(), sel.begin(), sel.end(), std::back_inserter(left.samples));
    std::set_difference(n->samples.begin(), n->samples.end(), left.samples.begin(), left.samples.end(),
                        std::back_inserter(right.samples));
    if (left.samples.empty()) return {false, "the selection holds none of node " + std::to_string(id) + "'s samples"};
    if (right.samples.empty())
        return {false, "the selection holds all of node " + std::to_string(id) + "'s samples; nothing would be left"};
    left.ss_radius = node_radius(left.samples, samples, rule);
    right.ss_radius = node_radius(right.samples, samples, rule);
    // The parent's centre is a candidate for each half: a half of a ring is bounded best from
    // the ring's centre, where the centre of its own box would give a sphere larger than the
    // parent's.
    const detail::Ball parent{n->center.cast<double>(), double(n->bv_radius)};
    bound_samples(left, left.samples, samples, bounds, parent);
    bound_samples(right, right.samples, samples, bounds, parent);
    n->active = false;
    n->samples.clear();
    n->samples.shrink_to_fit();
    put(std::move(left));
    put(std::move(right));
    refresh_path(id, samples, bounds);
    return {};
}

EditResult SamplingTree::set_radius(NodeId id, float radius, const SampleSet& samples, BoundsMethod bounds) {
    TreeNode* n = find_mutable(id);
    if (!n) return {false, "node " + std::to_string(id) + " does not exist"};
    if (!n->active)
        return {false, "node " + std::to_string(id) + " is split; its radius is the largest of its children's"};
    if (!(radius > 0) || !std::isfinite(radius)) return {false, "a sampling-sphere radius must be positive and finite"};
    n->ss_radius = radius;
    refresh_path(id, samples, bounds);
    return {};
}

void SamplingTree::remove_subtree(NodeId id) {
    for (NodeId child : {left_child(id), right_child(id)}) {
        if (node_depth(id) >= kMaxNodeDepth || !find(child)) continue;
        remove_subtree(child);
        nodes_.erase(child);
    }
}

EditResult SamplingTree::merge(NodeId id, const SampleSet& samples, const RadiusRule& rule, BoundsMethod bounds) {
    TreeNode* n = find_mutable(id);
    if (!n) return {false, "node " + std::to_string(id) + " does not exist"};
    if (n->active) return {false, "node " + std::to_string(id) + " is active; there is nothing to merge"};
    std::vector<uint32_t> all;
    for (const auto& [nid, t] : nodes_) {
        if (!t.active || nid <= id) continue;
        NodeId a = nid;
        while (a > id) a = parent_of(a);
        if (a == id) all.insert(all.end(), t.samples.begin(), t.samples.end());
    }
    std::sort(all.begin(), all.end());
    remove_subtree(id);
    // The merged splits no longer exist: neither do the steps that made them.
    auto under = [id](NodeId node) {
        while (node > id) node = parent_of(node);
        return node == id;
    };
    // A build from motion keeps its place among the recipe steps that remain.
    for (MotionBuildStep& m : motion_builds_) {
        uint32_t gone = 0;
        for (uint32_t k = 0; k < m.after_steps && k < recipe_.size(); ++k) gone += under(recipe_[k].node);
        m.after_steps -= gone;
    }
    motion_builds_.erase(std::remove_if(motion_builds_.begin(), motion_builds_.end(),
                                        [&](const MotionBuildStep& m) { return under(m.node); }),
                         motion_builds_.end());
    recipe_.erase(std::remove_if(recipe_.begin(), recipe_.end(), [&](const RecipeStep& step) { return under(step.node); }),
                  recipe_.end());
    n = find_mutable(id);
    n->active = true;
    n->samples = std::move(all);
    n->ss_radius = node_radius(n->samples, samples, rule);
    refresh_path(id, samples, bounds);
    return {};
}

std::string SamplingTree::validate(uint32_t sample_count) const {
    auto where = [](NodeId id) { return "node " + std::to_string(id) + ": "; };
    if (!find(root_id())) return "tree has no root node";
    std::vector<uint8_t> seen(sample_count, 0);
    // Parents' and children's ids grow with a node's id, so two cursors walking the nodes in id
    // order find them (a look-up each made this a tenth of saving a 1M-sample tree).
    auto parent = nodes_.begin(), child = nodes_.begin();
    auto seek = [&](std::map<NodeId, TreeNode>::const_iterator& c, NodeId want) {
        while (c != nodes_.end() && c->first < want) ++c;
        return c != nodes_.end() && c->first == want ? &c->second : nullptr;
    };
    for (const auto& [id, n] : nodes_) {
        if (id == 0 || id != n.id) return where(id) + "invalid id";
        if (node_depth(id) > kMaxNodeDepth) return where(id) + "deeper than " + std::to_string(kMaxNodeDepth) + " levels";
        if (id != root_id()) {
            const TreeNode* p = seek(parent, parent_of(id));
            if (!p) return where(id) + "parent " + std::to_string(parent_of(id)) + " is missing";
            if (p->active) return where(id) + "parent " + std::to_string(parent_of(id)) + " is active";
        }
        if (!n.center.allFinite() || !std::isfinite(n.bv_radius) || n.bv_radius < 0)
            return where(id) + "bounding sphere is not finite and non-negative";
        if (!std::isfinite(n.ss_radius) || !(n.ss_radius > 0)) return where(id) + "sampling-sphere radius must be > 0";
        if (n.active) {
            if (n.samples.empty()) return where(id) + "active node holds no samples";
            for (size_t i = 0; i < n.samples.size(); ++i) {
                const uint32_t s = n.samples[i];
                if (s >= sample_count)
                    return where(id) + "sample index " + std::to_string(s) + " out of range (" +
                           std::to_string(sample_count) + " samples)";
                if (i && s <= n.samples[i - 1]) return where(id) + "sample indices are not strictly increasing";
                if (seen[s]) return where(id) + "sample " + std::to_string(s) + " is in two active nodes";
                seen[s] = 1;
            }
        } else {
            if (!n.samples.empty()) return where(id) + "inactive node holds samples";
            // The right child's id follows the left's: one cursor finds both.
            const bool left = seek(child, left_child(id)) != nullptr;
            if (!left || std::next(child) == nodes_.end() || std::next(child)->first != right_child(id))
                return where(id) + "inactive node lacks a child";
        }
    }
    for (uint32_t s = 0; s < sample_count; ++s)
        if (!seen[s]) return "sample " + std::to_string(s) + " is in no active node";
    return {};
}

} // namespace spt
