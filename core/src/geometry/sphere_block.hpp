#pragma once
/// The hot loop of a query: squared distances between a block of A's sphere
/// centres and a block of B's, 8 lanes at a time (AVX2 when the CPU has it,
/// chosen at run time; SSE2 otherwise).
#include <cstdint>

namespace spt {

/// Writes |a_i - b_j|^2 to out[i * stride + j] for i < na, j < nb, with stride = nb
/// rounded up to 8 (lanes j >= nb get +inf), and returns the smallest value.
/// b columns must be readable up to stride; out must hold na * stride floats.
float sphere_block_d2(const float* ax, const float* ay, const float* az, uint32_t na, const float* bx,
                      const float* by, const float* bz, uint32_t nb, float* out);

/// Row stride that sphere_block_d2 uses for nb spheres of B.
constexpr uint32_t sphere_block_stride(uint32_t nb) { return (nb + 7u) & ~7u; }

/// Name of the kernel variant the running CPU uses ("avx2" or "default").
const char* sphere_block_variant();

} // namespace spt
