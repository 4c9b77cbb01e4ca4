#pragma once
// Exact equality of frames and cameras: whether a view's cached layers still show a frame.
#include "spt/render/camera.hpp"
#include "spt/render/frame.hpp"

namespace spt::render::detail {

// True when `a` and `b` draw the same (every field equal, floats compared exactly; the
// uploads behind the handles are compared by the caller through their revisions).
bool same_frame(const Frame& a, const Frame& b);
// True when every field of the two cameras is equal.
bool same_camera(const Camera& a, const Camera& b);

} // namespace spt::render::detail
