// The osmesa backend: Mesa's OSMesa with a core-profile context (removed in Mesa 25.1;
// the egl backend covers newer Mesa). Only OSMesa* functions are called here, through the library
// opened on the first context (SPT_OSMESA_SONAME, found when configuring).
#include "gl_library.hpp"
#include "offscreen_backends.hpp"
#include "spt/error.hpp"
#include <GL/osmesa.h>

namespace spt::render::detail {
namespace {

struct OsmesaApi {
    GlLibrary lib{"osmesa", SPT_OSMESA_SONAME};
    decltype(&OSMesaCreateContextAttribs) create = lib.function<decltype(create)>("OSMesaCreateContextAttribs");
    decltype(&OSMesaMakeCurrent) make_current = lib.function<decltype(make_current)>("OSMesaMakeCurrent");
    decltype(&OSMesaDestroyContext) destroy = lib.function<decltype(destroy)>("OSMesaDestroyContext");
    decltype(&OSMesaGetProcAddress) get_proc = lib.function<decltype(get_proc)>("OSMesaGetProcAddress");
};

// Loaded on the first context; if loading fails, that context is refused and the next call tries again.
const OsmesaApi& osmesa() {
    static const OsmesaApi api;
    return api;
}

class OsmesaContext final : public OffscreenContext {
public:
    OsmesaContext(int width, int height) : OffscreenContext(width, height) {
        pin_llvmpipe();
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0,
                               OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
        ctx_ = osmesa().create(attribs, nullptr);
        if (!ctx_) throw Error(ErrorKind::Usage, "osmesa: cannot create an OpenGL 3.3 core-profile context");
        // OSMesa needs a colour buffer to make a context current; drawing goes to the
        // framebuffer object, so one pixel is enough.
        if (!osmesa().make_current(ctx_, pixel_, GL_UNSIGNED_BYTE, 1, 1)) {
            osmesa().destroy(ctx_);
            throw Error(ErrorKind::Usage, "osmesa: cannot make the context current");
        }
        try {
            init_gl();
        } catch (...) {
            osmesa().destroy(ctx_);
            throw;
        }
    }
    ~OsmesaContext() override {
        make_current();
        release_gl();
        osmesa().destroy(ctx_);
    }
    const char* backend() const override { return "osmesa"; }
    ProcLoader loader() const override {
        return [](const char* name) { return reinterpret_cast<void*>(osmesa().get_proc(name)); };
    }
    void make_current() override { osmesa().make_current(ctx_, pixel_, GL_UNSIGNED_BYTE, 1, 1); }

private:
    OSMesaContext ctx_ = nullptr;
    unsigned char pixel_[4] = {};
};

} // namespace

std::unique_ptr<OffscreenContext> make_osmesa_context(int width, int height) {
    return std::make_unique<OsmesaContext>(width, height);
}

} // namespace spt::render::detail
