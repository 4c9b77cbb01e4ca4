#pragma once
// Bounding spheres over a contiguous run of sampling spheres.
#include "tree/miniball.hpp"
#include "spt/sampling_tree.hpp"
#include <Eigen/Geometry>

namespace spt {

/// Radius that `rule` gives a node holding `members`.
float node_radius(const std::vector<uint32_t>& members, const SampleSet& samples, const RadiusRule& rule);

/// Bounding sphere of the sampling spheres of `members` under `method`; `hint` as for bound_run.
void bound_samples(TreeNode& node, const std::vector<uint32_t>& members, const SampleSet& samples,
                   BoundsMethod method, const detail::Ball& hint = {});

/// A tree's reachable nodes in depth-first order (a node, its left subtree, its right subtree)
/// with their children's indices, so that whole-tree passes need no look-ups by id.
struct NodeArray {
    static constexpr uint32_t kNone = ~0u; ///< no such child
    std::vector<TreeNode*> node;
    std::vector<uint32_t> left, right;
    /// Appends a node whose children are not known yet; returns its index.
    uint32_t add(TreeNode* n) {
        node.push_back(n), left.push_back(kNone), right.push_back(kNone);
        return uint32_t(node.size() - 1);
    }
};

/// Sets every node's sampling-sphere radius: active nodes by `rule`, inner nodes the largest below.
void assign_radii(NodeArray& tree, const SampleSet& samples, const RadiusRule& rule);

/// Sets every node's bounding sphere, leaves first (SamplingTree::compute_bounds's rule).
/// Threads: up to this many subtrees are bounded at once; the result is the same on any count.
void compute_bounds(NodeArray& tree, const SampleSet& samples, BoundsMethod method, int threads = 1,
                    TaskSystem* tasks = nullptr);

namespace detail {

/// Measures, for each of m candidate centres, the largest |centre - c_i| + r_i over a run's
/// spheres: exactly the values a pass over the run gives, found with the help of something the
/// caller knows (e.g. the bounding spheres of the nodes below).
class FarthestSearch {
public:
    virtual ~FarthestSearch() = default;
    /// Writes the m radii to `out`; `equal_radii` as bound_run found it.
    virtual void radii(const Eigen::Vector3d* centre, size_t m, bool equal_radii, double* out) const = 0;
};

/// What a caller already knows about a run, to save passes over it.
struct RunFacts {
    const Eigen::AlignedBox3f* centre_box = nullptr; ///< the box of the n centres
    int equal_radii = -1; ///< 1: every radius is r[0]; 0: not; -1: unknown
    const FarthestSearch* farthest = nullptr; ///< replaces the pass that measures radii (tight bounds)
};

/// Sets node.center/bv_radius from n sampling spheres (centres c, radii r, surface points p).
/// `hint` (may be empty) is a ball whose centre is worth trying, e.g. the children's merged
/// ball, or the parent's ball for the two halves of a split (tight bounds only).
void bound_run(TreeNode& node, const Eigen::Vector3f* c, const float* r, const Eigen::Vector3f* p, size_t n,
               const Ball& hint, BoundsMethod method, const RunFacts& facts = {});

/// Largest |centre - c_i|^2 over n spheres if `equal_radii`, else largest |centre - c_i| + r_i
/// (as bound_run computes them: with equal radii, the largest squared distance is what it roots).
double run_extent(const Eigen::Vector3d& centre, const Eigen::Vector3f* c, const float* r, size_t n, bool equal_radii);

} // namespace detail
} // namespace spt
