#pragma once
// Programs built on spt allocate and first touch hundreds of megabytes (a mesh's import, its
// samples and trees, a renderer's buffers). The kernel fills fresh memory a 4 KiB page at a time,
// one fault a page; where a fault is dear (virtual machines that trap it: about 10 us a fault on
// our 2-core machines, docs/benchmarks.md) that alone can be half of a command's time. glibc's malloc asks for 2 MiB pages when GLIBC_TUNABLES holds
// glibc.malloc.hugetlb=1, but reads it only when a program starts: so the program starts again.

namespace spt {

/// Re-executes the running program (same pid, arguments, descriptors) with glibc's malloc asking
/// for transparent huge pages, and returns without doing so where that cannot help or was decided
/// already: GLIBC_TUNABLES names glibc.malloc.hugetlb, SPT_HUGE_PAGE_HEAP=0, the kernel's
/// transparent huge pages are off, the C library is not glibc 2.35 or later, malloc is replaced
/// (sanitizers, valgrind), or the exec fails. Call it first in main, before any output or thread.
void reexec_with_huge_page_heap(char** argv);

} // namespace spt
