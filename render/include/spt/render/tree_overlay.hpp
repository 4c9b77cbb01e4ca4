#pragma once
/// Sampling trees as plain draw data: sampling spheres coloured by level or by
/// node, sphere ranges of subtrees (for highlighting), bounding spheres. Spheres
/// come in CompactTree order, so the spheres below any node are one range.
#include "spt/compact_tree.hpp"
#include "spt/render/frame.hpp"
#include "spt/sampling_tree.hpp"
#include <vector>

namespace spt::render {

/// How sampling spheres are coloured.
enum class ColorBy {
    Level, ///< by the depth of the sphere's active node (a fixed palette, cycled)
    Node,  ///< by the active node's paper id: siblings in opposite hues (the default everywhere)
};

/// Colour of tree depth `depth` (root 0) in the level palette.
Color level_color(int depth);
/// Stable colour of a node id: the left child of a split (2i) takes a hue hashed from its parent's
/// id, the right child (2i + 1) the opposite hue, so the two halves of every split contrast.
Color node_color(NodeId id);
/// Colour used for the highlighted node (opaque).
Color highlight_color();

/// Every sampling sphere of `compact` in the object frame (the layout's origin added), coloured by `by`; `tree` is
/// the tree `compact` was built from (for node ids and depths). Centres are relative to
/// `frame_origin` (subtracted in double): pass the layout's origin and draw the set with
/// local_frame(origin) to keep a model far from the origin sharp.
std::vector<SphereInstance> sampling_spheres(const CompactTree& compact, const SamplingTree& tree, ColorBy by,
                                             const Eigen::Vector3d& frame_origin = Eigen::Vector3d::Zero());

/// A range [first, first + count) of sampling_spheres(), i.e. of the CompactTree's spheres.
struct SphereRange {
    uint32_t first = 0; ///< index of the first sphere
    uint32_t count = 0; ///< number of spheres; 0 for an empty range
};
/// The spheres below node `id`: one range in CompactTree order; count 0 if the tree has
/// no such node.
SphereRange sphere_range(const CompactTree& compact, const SamplingTree& tree, NodeId id);

/// The ranges of sampling_spheres() (`set_size` spheres) left shown when the subtrees of the nodes
/// `hidden` are hidden: the complement of their ranges, in order, disjoint; ids the tree lacks hide nothing.
std::vector<SphereRange> shown_ranges(const CompactTree& compact, const SamplingTree& tree,
                                      const std::vector<NodeId>& hidden, uint32_t set_size);

/// `items` cut to the sphere ranges `shown` (in order, disjoint): each item's part inside them.
std::vector<SphereItem> clip_to_ranges(const std::vector<SphereItem>& items, const std::vector<SphereRange>& shown);

/// How much the spheres of nodes that are not highlighted are faded (SphereItem::fade).
constexpr float kDimmedFade = 0.7f;

/// The sphere items of set `set` (sampling_spheres()) with node range `node` highlighted:
/// with `show_all`, every sphere dimmed first (unless the node holds them all), then the
/// node's spheres in the highlight colour; without, the node's spheres alone. With `own_colours`
/// (an inner node: its leaves' colours tell its children apart) the node's spheres keep their
/// colours, undimmed, instead of the highlight colour. What the editor's views and `spt render
/// --overlay node` draw.
std::vector<SphereItem> highlighted_node(SphereSetHandle set, uint32_t set_size, SphereRange node, bool show_all,
                                         bool own_colours = false);

/// True when node `id` of `tree` is an inner node (split): highlighted_node's `own_colours`.
bool is_inner_node(const SamplingTree& tree, NodeId id);

/// Bounding spheres of node `id` and of its descendants down to `levels` levels
/// below it (0: the node alone), moved from the tree's local frame into the object frame
/// by `origin` (SampleSet::origin), then by `pose`. The node itself gets `color`,
/// descendants the level palette.
std::vector<WireSphere> bounding_spheres(const SamplingTree& tree, const Eigen::Vector3d& origin, NodeId id, int levels,
                                         const Color& color, const Eigen::Affine3f& pose = Eigen::Affine3f::Identity());

/// The bounding sphere of node `id` as `compact` (a layout of `tree`) holds it, in the object frame:
/// at a deformed pose (DeformingModel::model().tree()) the ball refit around the posed spheres.
/// Empty if the tree has no such node.
std::vector<WireSphere> bounding_sphere(const CompactTree& compact, const SamplingTree& tree, NodeId id,
                                        const Color& color);

} // namespace spt::render
