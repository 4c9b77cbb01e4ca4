// Linked into spt's programs only (cmake/program_allocator.cmake). mimalloc replaces malloc and
// operator new; it is asked for large OS pages so that a program's big arrays (an import's
// buffers, samples, trees, a renderer's images) are not first touched a 4 KiB page at a time:
// on virtual machines that trap page faults each costs up to 10 us (docs/benchmarks.md).
// MIMALLOC_LARGE_OS_PAGES in the environment still decides, as for any mimalloc program.
#include <mimalloc.h>
#include <cstdlib>

namespace {

void ask_mimalloc_for_large_os_pages() {
    if (std::getenv("MIMALLOC_LARGE_OS_PAGES")) return; // the user's choice wins
    mi_option_enable(mi_option_large_os_pages);
}

// The executable's pre-initialisers run before any shared library's constructors (the C++
// runtime's, Qt's, assimp's), which already allocate: set from an ordinary constructor, the
// option missed the segments those first allocations made, and a third more pages faulted.
__attribute__((section(".preinit_array"), used)) void (*const ask_first)() = ask_mimalloc_for_large_os_pages;

} // namespace
