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
    /// by a count per sample (a heat map: MotionRecording::contact_steps, how many steps of a recorded
    /// motion each sample's sphere was in contact), through heat_scale and heat_color
    Contacts,
};

/// How counts map to the heat map's colours: 0 is neutral grey; the nonzero counts run from
/// `low` to `high` along a perceptual ramp (viridis: dark violet to yellow), on a log scale when
/// high / low > kHeatLogRatio (a few samples in contact at many steps would otherwise leave
/// every other one at the dark end).
struct HeatScale {
    uint32_t low = 0;  ///< smallest nonzero count (0 when every count is 0)
    uint32_t high = 0; ///< largest count
    bool log = false;  ///< log scale between low and high
};
/// Above this ratio of the largest to the smallest nonzero count, the scale is logarithmic.
constexpr double kHeatLogRatio = 20;
/// The scale of `counts` (one per sample).
HeatScale heat_scale(const std::vector<uint32_t>& counts);
/// Colour of `count` on `scale` (opaque).
Color heat_color(const HeatScale& scale, uint32_t count);
/// Colour of a count of 0 (neutral grey).
Color heat_zero_color();

/// One row of the heat map's legend: counts in [from, to], their colour (of the middle of the
/// row's span), and how many samples have them.
struct HeatLegendRow {
    uint32_t from = 0, to = 0; ///< inclusive range of counts
    Color color;               ///< heat_color at the row's middle
    size_t samples = 0;        ///< samples whose count is in the range
};
/// The legend of `counts` on `scale`: a row for 0, then at most `rows` rows splitting
/// [low, high] evenly on the scale (log or linear), each holding distinct whole counts.
std::vector<HeatLegendRow> heat_legend(const HeatScale& scale, const std::vector<uint32_t>& counts, int rows = 5);

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
/// local_frame(origin) to keep a model far from the origin sharp. ColorBy::Contacts colours each
/// sphere by its sample's entry of `counts` (one per sample of the tree's sample set; missing or
/// null: all 0) on heat_scale(counts).
std::vector<SphereInstance> sampling_spheres(const CompactTree& compact, const SamplingTree& tree, ColorBy by,
                                             const Eigen::Vector3d& frame_origin = Eigen::Vector3d::Zero(),
                                             const std::vector<uint32_t>* counts = nullptr);

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
/// node's spheres in the highlight colour; without, the node's spheres alone. With `own_colors`
/// (a heat map, whose colours are the information, or an inner node: its leaves' colours tell its
/// children apart) the node's spheres keep their own colours, undimmed, the rest dimmed. What the
/// editor's views and `spt render --overlay node` draw.
std::vector<SphereItem> highlighted_node(SphereSetHandle set, uint32_t set_size, SphereRange node, bool show_all,
                                         bool own_colors = false);

/// True when node `id` of `tree` is an inner node (split): highlighted_node's `own_colors`.
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
