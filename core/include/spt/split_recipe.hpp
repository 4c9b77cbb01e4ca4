#pragma once
/// How a manual split was made (the authoring recipe): the rectangles, with the view that
/// drew each and how it combined with the selection. A rectangle with its view's matrices
/// is a region of the object frame (a prism for an orthographic view, a frustum for the
/// camera), so it selects again on a changed mesh. Stored in .spt version 3; a split made at a
/// pose of an animated mesh records the pose too (version 4).
#include "spt/node_id.hpp"
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace spt {

/// How a view maps object-frame points to its framebuffer.
struct ViewProjection {
    Eigen::Matrix4f view = Eigen::Matrix4f::Identity();       ///< object frame to eye (OpenGL: eye looks down -Z)
    Eigen::Matrix4f projection = Eigen::Matrix4f::Identity(); ///< eye to clip
    bool perspective = false; ///< true: a point must lie in front of the eye to be selectable
    int width = 1;            ///< framebuffer width, pixels
    int height = 1;           ///< framebuffer height, pixels
};

/// A rectangle in GL window coordinates: pixels from the framebuffer's lower-left corner.
/// Corners in any order; a point on the border is inside.
struct PixelRect {
    float x0 = 0; ///< one corner, pixels from the left
    float y0 = 0; ///< one corner, pixels from the bottom
    float x1 = 0; ///< opposite corner, pixels from the left
    float y1 = 0; ///< opposite corner, pixels from the bottom
};

/// How a new rectangle combines with the current selection (fixed when the drag starts).
enum class SelectionMode {
    Replace,  ///< the rectangle's samples replace the selection
    Add,      ///< added to the selection
    Subtract, ///< removed from the selection
};

/// What a stroke of a selection is: a region drawn in a view (rectangle, lasso, brush), a pick
/// (linked), or an operation on the selection so far (invert, grow, shrink). Stored as one byte
/// (.spt version 5 for any kind but Rect); the values never change meaning.
enum class StrokeKind : uint8_t {
    Rect = 0,   ///< the rectangle `rect`
    Lasso = 1,  ///< the polygon `points` (even-odd inside)
    Brush = 2,  ///< a circle of `radius` pixels moved along the path `points`
    Linked = 3, ///< the mesh-connected part holding the sample nearest `pick`
    Invert = 4, ///< the node's samples not selected
    Grow = 5,   ///< the selection and its neighbours (one ring of mesh adjacency)
    Shrink = 6, ///< the selection less the samples with an unselected neighbour
};
/// The largest StrokeKind value.
constexpr uint8_t kLastStrokeKind = 6;

/// One stroke of a selection: where it was drawn and how it combined.
struct RecipeStroke {
    ViewProjection view;          ///< the view's matrices and framebuffer size, pixels
    PixelRect rect;               ///< the rectangle (kind Rect), GL window pixels of that framebuffer
    SelectionMode mode = SelectionMode::Replace; ///< how it combined with the selection before it
    bool visible_only = false;    ///< depth-tested against the mesh (spt/selection.hpp)
    StrokeKind kind = StrokeKind::Rect; ///< what the stroke is (rectangle unless given)
    std::vector<Eigen::Vector2f> points = {}; ///< Lasso: polygon vertices; Brush: path; GL window pixels
    float radius = 0;             ///< Brush: circle radius, GL window pixels
    Eigen::Vector3d pick = Eigen::Vector3d::Zero(); ///< Linked: object-frame point (the picked sample's)
    /// True for the kinds that change the selection without a view (invert, grow, shrink).
    bool is_operation() const { return kind == StrokeKind::Invert || kind == StrokeKind::Grow || kind == StrokeKind::Shrink; }
    /// True for the kinds that read mesh adjacency (linked, grow, shrink).
    bool needs_adjacency() const {
        return kind == StrokeKind::Linked || kind == StrokeKind::Grow || kind == StrokeKind::Shrink;
    }
};

/// The pose of an animated mesh the strokes were drawn at (docs/deforming.md): the samples
/// selected where the clip put them at that time.
struct RecipePose {
    std::string clip; ///< the clip's name; empty for the bind pose (the mesh as imported)
    double time = 0;  ///< seconds into the clip (0 at the bind pose)
    /// True for the bind pose.
    bool bind() const { return clip.empty(); }
    /// Same clip and time.
    bool operator==(const RecipePose& o) const { return clip == o.clip && time == o.time; }
    /// Another clip or time.
    bool operator!=(const RecipePose& o) const { return !(*this == o); }
};

/// One manual split: node `node` split by the selection its strokes make (left = selection).
struct RecipeStep {
    NodeId node = root_id();           ///< paper id of the node that was split
    std::vector<RecipeStroke> strokes; ///< in the order drawn; the first usually replaces
    RecipePose pose;                   ///< where the samples were when the strokes were drawn

    /// A step of the root with no strokes, at the bind pose.
    RecipeStep() = default;
    /// The split of `split_node` by `drawn`, at `at` (the bind pose unless given; a constructor, so
    /// that a step written {node, strokes} as before poses needs no third field).
    RecipeStep(NodeId split_node, std::vector<RecipeStroke> drawn, RecipePose at = {})
        : node(split_node), strokes(std::move(drawn)), pose(std::move(at)) {}
};

} // namespace spt
