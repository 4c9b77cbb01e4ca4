// Loading the GL function table through a ProcLoader, and the GL error check.
#include "gl_functions.hpp"
#include <cstdio>
#include <stdexcept>
#include <string>

namespace spt::render::detail {

void GlFunctions::load(const ProcLoader& loader) {
    if (!loader) throw std::runtime_error("OpenGL: no loader function given");
#define SPT_GL_LOAD(type, name)                                                              \
    name = reinterpret_cast<type>(loader("gl" #name));                                        \
    if (!name) throw std::runtime_error("OpenGL: the context does not provide gl" #name);
    SPT_GL_FUNCTIONS(SPT_GL_LOAD)
#undef SPT_GL_LOAD
}

void check_gl(const GlFunctions& gl, const char* what) {
    const GLenum e = gl.GetError();
    if (e == GL_NO_ERROR) return;
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", unsigned(e));
    // Out of memory is the one a user can act on (a smaller image): say so in words.
    const char* name = e == GL_OUT_OF_MEMORY ? " (out of memory)" : "";
    throw std::runtime_error(std::string(what) + ": GL error " + code + name);
}

} // namespace spt::render::detail
