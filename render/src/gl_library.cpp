#include "gl_library.hpp"
#include "spt/error.hpp"
#include <dlfcn.h>

namespace spt::render::detail {

GlLibrary::GlLibrary(const char* backend, const char* soname) : backend_(backend), soname_(soname) {
    handle_ = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
    if (!handle_) {
        const char* why = dlerror();
        throw Error(ErrorKind::Usage, backend_ + ": cannot load " + soname_ + " (" + (why ? why : "unknown reason") + ")");
    }
}

void* GlLibrary::symbol(const char* name) const {
    dlerror();
    void* f = dlsym(handle_, name);
    if (!f) throw Error(ErrorKind::Usage, backend_ + ": " + soname_ + " has no " + name);
    return f;
}

} // namespace spt::render::detail
