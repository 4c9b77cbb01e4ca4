#pragma once
// Geometry measured in double, stored in float: each stored bound must still hold
// what it was measured to hold after rounding.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace spt::detail {

/// std::nextafter(f, +infinity), without a library call (refits round every bound of a tree up,
/// every pose): the next float's bits are one step further from zero for positive f, one nearer
/// for negative f.
inline float next_up(float f) {
    if (std::isnan(f) || f == std::numeric_limits<float>::infinity()) return f;
    if (f == 0) return std::numeric_limits<float>::denorm_min();
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    bits = f > 0 ? bits + 1 : bits - 1;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

/// Smallest float at least r grown by 1e-6 relative: a stored radius or half-width that holds r.
/// Never a denormal: 0 (a flat patch's thickness, exact in float) stays 0, and a positive r below
/// the least normal float is stored as that. A denormal extent, or one whose products with unit
/// vectors fall below it, costs each product an x86 microcode assist of about a hundred cycles:
/// the exact distance on FCL's axis-aligned env.obj spent over half its time there.
inline float round_up(double r) {
    if (r == 0) return 0;
    const float f = next_up(float(r * (1 + 1e-6)));
    return f > 0 && f < std::numeric_limits<float>::min() ? std::numeric_limits<float>::min() : f;
}

/// v rounded to float. Through a volatile, so that double(to_float(v)) is the value stored:
/// GCC 12 with Eigen 3.4 was seen folding x.cast<float>().cast<double>() into x at -O2,
/// which measured bounds around a point other than the stored one.
inline float to_float(double v) {
    volatile float f = float(v);
    return f;
}

/// x rounded to the nearest integer, halves away from zero (std::round's and std::lround's
/// value) for |x| < 2^30, without a library call: in double, x ± 0.5 is exact for every
/// float-valued x of that size, and truncation is then the rounding. NaN gives 0. The half
/// takes x's sign without a branch: the signs of normals' coordinates, rounded for every sphere
/// of a deformed pose, are a coin toss to a predictor.
inline int round_half_away(double x) {
    if (std::isnan(x)) return 0;
    return int(x + std::copysign(0.5, x));
}

/// x rounded to float per coordinate (see to_float), read back as double.
inline Eigen::Vector3d float_rounded(const Eigen::Vector3d& x) {
    return {double(to_float(x.x())), double(to_float(x.y())), double(to_float(x.z()))};
}

} // namespace spt::detail
