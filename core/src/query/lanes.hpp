#pragma once
// Four-lane float vectors of the query walk and the one way B's points are moved into A's frame.
#include "query/query_run.hpp"
#include <cstdint>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace spt::detail {

typedef float v4f __attribute__((vector_size(16)));
typedef int32_t v4i __attribute__((vector_size(16)));

inline v4f splat(float x) { return v4f{x, x, x, x}; }

// Bit k set when lane k is true.
inline int movemask(v4i m) {
#if defined(__SSE__)
    return _mm_movemask_ps(__m128(m));
#else
    int bits = 0;
    for (int k = 0; k < 4; ++k) bits |= (m[k] & 1) << k;
    return bits;
#endif
}

// Four points of B's frame into A's, in place; the one expression every move of B
// uses, so leaf spheres and node centres round alike (no fused multiply-add).
inline void b_to_a(const QueryFrame& f, v4f& x, v4f& y, v4f& z) {
    const Eigen::Matrix3f& R = f.R;
    const v4f bx = x, by = y, bz = z;
    x = splat(R(0, 0)) * bx + splat(R(0, 1)) * by + splat(R(0, 2)) * bz + splat(f.t.x());
    y = splat(R(1, 0)) * bx + splat(R(1, 1)) * by + splat(R(1, 2)) * bz + splat(f.t.y());
    z = splat(R(2, 0)) * bx + splat(R(2, 1)) * by + splat(R(2, 2)) * bz + splat(f.t.z());
}

} // namespace spt::detail
