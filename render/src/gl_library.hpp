#pragma once
// A GL implementation (libOSMesa, libEGL) opened when its backend is first asked for, not when
// the program starts: loading Mesa brings in LLVM, whose relocations cost tens of milliseconds a
// start on our machines, and most `spt` commands never draw.
#include <string>

namespace spt::render::detail {

/// A shared library opened once for the life of the program (never closed: Mesa keeps threads).
class GlLibrary {
public:
    /// Opens `soname`; throws Error(Usage) naming `backend`, the library and the loader's reason.
    GlLibrary(const char* backend, const char* soname);
    /// The function `name`; throws Error(Usage) if the library has none.
    void* symbol(const char* name) const;

    /// Casts symbol(name) to the function pointer type F.
    template <class F> F function(const char* name) const { return reinterpret_cast<F>(symbol(name)); }

private:
    std::string backend_, soname_;
    void* handle_ = nullptr;
};

} // namespace spt::render::detail
