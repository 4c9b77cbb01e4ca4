#pragma once
/// How spt reaches OpenGL: through a loader the caller passes, never by linking
/// a GL library (libOSMesa and glvnd's libOpenGL both export every `gl*` symbol,
/// and a direct call can land in the wrong one; see docs/rendering.md).
#include <functional>

namespace spt::render {

/// Returns the address of a GL entry point by name ("glDrawArrays"), or nullptr if
/// the current context has none; e.g. a wrapper around QOpenGLContext::getProcAddress,
/// OSMesaGetProcAddress or eglGetProcAddress. spt calls it only while the context
/// it belongs to is current.
using ProcLoader = std::function<void*(const char*)>;

} // namespace spt::render
