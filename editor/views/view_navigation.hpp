#pragma once
// Camera moves of the editor's views, as pure functions of a render::Camera: pan, zoom
// about a point, orbit. Sizes are the view's logical pixels; lengths model units.
#include "spt/render/camera.hpp"

namespace spt::editor {

/// World length of one logical pixel at the target's depth in a width x height view.
float pixel_size(const render::Camera& camera, int width, int height);
/// Moves the camera so the scene follows the mouse by (dx, dy) logical pixels (y down).
void pan(render::Camera& camera, float dx, float dy, int width, int height);
/// Zooms by `factor` (> 1 magnifies); an orthographic view keeps the world point under
/// (x, y) (logical pixels from the top left) under the cursor.
void zoom_about(render::Camera& camera, float factor, float x, float y, int width, int height);
/// Orbits the perspective camera by (dx, dy) logical pixels of mouse motion.
void orbit(render::Camera& camera, float dx, float dy);

} // namespace spt::editor
