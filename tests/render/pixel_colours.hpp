#pragma once
// How much of a colour a picture shows: overlays drawn in a colour of their own (manifold
// points) are found in a render or a grabbed frame by counting its pixels.
#include "spt/render/frame.hpp"
#include "spt/render/image.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace spt::test {

/// Pixels of `image` within `tolerance` (0..1) of `color` in each of red, green and blue.
inline size_t pixels_of_color(const render::Image& image, const render::Color& color, float tolerance = 2.0f / 255.0f) {
    size_t n = 0;
    for (size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
        const float d = std::max({std::abs(image.rgba[i] / 255.0f - color.r), std::abs(image.rgba[i + 1] / 255.0f - color.g),
                                  std::abs(image.rgba[i + 2] / 255.0f - color.b)});
        n += d <= tolerance;
    }
    return n;
}

} // namespace spt::test
