#pragma once
// Radius classes: samples whose own radii lie within a fixed ratio share an active node.
#include <cmath>
#include <cstdint>
#include <cstring>

namespace spt {

/// Auto-built active nodes hold samples whose own radii (RadiusRule::for_sample) lie within
/// this ratio, so a node's radius is never below 1/ratio of any member's own radius.
constexpr float kRadiusClassRatio = 1.5f;

/// Radius class of a sample radius: samples of one class are within kRadiusClassRatio.
inline int radius_class(float r) {
    return r > 0 ? int(std::floor(std::log(r) / std::log(kRadiusClassRatio))) : -1000000;
}

/// Radius class of a two-sided sample's own radius (an open part's): one class for each
/// bfloat16 value, apart from every one-sided class. Two-sided radii come from a short ladder
/// (RadiusLimiter::limit), so an active node of them takes its members' own radius, not
/// 1/kRadiusClassRatio of it, and faces are sampled for that radius.
inline int two_sided_radius_class(float r) {
    uint32_t bits;
    std::memcpy(&bits, &r, 4);
    return r > 0 ? (1 << 20) + int(bits >> 16) : -1000001;
}

} // namespace spt
