// The egl backend: EGL on Mesa's surfaceless platform (no display, no window system),
// a desktop OpenGL 3.3 core-profile context. Only egl* functions are called here, through the
// library opened on the first context (SPT_EGL_SONAME, found when configuring).
#include "gl_library.hpp"
#include "offscreen_backends.hpp"
#include "spt/error.hpp"
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>

namespace spt::render::detail {
namespace {

struct EglApi {
    GlLibrary lib{"egl", SPT_EGL_SONAME};
    decltype(&eglQueryString) query_string = lib.function<decltype(query_string)>("eglQueryString");
    decltype(&eglGetProcAddress) get_proc_address = lib.function<decltype(get_proc_address)>("eglGetProcAddress");
    decltype(&eglInitialize) initialize = lib.function<decltype(initialize)>("eglInitialize");
    decltype(&eglGetError) get_error = lib.function<decltype(get_error)>("eglGetError");
    decltype(&eglBindAPI) bind_api = lib.function<decltype(bind_api)>("eglBindAPI");
    decltype(&eglChooseConfig) choose_config = lib.function<decltype(choose_config)>("eglChooseConfig");
    decltype(&eglCreateContext) create_context = lib.function<decltype(create_context)>("eglCreateContext");
    decltype(&eglMakeCurrent) make_current = lib.function<decltype(make_current)>("eglMakeCurrent");
    decltype(&eglDestroyContext) destroy_context = lib.function<decltype(destroy_context)>("eglDestroyContext");
    decltype(&eglTerminate) terminate = lib.function<decltype(terminate)>("eglTerminate");
};

// Loaded on the first context; if loading fails, that context is refused and the next call tries again.
const EglApi& egl() {
    static const EglApi api;
    return api;
}

// EGL hands out one EGLDisplay per platform; terminate it only when the last of our
// contexts is gone.
std::mutex g_display_mutex;
int g_display_users = 0;

std::string egl_error(const char* what) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", unsigned(egl().get_error()));
    return std::string("egl: ") + what + " (EGL error " + code + ")";
}

class EglContext final : public OffscreenContext {
public:
    EglContext(int width, int height) : OffscreenContext(width, height) {
        pin_llvmpipe();
        const char* client_ext = egl().query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (!client_ext || !std::strstr(client_ext, "EGL_MESA_platform_surfaceless"))
            throw Error(ErrorKind::Usage, "egl: the EGL library has no surfaceless platform (EGL_MESA_platform_surfaceless)");
        auto get_display =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(egl().get_proc_address("eglGetPlatformDisplayEXT"));
        if (!get_display) throw Error(ErrorKind::Usage, "egl: eglGetPlatformDisplayEXT is missing");
        {
            std::lock_guard<std::mutex> lock(g_display_mutex);
            display_ = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
            if (display_ == EGL_NO_DISPLAY) throw Error(ErrorKind::Usage, egl_error("no surfaceless display"));
            EGLint major = 0, minor = 0;
            if (!egl().initialize(display_, &major, &minor))
                throw Error(ErrorKind::Usage, egl_error("cannot initialise the surfaceless display"));
            ++g_display_users;
        }
        try {
            create();
            init_gl();
        } catch (...) {
            destroy();
            throw;
        }
    }
    ~EglContext() override {
        make_current();
        release_gl();
        destroy();
    }
    const char* backend() const override { return "egl"; }
    ProcLoader loader() const override {
        return [](const char* name) { return reinterpret_cast<void*>(egl().get_proc_address(name)); };
    }
    void make_current() override { egl().make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_); }

private:
    void create() {
        const char* ext = egl().query_string(display_, EGL_EXTENSIONS);
        if (!ext || !std::strstr(ext, "EGL_KHR_surfaceless_context"))
            throw Error(ErrorKind::Usage, "egl: the display cannot make a context current without a surface");
        if (!egl().bind_api(EGL_OPENGL_API)) throw Error(ErrorKind::Usage, egl_error("desktop OpenGL is not supported"));
        const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8,
                                         EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (!egl().choose_config(display_, config_attribs, &config, 1, &count) || count < 1) {
            // Drivers that expose no configs on surfaceless still accept a config-less context.
            if (!std::strstr(ext, "EGL_KHR_no_config_context"))
                throw Error(ErrorKind::Usage, egl_error("no RGBA8 OpenGL config"));
            config = EGL_NO_CONFIG_KHR;
        }
        const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                          EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                          EGL_NONE};
        context_ = egl().create_context(display_, config, EGL_NO_CONTEXT, context_attribs);
        if (context_ == EGL_NO_CONTEXT)
            throw Error(ErrorKind::Usage, egl_error("cannot create an OpenGL 3.3 core-profile context"));
        if (!egl().make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw Error(ErrorKind::Usage, egl_error("cannot make the context current"));
    }

    void destroy() {
        if (display_ == EGL_NO_DISPLAY) return;
        egl().make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_ != EGL_NO_CONTEXT) egl().destroy_context(display_, context_);
        context_ = EGL_NO_CONTEXT;
        std::lock_guard<std::mutex> lock(g_display_mutex);
        if (--g_display_users == 0) egl().terminate(display_);
        display_ = EGL_NO_DISPLAY;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

} // namespace

std::unique_ptr<OffscreenContext> make_egl_context(int width, int height) {
    return std::make_unique<EglContext>(width, height);
}

} // namespace spt::render::detail
