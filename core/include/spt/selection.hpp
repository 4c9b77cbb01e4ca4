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

/// Samples below node `id` whose surface point projects inside the lasso `polygon` (GL window
/// pixels, vertices in drawing order, closed from the last to the first; even-odd rule); sorted.
/// With `depth`, only those the mesh does not hide, as visible_samples_in_rect (`tolerance` in
/// model units). Fewer than 3 vertices select nothing; a vertex not finite is Error(Usage).
std::vector<uint32_t> samples_in_polygon(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                         const ViewProjection& view, const std::vector<Eigen::Vector2f>& polygon,
                                         const DepthMap* depth = nullptr, float tolerance = 0);

/// Samples below node `id` whose surface point projects within `radius` GL window pixels of the
/// brush `path` (window points joined by segments; one point: a circle); sorted. With `depth`,
/// only those the mesh does not hide. An empty path selects nothing; a point or radius not finite,
/// or a negative radius, is Error(Usage).
std::vector<uint32_t> samples_in_brush(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                       const ViewProjection& view, const std::vector<Eigen::Vector2f>& path,
                                       float radius, const DepthMap* depth = nullptr, float tolerance = 0);

/// The GL window rectangle (pixels) holding a drawn stroke's region: the rectangle, the lasso's
/// bounding box, the brush path's box grown by its radius; where a visible-only test reads depth.
PixelRect stroke_window(const RecipeStroke& stroke);

/// The sample below node `id` that projects nearest window point (x, y) (GL window pixels), at
/// most `max_pixels` from it: nearest in the window, then nearest the eye, then the lowest index.
/// With `depth`, only samples the mesh does not hide. -1 if there is none.
int64_t pick_sample(const SamplePoints& samples, const SamplingTree& tree, NodeId id, const ViewProjection& view,
                    const Eigen::Vector2f& window, float max_pixels, const DepthMap* depth = nullptr,
                    float tolerance = 0);

/// The sample below node `id` whose surface point (origin + point) is nearest object-frame
/// point `p` (model units), the lowest index among equals; -1 if the node has none.
int64_t nearest_sample(const SamplePoints& samples, const SamplingTree& tree, NodeId id, const Eigen::Vector3d& p);

/// Mesh adjacency of samples. A vertex sample touches its vertex, a face sample its triangle's
/// three vertices; two samples are neighbours when they touch the same vertex or two vertices
/// joined by a mesh edge. Parts are the mesh's edge-connected parts. Built once, in order (no
/// threads), so everything read from it is deterministic.
class SampleAdjacency {
public:
    /// The adjacency of `samples` taken from `mesh`; Error(Usage) if a sample's source lies
    /// beyond the mesh (samples of another mesh).
    SampleAdjacency(const TriangleMesh& mesh, const SampleSet& samples);
    /// Number of samples.
    size_t size() const { return first_vertex_.size(); }
    /// Sample `s`'s neighbours (sorted, without `s`).
    std::vector<uint32_t> neighbours(uint32_t s) const;
    /// The mesh part sample `s` lies on (an index; equal for samples on one part).
    uint32_t part(uint32_t s) const { return part_[first_vertex_[s]]; }

private:
    std::vector<uint32_t> first_vertex_;              // per sample: the vertex (or a corner) it touches
    std::vector<uint32_t> touch_start_, touching_;    // per vertex: the samples touching it
    std::vector<uint32_t> edge_start_, edge_to_;      // per vertex: vertices joined to it by an edge
    std::vector<uint32_t> corner_start_, corners_;    // per sample: the vertices it touches
    std::vector<uint32_t> part_;                      // per vertex: its part
};

/// Sample `s`'s neighbours through the mesh (sorted; SampleAdjacency::neighbours).
std::vector<uint32_t> sample_neighbours(const SampleAdjacency& adjacency, uint32_t s);

/// The samples below node `id` on the mesh part of sample `seed` (sorted): select linked.
std::vector<uint32_t> linked_samples(const SampleAdjacency& adjacency, const SamplingTree& tree, NodeId id,
                                     uint32_t seed);

/// `selection` (sorted) and every sample below node `id` neighbouring it: one ring grown.
std::vector<uint32_t> grow_selection(const SampleAdjacency& adjacency, const SamplingTree& tree, NodeId id,
                                     const std::vector<uint32_t>& selection);

/// `selection` (sorted) less its samples with a neighbour below node `id` that is not selected:
/// one ring shrunk.
std::vector<uint32_t> shrink_selection(const SampleAdjacency& adjacency, const SamplingTree& tree, NodeId id,
                                       const std::vector<uint32_t>& selection);

/// The samples below node `id` not in `selection` (sorted).
std::vector<uint32_t> invert_selection(const SamplingTree& tree, NodeId id, const std::vector<uint32_t>& selection);

/// The selection after `stroke` is applied to `current` (sorted) among the samples below
/// node `id`: through, or visible only against `mesh` (then `mesh` must not be null; at a pose,
/// the mesh at that pose). Linked, grow and shrink read `adjacency` (Error(Usage) if null).
std::vector<uint32_t> apply_stroke(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                   const std::vector<uint32_t>& current, const RecipeStroke& stroke,
                                   const TriangleMesh* mesh, const SampleAdjacency* adjacency = nullptr);

/// The hits of a stroke drawn in a view (rectangle, lasso, brush, linked) on its own, before it
/// combines with a selection; empty for an operation (invert, grow, shrink).
std::vector<uint32_t> stroke_hits(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                  const RecipeStroke& stroke, const TriangleMesh* mesh,
                                  const SampleAdjacency* adjacency = nullptr);

/// The selection a recipe step's strokes make, from nothing, below its node.
std::vector<uint32_t> select_strokes(const SamplePoints& samples, const SamplingTree& tree, const RecipeStep& step,
                                     const TriangleMesh* mesh, const SampleAdjacency* adjacency = nullptr);

/// The selection after a rectangle's `hits` are applied to `current` in `mode` (all sorted).
std::vector<uint32_t> combine_selection(const std::vector<uint32_t>& current, const std::vector<uint32_t>& hits,
                                        SelectionMode mode);

} // namespace spt
