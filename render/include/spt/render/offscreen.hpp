#pragma once
/// OpenGL contexts without a window, for `spt render` and the golden-image tests.
/// Each renders into its own single-sample RGBA8 + depth framebuffer object, so
/// every backend produces the same pixels; both pin Mesa's llvmpipe rasteriser
/// (see docs/rendering.md, "Determinism").
#include "spt/render/gl_loader.hpp"
#include "spt/render/image.hpp"
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace spt::render {

/// A current off-screen GL 3.3 core context with a framebuffer of fixed size.
class OffscreenContext {
public:
    /// Deletes the framebuffer and destroys the context; destroy every Renderer made on it first.
    virtual ~OffscreenContext();
    /// Not copyable: it owns a GL context.
    OffscreenContext(const OffscreenContext&) = delete;
    /// Not copyable: it owns a GL context.
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    /// Backend name: "osmesa" or "egl".
    virtual const char* backend() const = 0;
    /// The context's own proc-address function (OSMesaGetProcAddress, eglGetProcAddress), for Renderer.
    virtual ProcLoader loader() const = 0;
    /// Makes this context current on the calling thread (it is current after creation).
    virtual void make_current() = 0;

    /// Framebuffer width in pixels.
    int width() const { return width_; }
    /// Framebuffer height in pixels.
    int height() const { return height_; }
    /// Name of the framebuffer object to draw into (pass it to Renderer::draw).
    uint32_t framebuffer() const;
    /// GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    const std::string& gl_renderer() const { return renderer_; }
    /// GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6".
    const std::string& gl_version() const { return version_; }
    /// Waits for rendering to finish and returns the framebuffer as an Image: top row
    /// first (GL's rows, bottom first, are flipped), RGBA8 as drawn.
    Image read_pixels();

protected:
    /// A backend's context with a width x height framebuffer (pixels); no GL yet.
    OffscreenContext(int width, int height);
    /// Loads GL through loader(), checks the renderer and makes the framebuffer; the
    /// backend calls it once its context is current.
    void init_gl();
    /// Deletes the framebuffer; the backend calls it before destroying its context.
    void release_gl();

private:
    struct GlState; // the GL function table and the framebuffer's objects (offscreen.cpp)
    int width_, height_;
    std::unique_ptr<GlState> gl_;
    std::string renderer_, version_;
};

/// Backends compiled into this build, default first ("osmesa", "egl").
std::vector<std::string> offscreen_backends();

/// Bytes an off-screen render of width x height pixels holds at its peak: the context's
/// framebuffer, the renderer's layers and sphere splat, and the pixels read back (96 a pixel,
/// the measured peak of `spt render` at 2048 to 8192 pixels a side, rounded up).
uint64_t offscreen_render_bytes(int width, int height);

/// Creates and makes current an off-screen context of `backend` with a width x height
/// framebuffer (pixels, 1 to 16384 a side and at most the driver's limit). Throws
/// Error(Usage) for an unknown or unavailable backend or a size out of range, naming
/// the backend and the reason.
std::unique_ptr<OffscreenContext> make_offscreen_context(const std::string& backend, int width, int height);

} // namespace spt::render
