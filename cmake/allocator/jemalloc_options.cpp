// Linked into spt's programs only (cmake/program_allocator.cmake). jemalloc replaces malloc and
// reads this string when it starts; MALLOC_CONF in the environment is read after it, so a user's
// settings still win. thp:always asks for transparent huge pages on every arena mapping, so that
// big arrays are not first touched a 4 KiB page at a time (about 10 us a fault on virtual
// machines that trap them).
extern "C" {
// jemalloc looks this symbol up in the program; its name is fixed by jemalloc.
extern const char* malloc_conf;
const char* malloc_conf = "thp:always,metadata_thp:auto";
}
