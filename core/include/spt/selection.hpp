#pragma once
/// Rectangle selection of samples as the sampling tool does it (paper §3-2): the samples
/// below a node whose surface point projects inside a rectangle of a view, either all of
/// them ("through", the paper's world-range test) or only those not hidden by the mesh
/// ("visible only", depth-tested against the mesh drawn into a depth map). The editor and
/// its tests both call these, so a selection made with the mouse has one reference.
#include "spt/mesh.hpp"
#include "spt/sampling_tree.hpp"
#include "spt/split_recipe.hpp"
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace spt {

/// Where object-frame point p lands: x, y in GL window pixels, z the eye depth (model
/// units in front of the eye; negative behind it). Computed in double through the view's
/// matrices composed once, rounded to float at the end, so a point far from the origin
/// keeps its place to the pixel.
Eigen::Vector3f project_to_window(const ViewProjection& view, const Eigen::Vector3d& p);

/// Every sample below node `id` (all samples of its active descendants), sorted; empty if
/// the tree has no such node.
std::vector<uint32_t> samples_below(const SamplingTree& tree, NodeId id);

/// Where a selection finds each sample's surface point: `points` (SampleSet order, the samples'
/// local frame) plus `origin` for the object frame. A SampleSet converts to its own points; a
/// deformed pose gives DeformingModel::sample_points() with the document's origin, so a rectangle
/// selects the samples where that pose draws them.
struct SamplePoints {
    const std::vector<Eigen::Vector3f>& points; ///< per sample, local frame, model units
    Eigen::Vector3d origin;                      ///< object-frame point `points` are relative to
    /// The samples' own surface points (implicit: every call with a SampleSet reads as it did).
    SamplePoints(const SampleSet& samples) : points(samples.points), origin(samples.origin) {} // NOLINT
    /// Surface points of a pose, relative to `local_origin`.
    SamplePoints(const std::vector<Eigen::Vector3f>& posed, const Eigen::Vector3d& local_origin)
        : points(posed), origin(local_origin) {}
};

/// Samples below node `id` whose surface point (origin + point) projects inside `rect`,
/// whatever is in front of them; sorted. Error(Usage) if `samples` has fewer points than the
/// tree's samples.
std::vector<uint32_t> samples_in_rect(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                      const ViewProjection& view, const PixelRect& rect);

/// Eye depth (model units) of the nearest mesh surface at each pixel centre of a view;
/// +infinity where no triangle covers the pixel. Row 0 is the bottom row.
struct DepthMap {
    int width = 0;            ///< pixels
    int height = 0;           ///< pixels
    std::vector<float> depth; ///< width * height eye depths, bottom row first
    /// Depth at pixel (x, y), +infinity outside the map.
    float at(int x, int y) const;
};

/// Draws `mesh` (object frame) into a depth map of the view's size, in software, so the
/// result does not depend on a GPU. Triangles crossing the eye plane are left out (they
/// hide nothing that could be missed).
DepthMap render_depth(const TriangleMesh& mesh, const ViewProjection& view);

/// Like render_depth, but draws only the pixels a rectangle selection reads: those inside
/// `window` (GL window pixels) and one pixel around it; every other pixel stays +infinity.
/// visible_samples_in_rect with the same rectangle gives the same result with either map.
DepthMap render_depth(const TriangleMesh& mesh, const ViewProjection& view, const PixelRect& window);

/// Like samples_in_rect, but only samples the mesh does not hide: a sample counts as
/// visible when its eye depth is at most `tolerance` (model units) behind the farthest
/// surface in the 3x3 pixels around it, so a sample on the surface is never missed
/// where the depth map's pixel centres fall on neighbouring, steeper triangles.
std::vector<uint32_t> visible_samples_in_rect(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                              const ViewProjection& view, const PixelRect& rect,
                                              const DepthMap& depth, float tolerance);

/// Depth tolerance of visible-only selection on `mesh`: 0.5% of its diagonal (model units).
float visible_tolerance(const TriangleMesh& mesh);

/// The selection after `stroke` is applied to `current` (sorted) among the samples below
/// node `id`: through, or visible only against `mesh` (then `mesh` must not be null; at a pose,
/// the mesh at that pose).
std::vector<uint32_t> apply_stroke(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                   const std::vector<uint32_t>& current, const RecipeStroke& stroke,
                                   const TriangleMesh* mesh);

/// The selection a recipe step's strokes make, from nothing, below its node.
std::vector<uint32_t> select_strokes(const SamplePoints& samples, const SamplingTree& tree, const RecipeStep& step,
                                     const TriangleMesh* mesh);

/// The selection after a rectangle's `hits` are applied to `current` in `mode` (all sorted).
std::vector<uint32_t> combine_selection(const std::vector<uint32_t>& current, const std::vector<uint32_t>& hits,
                                        SelectionMode mode);

} // namespace spt
