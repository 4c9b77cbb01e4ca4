#pragma once
// tests/data/anim/bending_bar.gltf seen from the front, for tests of selection and recipes at a
// pose: a bar along x from 0 to 2 whose tip half turns 90 degrees about z at x = 1; clip "step"
// holds the turn from t = 1 s to 2 s, so at t = 1 the tip stands up along +y, where nothing of
// the bar is at its bind pose.
#include "spt/split_recipe.hpp"
#include <string>

namespace spt::test {

/// A file of tests/data/anim.
inline std::string anim_data(const std::string& name) { return std::string(SPT_SOURCE_DIR) + "/tests/data/anim/" + name; }

/// Orthographic view down -Z: object x, y in [-1, 3] fill a 400x400 framebuffer, window x = (x + 1) * 100.
inline ViewProjection bar_front_view() {
    ViewProjection v;
    v.view(2, 3) = -10;
    v.view(0, 3) = v.view(1, 3) = -1;
    v.projection(0, 0) = v.projection(1, 1) = 0.5f;
    v.projection(2, 2) = -0.05f;
    v.width = v.height = 400;
    return v;
}

/// Object x in [x0, x1] (all y) in bar_front_view, pixels.
inline PixelRect bar_band(float x0, float x1) { return {(x0 + 1) * 100, 0, (x1 + 1) * 100, 400}; }

/// A stroke over everything above object y = 0.45: the standing tip at "step", 1 s; nothing at the bind pose.
inline RecipeStroke above_the_bar(SelectionMode mode = SelectionMode::Replace) {
    return {bar_front_view(), {0, 145, 400, 400}, mode, false};
}

} // namespace spt::test
