#pragma once
// FNV-1a 64: stable across platforms, good enough to tell meshes apart.
#include <cstddef>
#include <cstdint>

namespace spt::detail {

inline uint64_t fnv1a(const void* data, size_t size, uint64_t h = 0xcbf29ce484222325ull) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

} // namespace spt::detail
