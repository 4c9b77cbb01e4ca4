// Preloaded into a program by program_start_test: appends a line to $SPT_START_LOG each time a
// process image loads it, so the log counts how many times the program started (an exec of
// itself is a second start, with the same pid).
#include <cstdio>
#include <cstdlib>

__attribute__((constructor)) static void count_start() {
    const char* path = std::getenv("SPT_START_LOG");
    if (!path) return;
    if (std::FILE* f = std::fopen(path, "a")) {
        std::fputs("start\n", f);
        std::fclose(f);
    }
}
