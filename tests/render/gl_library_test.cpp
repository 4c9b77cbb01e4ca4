// The GL implementations are opened by name when a backend is first asked for; a missing one or
// a missing function is a message naming the backend and the library, never a crash.
#include "gl_library.hpp"
#include "spt/error.hpp"
#include <gtest/gtest.h>

using spt::render::detail::GlLibrary;

TEST(GlLibrary, MissingLibraryIsRefusedNamingBackendAndLibrary) {
    try {
        GlLibrary lib("osmesa", "libspt-no-such-gl.so.9");
        FAIL() << "opened a library that does not exist";
    } catch (const spt::Error& e) {
        EXPECT_EQ(e.kind(), spt::ErrorKind::Usage);
        const std::string m = e.what();
        EXPECT_NE(m.find("osmesa: cannot load libspt-no-such-gl.so.9"), std::string::npos) << m;
    }
}

TEST(GlLibrary, MissingFunctionIsRefusedNamingIt) {
    const GlLibrary libc("test", "libc.so.6"); // always there; has no GL
    EXPECT_NE(libc.symbol("malloc"), nullptr);
    try {
        libc.symbol("OSMesaCreateContextAttribs");
        FAIL() << "found a GL entry point in the C library";
    } catch (const spt::Error& e) {
        EXPECT_EQ(std::string(e.what()), "test: libc.so.6 has no OSMesaCreateContextAttribs");
    }
}
