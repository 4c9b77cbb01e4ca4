#pragma once
// How rectangle selection splits its work: the thread count for n items and the contiguous parts.
#include <algorithm>
#include <cstddef>
#include <thread>

namespace spt::detail {

// Threads for a selection pass over n items: one below 65536 items (threads cost more than
// they save), else the machine's hardware threads, at most 8.
inline int selection_threads(size_t n) {
    if (n < 65536) return 1;
    return int(std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
}

// Items [first, end) of part `part` of `parts` contiguous, nearly equal parts of n items.
struct Span {
    size_t first, end;
};
inline Span part_of(size_t n, size_t part, size_t parts) { return {n * part / parts, n * (part + 1) / parts}; }

} // namespace spt::detail
