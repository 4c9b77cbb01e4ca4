// Written with GCC vector extensions so one source serves both clones: the
// default clone splits each 8-lane operation into two SSE2 halves, the avx2
// clone uses one ymm register. The project stays portable (no -march flag).
#include "geometry/sphere_block.hpp"
#include <cstring>
#include <limits>

namespace spt {
namespace {

typedef float v8f __attribute__((vector_size(32)));
typedef int32_t v8i __attribute__((vector_size(32)));

} // namespace

// Not under ThreadSanitizer: a clone's ifunc resolver runs while the program is relocated,
// before TSan is set up, and crashes there.
#if !defined(__SANITIZE_THREAD__)
__attribute__((target_clones("avx2", "default")))
#endif
float sphere_block_d2(const float* ax, const float* ay, const float* az, uint32_t na, const float* bx,
                      const float* by, const float* bz, uint32_t nb, float* out) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    const uint32_t stride = sphere_block_stride(nb);
    const v8i lane = {0, 1, 2, 3, 4, 5, 6, 7};
    const v8f inf = {kInf, kInf, kInf, kInf, kInf, kInf, kInf, kInf};
    v8f best = inf;
    for (uint32_t i = 0; i < na; ++i) {
        const v8f x = {ax[i], ax[i], ax[i], ax[i], ax[i], ax[i], ax[i], ax[i]};
        const v8f y = {ay[i], ay[i], ay[i], ay[i], ay[i], ay[i], ay[i], ay[i]};
        const v8f z = {az[i], az[i], az[i], az[i], az[i], az[i], az[i], az[i]};
        float* row = out + size_t(i) * stride;
        for (uint32_t j = 0; j < stride; j += 8) {
            v8f lx, ly, lz; // unaligned loads
            std::memcpy(&lx, bx + j, sizeof lx), std::memcpy(&ly, by + j, sizeof ly), std::memcpy(&lz, bz + j, sizeof lz);
            const v8f dx = lx - x, dy = ly - y, dz = lz - z;
            v8f d2 = dx * dx + dy * dy + dz * dz;
            const int32_t left = int32_t(nb - j);
            const v8i valid = lane < left;
            d2 = valid ? d2 : inf;
            std::memcpy(row + j, &d2, sizeof d2);
            best = d2 < best ? d2 : best;
        }
    }
    float m = best[0];
    for (int k = 1; k < 8; ++k) m = best[k] < m ? best[k] : m;
    return m;
}

const char* sphere_block_variant() { return __builtin_cpu_supports("avx2") ? "avx2" : "default"; }

} // namespace spt
