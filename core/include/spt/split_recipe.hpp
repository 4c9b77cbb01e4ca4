#pragma once
/// How a manual split was made (the authoring recipe): the rectangles, with the view that
/// drew each and how it combined with the selection. A rectangle with its view's matrices
/// is a region of the object frame (a prism for an orthographic view, a frustum for the
/// camera), so it selects again on a changed mesh. Stored in .spt version 3.
#include "spt/node_id.hpp"
#include <Eigen/Core>
#include <cstdint>
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

/// One rectangle of a selection: where it was drawn and how it combined.
struct RecipeStroke {
    ViewProjection view;          ///< the view's matrices and framebuffer size, pixels
    PixelRect rect;               ///< the rectangle, GL window pixels of that framebuffer
    SelectionMode mode = SelectionMode::Replace; ///< how it combined with the selection before it
    bool visible_only = false;    ///< depth-tested against the mesh (spt/selection.hpp)
};

/// One manual split: node `node` split by the selection its strokes make (left = selection).
struct RecipeStep {
    NodeId node = root_id();           ///< paper id of the node that was split
    std::vector<RecipeStroke> strokes; ///< in the order drawn; the first usually replaces
};

} // namespace spt
