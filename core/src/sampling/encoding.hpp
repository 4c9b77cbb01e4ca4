#pragma once
// Compact stored forms of sample data (.spt file): octahedral normals and bfloat16 lengths.
#include <Eigen/Core>
#include <cstdint>

namespace spt {

/// bfloat16 storage of a non-negative length: nearest, or rounded towards zero.
uint16_t encode_length(float v, bool round_down);
/// Inverse of encode_length.
float decode_length(uint16_t code);
/// Length v as a .spt file stores it (encoded and decoded): a sample's spacing is rounded to
/// nearest, its max_radius towards zero, so a stored cap never exceeds the limiter's.
inline float snap_length(float v, bool round_down) { return decode_length(encode_length(v, round_down)); }

/// Octahedral 2x16-bit encoding of a unit normal, as stored in .spt files.
uint32_t encode_normal(const Eigen::Vector3f& n);
/// Inverse of encode_normal; returns a unit vector.
Eigen::Vector3f decode_normal(uint32_t code);
/// Unit normal n as a .spt file stores it (encoded and decoded): every sample's normal is
/// snapped so, so that a posed model, the radius limiter and a loaded file see the same one.
inline Eigen::Vector3f snap_normal(const Eigen::Vector3f& n) { return decode_normal(encode_normal(n)); }

} // namespace spt
