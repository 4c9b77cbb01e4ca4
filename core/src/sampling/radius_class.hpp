#pragma once
// Radius classes: samples whose own radii lie within a fixed ratio share an active node.
#include <cmath>

namespace spt {

/// Auto-built active nodes hold samples whose own radii (RadiusRule::for_sample) lie within
/// this ratio, so a node's radius is never below 1/ratio of any member's own radius.
constexpr float kRadiusClassRatio = 1.5f;

/// Radius class of a sample radius: samples of one class are within kRadiusClassRatio.
inline int radius_class(float r) {
    return r > 0 ? int(std::floor(std::log(r) / std::log(kRadiusClassRatio))) : -1000000;
}

} // namespace spt
