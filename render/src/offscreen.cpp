// OffscreenContext's backend-independent part: framebuffer object, pixel read-back, choice of backend.
#include "spt/render/offscreen.hpp"
#include "gl_functions.hpp"
#include "offscreen_backends.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace spt::render {

namespace detail {
void pin_llvmpipe() {
    // llvmpipe output is byte-identical across runs and thread counts; softpipe and
    // hardware drivers are not, so the choice is not left to the environment.
    ::setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    ::setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
}
} // namespace detail

struct OffscreenContext::GlState {
    detail::GlFunctions gl;
    bool ready = false;
    GLuint fbo = 0, color_rb = 0, depth_rb = 0;
};

OffscreenContext::OffscreenContext(int width, int height)
    : width_(width), height_(height), gl_(std::make_unique<GlState>()) {}

OffscreenContext::~OffscreenContext() = default;

uint32_t OffscreenContext::framebuffer() const { return gl_->fbo; }

void OffscreenContext::init_gl() {
    GlState& g = *gl_;
    g.gl.load(loader());
    const detail::GlFunctions& gl = g.gl;
    auto str = [&](GLenum e) {
        const GLubyte* s = gl.GetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("unknown");
    };
    renderer_ = str(GL_RENDERER);
    version_ = str(GL_VERSION);
    if (renderer_.rfind("llvmpipe", 0) != 0)
        throw Error(ErrorKind::Usage, std::string(backend()) + ": the renderer is '" + renderer_ +
                                          "', not llvmpipe; its output would not be reproducible");
    GLint max_size = 0;
    gl.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    if (width_ > max_size || height_ > max_size)
        throw Error(ErrorKind::Usage, std::string(backend()) + ": " + std::to_string(width_) + "x" +
                                          std::to_string(height_) + " exceeds the largest framebuffer, " +
                                          std::to_string(max_size) + " pixels a side");
    gl.GenFramebuffers(1, &g.fbo);
    gl.GenRenderbuffers(1, &g.color_rb);
    gl.GenRenderbuffers(1, &g.depth_rb);
    gl.BindRenderbuffer(GL_RENDERBUFFER, g.color_rb);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
    gl.BindRenderbuffer(GL_RENDERBUFFER, g.depth_rb);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);
    gl.BindFramebuffer(GL_FRAMEBUFFER, g.fbo);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, g.color_rb);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, g.depth_rb);
    const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(backend()) + ": the off-screen framebuffer is incomplete");
    gl.DrawBuffer(GL_COLOR_ATTACHMENT0);
    gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
    check_gl(gl, "off-screen framebuffer");
    g.ready = true;
}

void OffscreenContext::release_gl() {
    GlState& g = *gl_;
    if (!g.ready) return;
    const detail::GlFunctions& gl = g.gl;
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.DeleteFramebuffers(1, &g.fbo);
    GLuint rbs[] = {g.color_rb, g.depth_rb};
    gl.DeleteRenderbuffers(2, rbs);
    g.ready = false;
}

Image OffscreenContext::read_pixels() {
    const detail::GlFunctions& gl = gl_->gl;
    Image im;
    im.width = width_, im.height = height_;
    im.rgba.resize(size_t(width_) * size_t(height_) * 4);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, gl_->fbo);
    gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.Finish();
    std::vector<uint8_t> rows(im.rgba.size());
    gl.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    check_gl(gl, "reading the off-screen framebuffer");
    // GL's row 0 is the bottom row; images are stored top row first.
    const size_t stride = size_t(width_) * 4;
    for (int y = 0; y < height_; ++y)
        std::memcpy(&im.rgba[size_t(y) * stride], &rows[size_t(height_ - 1 - y) * stride], stride);
    return im;
}

std::vector<std::string> offscreen_backends() {
    std::vector<std::string> names;
#ifdef SPT_HAVE_OSMESA
    names.push_back("osmesa");
#endif
#ifdef SPT_HAVE_EGL
    names.push_back("egl");
#endif
    return names;
}

uint64_t offscreen_render_bytes(int width, int height) {
    // Framebuffer colour and depth 8, layers 38, splat and its upload 40, read back twice 8.
    constexpr uint64_t kBytesPerPixel = 96;
    return uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0)) * kBytesPerPixel;
}

std::unique_ptr<OffscreenContext> make_offscreen_context(const std::string& backend, int width, int height) {
    constexpr int kMaxSide = 16384;
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
        throw Error(ErrorKind::Usage, "image size " + std::to_string(width) + "x" + std::to_string(height) +
                                          " is out of range (1 to " + std::to_string(kMaxSide) + " pixels a side)");
#ifdef SPT_HAVE_OSMESA
    if (backend == "osmesa") return detail::make_osmesa_context(width, height);
#endif
#ifdef SPT_HAVE_EGL
    if (backend == "egl") return detail::make_egl_context(width, height);
#endif
    std::string have;
    for (const auto& b : offscreen_backends()) have += (have.empty() ? "" : ", ") + b;
    if (backend == "osmesa" || backend == "egl")
        throw Error(ErrorKind::Usage, "off-screen backend '" + backend + "' is not built in (available: " +
                                          (have.empty() ? "none" : have) + ")");
    throw Error(ErrorKind::Usage, "unknown off-screen backend '" + backend + "' (available: " +
                                      (have.empty() ? "none" : have) + ")");
}

} // namespace spt::render
