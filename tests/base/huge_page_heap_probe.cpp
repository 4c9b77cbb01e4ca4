// Starts as every spt program does, then prints what it started again with: GLIBC_TUNABLES on
// the first line ("unset" if it is not), then its arguments one a line.
#include "spt/huge_page_heap.hpp"
#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
    spt::reexec_with_huge_page_heap(argv);
    const char* t = std::getenv("GLIBC_TUNABLES");
    std::printf("%s\n", t ? t : "unset");
    for (int i = 1; i < argc; ++i) std::printf("%s\n", argv[i]);
    return 0;
}
