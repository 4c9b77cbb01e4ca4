#pragma once
// Factories of the compiled-in backends (each in its own file, linked only here).
#include "spt/render/offscreen.hpp"

namespace spt::render::detail {

#ifdef SPT_HAVE_OSMESA
std::unique_ptr<OffscreenContext> make_osmesa_context(int width, int height);
#endif
#ifdef SPT_HAVE_EGL
std::unique_ptr<OffscreenContext> make_egl_context(int width, int height);
#endif

// Sets the Mesa environment that pins the llvmpipe rasteriser; called before a
// backend initialises Mesa.
void pin_llvmpipe();

} // namespace spt::render::detail
