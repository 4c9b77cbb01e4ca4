#pragma once
/// The sampling tree (paper §3-3, §3-4-1): a binary tree over the samples of a mesh.
/// Every node has a bounding sphere; only active nodes (the leaves) hold sample
/// indices and have their sampling spheres tested. All geometry is in the samples'
/// local frame (SampleSet::origin), model units.
#include "spt/node_id.hpp"
#include "spt/samples.hpp"
#include "spt/split_recipe.hpp"
#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

namespace spt {

struct BuildOptions; // tree_builder.hpp
namespace detail {
struct TreeGraft; // tree/split_chooser.hpp: build_subtree with a split chooser
}

/// One node, with the fields of the paper's CNode.
struct TreeNode {
    NodeId id = root_id(); ///< paper id (node_id.hpp)
    Eigen::Vector3f center = Eigen::Vector3f::Zero(); ///< bounding-sphere centre
    float bv_radius = 0;   ///< bounding-sphere radius
    float ss_radius = 0;   ///< sampling-sphere radius (for an inner node: the largest below it)
    bool active = true;    ///< a leaf whose sampling spheres are tested
    std::vector<uint32_t> samples; ///< sorted sample indices; empty unless active
};

/// How a node's bounding sphere is made.
enum class BoundsMethod {
    Tight, ///< contains every sampling sphere below the node (default, conservative)
    Paper, ///< centre of the node's sample box, radius half its longest side (paper §3-4-1)
};

/// Why a split or merge was refused.
struct EditResult {
    bool ok = true;     ///< the edit was made
    std::string reason; ///< empty when ok
    /// True when the edit was made.
    explicit operator bool() const { return ok; }
};

/// A build from motion made under a node (spt/motion_tree.hpp, build_motion_subtree): what
/// replaying it on a re-exported mesh needs (.spt version 5).
struct MotionBuildStep {
    NodeId node = root_id(); ///< paper id of the node built under
    /// The scene file run: a relative path is relative to the folder of the .spt file that holds
    /// the tree (front ends write it so when they know where the file goes).
    std::string scene;
    std::string object;      ///< the object of the scene whose motion it was
    int steps = 0;           ///< steps recorded (0: the scene's own count)
    uint32_t leaf_size = 8;  ///< BuildOptions::leaf_size of the build
    uint32_t after_steps = 0; ///< how many recipe steps were made before it (the order of a replay)
};

/// A named sampling tree over a SampleSet that the caller keeps alive alongside.
class SamplingTree {
public:
    /// A tree whose root holds every one of `sample_count` samples.
    SamplingTree(std::string name, uint32_t sample_count);
    /// A tree from explicit nodes (e.g. a loaded file); call validate() before use.
    SamplingTree(std::string name, std::vector<TreeNode> nodes);

    /// The tree's name, unique within a file.
    const std::string& name() const { return name_; }
    /// Renames the tree.
    void set_name(std::string name) { name_ = std::move(name); }

    /// Node by id, or nullptr.
    const TreeNode* find(NodeId id) const;
    /// All nodes in increasing id order.
    std::vector<const TreeNode*> nodes() const;
    /// Active nodes in increasing id order.
    std::vector<const TreeNode*> active_nodes() const;
    /// Number of nodes.
    size_t node_count() const { return nodes_.size(); }
    /// Deepest node depth (root is 0).
    int depth() const;

    /// Paper's split: left = node ∩ selection, right = node − left. The node must be
    /// active; both parts must be non-empty. Children get radii by `rule` and every
    /// bounding sphere on the path to the root is refreshed.
    EditResult split(NodeId node, const std::vector<uint32_t>& selection, const SampleSet& samples,
                     const RadiusRule& rule = {}, BoundsMethod bounds = BoundsMethod::Tight);
    /// Inverse of split: the node becomes active again with every sample below it.
    EditResult merge(NodeId node, const SampleSet& samples, const RadiusRule& rule = {},
                     BoundsMethod bounds = BoundsMethod::Tight);

    /// Sets an active node's sampling-sphere radius (model units, > 0) and refreshes the
    /// radii and bounding spheres on the path to the root.
    EditResult set_radius(NodeId node, float radius, const SampleSet& samples,
                          BoundsMethod bounds = BoundsMethod::Tight);
    /// Builds a subtree automatically under an active node (tree_builder.hpp's builder over
    /// the node's samples only); the rest of the tree is unchanged but for the path's bounds.
    EditResult build_subtree(NodeId node, const SampleSet& samples, const BuildOptions& options);

    /// Sets every active node's radius by `rule` (inner nodes: largest below).
    void assign_radii(const SampleSet& samples, const RadiusRule& rule);
    /// Recomputes every bounding sphere, leaves first.
    void compute_bounds(const SampleSet& samples, BoundsMethod method);

    /// Checks structure against `sample_count`: ids form a tree, every sample is in
    /// exactly one active node, values are finite and radii positive. Empty when valid.
    std::string validate(uint32_t sample_count) const;

    /// How the manual splits were made, in the order made (.spt version 3); a merge drops the
    /// steps of the merged node and of every node below it.
    const std::vector<RecipeStep>& recipe() const { return recipe_; }
    /// Records how the split of `step.node` was made (after the split).
    void add_recipe_step(RecipeStep step) { recipe_.push_back(std::move(step)); }
    /// Replaces the recipe (loaders).
    void set_recipe(std::vector<RecipeStep> recipe) { recipe_ = std::move(recipe); }
    /// The builds from motion made in this tree, in the order made; a merge drops those under the merged node.
    const std::vector<MotionBuildStep>& motion_builds() const { return motion_builds_; }
    /// Records a build from motion (after it was made); its after_steps is set to the recipe's length now.
    void add_motion_build(MotionBuildStep step) {
        step.after_steps = uint32_t(recipe_.size());
        motion_builds_.push_back(std::move(step));
    }
    /// Replaces the builds from motion (loaders).
    void set_motion_builds(std::vector<MotionBuildStep> builds) { motion_builds_ = std::move(builds); }

private:
    friend struct detail::TreeGraft;
    // Edits go through split, merge, set_radius and build_subtree, which keep the tree valid.
    TreeNode* find_mutable(NodeId id);
    void put(TreeNode node);
    void refresh_path(NodeId from, const SampleSet& samples, BoundsMethod method);
    void remove_subtree(NodeId id);
    std::string name_;
    std::map<NodeId, TreeNode> nodes_;
    std::vector<RecipeStep> recipe_;
    std::vector<MotionBuildStep> motion_builds_;
};

} // namespace spt
