#pragma once
// Compact stored forms of sample data (.spt file): octahedral normals and bfloat16 lengths.
#include <Eigen/Core>
#include <cstdint>

namespace spt {

/// bfloat16 storage of a non-negative length: nearest, or rounded towards zero.
uint16_t encode_length(float v, bool round_down);
/// Inverse of encode_length.
float decode_length(uint16_t code);

/// Octahedral 2x16-bit encoding of a unit normal, as stored in .spt files.
uint32_t encode_normal(const Eigen::Vector3f& n);
/// Inverse of encode_normal; returns a unit vector.
Eigen::Vector3f decode_normal(uint32_t code);

} // namespace spt
