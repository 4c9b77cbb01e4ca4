#pragma once
/// The query layout of a sampling tree: nodes in depth-first order in one array
/// (left child follows its parent, the right child is an index); the sampling-sphere
/// centres of each active node in one block (its x's, then y's, then z's), so a leaf
/// pair reads two or three cache lines a side and streams 8 spheres at a time. Size
/// is linear in the samples whatever the tree's shape. Float32 model units in the samples'
/// local frame (object frame minus origin()).
#include "spt/sampling_tree.hpp"
#include "spt/task_system.hpp"
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace spt {

/// One node of the query layout (32 bytes).
struct CompactNode {
    float center[3];   ///< bounding-sphere centre
    float bv_radius;   ///< bounding-sphere radius
    float ss_radius;   ///< sampling-sphere radius of the node's spheres
    uint32_t first;    ///< inner node: index of the right child; active node: first sphere
    uint32_t count;    ///< number of spheres; 0 for an inner node
    uint32_t tree_node; ///< index of the node in SamplingTree::nodes() order
    /// True for an active node (a leaf with spheres).
    bool is_active() const { return count != 0; }
};
static_assert(sizeof(CompactNode) == 32, "CompactNode must stay 32 bytes");

namespace detail {
class LazyPose;
}

/// Contiguous, SIMD-friendly copy of a tree for queries; changed after it is built only by
/// follow_samples and refit_bounds (a deformed pose), or part by part by a lazy pose.
class CompactTree {
public:
    /// An empty layout (no nodes).
    CompactTree() = default;
    /// Lays out `tree` over `samples`; sphere centres are p - r*n with the node's radius.
    CompactTree(const SamplingTree& tree, const SampleSet& samples);

    /// Object-frame point that every centre of the layout is relative to (SampleSet::origin).
    const Eigen::Vector3d& origin() const { return origin_; }
    /// Nodes, root first, depth-first.
    const std::vector<CompactNode>& nodes() const { return nodes_; }
    /// Centres of active node n's spheres: n.count x's, then n.count y's, then n.count z's.
    /// The array is padded by 8 floats so 8-wide loads from any block stay inside it.
    const float* centers(const CompactNode& n) const { return centers_.data() + 3 * size_t(n.first); }
    /// Centre of sphere k of active node n (n.first <= k < n.first + n.count).
    Eigen::Vector3f sphere_center(const CompactNode& n, uint32_t k) const {
        const float* c = centers(n) + (k - n.first);
        return {c[0], c[n.count], c[2 * n.count]};
    }
    /// x of each sphere's sample normal as snorm8 (value/127), sphere order.
    const int8_t* nx() const { return nx_.data(); }
    /// y of each sphere's sample normal as snorm8 (value/127), sphere order.
    const int8_t* ny() const { return ny_.data(); }
    /// z of each sphere's sample normal as snorm8 (value/127), sphere order.
    const int8_t* nz() const { return nz_.data(); }
    /// Per sphere, sphere order: 1 if two-sided (an open part's sphere, centred on the surface;
    /// its normal gives an axis, not a side). nullptr when no sphere is two-sided.
    const uint8_t* two_sided() const { return two_sided_.empty() ? nullptr : two_sided_.data(); }
    /// Per node, 4 floats: a unit normal and a half-thickness h such that the disc of every
    /// two-sided sphere below the node (its snorm8 normal, its radius, kDiscHalfThickness of it
    /// thick) lies within h of the plane through the node's centre; h < 0 when a sphere below
    /// is one-sided or the node is not flat. nullptr when no sphere is two-sided.
    const float* node_disc() const { return node_disc_.empty() ? nullptr : node_disc_.data(); }
    /// Sample index (into the SampleSet) of each sphere.
    const uint32_t* sample_index() const { return sample_index_.data(); }
    /// Number of spheres.
    size_t sphere_count() const { return sphere_count_; }
    /// Bytes held by the layout.
    size_t memory_bytes() const;

    /// Moves every sphere to follow its sample on a deformed surface: `points` and unit `normals`
    /// per sample of the SampleSet the layout was built over (local frame, model units), centre
    /// p - r*n (p if two-sided); then refit_bounds(). The tree's shape, radii and sphere order stay.
    /// Active nodes are spread over `threads` jobs on `tasks` (null: the library's pool); the
    /// layout is the same for any count.
    void follow_samples(const std::vector<Eigen::Vector3f>& points, const std::vector<Eigen::Vector3f>& normals,
                        int threads = 1, TaskSystem* tasks = nullptr);
    /// Fits every node's bounding sphere to the spheres below it, bottom up: an active node's
    /// around the middle of its centres' box; an inner node's the smallest ball holding its two
    /// children's or, with set_tight_refit and at least kTightSearchFrom spheres below it, the
    /// ball around the middle of its centres' box reaching its farthest sphere where that is
    /// smaller. A function of the centres alone:
    /// refitting after any sequence of poses gives what refitting a fresh layout at the last
    /// pose gives.
    void refit_bounds(int threads = 1, TaskSystem* tasks = nullptr);
    /// Whether refits search the spheres below each inner node of at least kTightSearchFrom
    /// spheres for a tighter ball (queries then walk about the node pairs of a build's tree;
    /// docs/deforming.md, "Refit").
    void set_tight_refit(bool tight) { tight_refit_ = tight; }
    /// The fewest spheres below an inner node whose ball a tight refit searches for.
    static constexpr uint32_t kTightSearchFrom = 256;

private:
    friend class detail::LazyPose; // poses the layout part by part (anim/lazy_pose.hpp)
    // Active node i's spheres and normals from `points` and `normals` (per sample), as follow_samples.
    void place_spheres(uint32_t i, const Eigen::Vector3f* points, const Eigen::Vector3f* normals);
    // Node i's ball as refit_bounds fits it: an active node's from its centres; an inner node's
    // from its two children's and, tight and `search_below`, the spheres below (every node
    // below fitted first).
    void fit_active_ball(uint32_t i);
    void fit_inner_ball(uint32_t i, bool search_below = true);
    // Node i's ball: one holding the ball (center, radius) once rounded to float.
    void set_ball(uint32_t i, const Eigen::Vector3d& center, double radius);
    // How far the spheres below node i reach from `from` (|from - c| + r at most), from the
    // balls below i; -1 if the subtree is too deep to search.
    double farthest_below(uint32_t i, const Eigen::Vector3d& from) const;
    // boxes_ sized for the nodes (before a refit).
    void ensure_boxes();
    std::vector<double> boxes_; // per node: the box of the sphere centres below it (lo xyz, hi xyz), set by a refit
    bool tight_refit_ = false;
    std::vector<uint32_t> spheres_below_; // per node: how many spheres lie below it (set with boxes_)
    Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
    std::vector<CompactNode> nodes_;
    std::vector<float> centers_;
    std::vector<int8_t> nx_, ny_, nz_;
    std::vector<uint8_t> two_sided_; // empty when no sphere is
    std::vector<float> node_disc_;   // empty when no sphere is two-sided
    void build_node_discs();
    // Node i's disc as build_node_discs makes it (its children's first); h < 0 if it is none.
    void fit_node_disc(uint32_t i);
    std::vector<uint32_t> sample_index_;
    size_t sphere_count_ = 0;
    std::vector<uint32_t> active_; // the active nodes, found at the first refit (a refit's jobs split them)
};

} // namespace spt
