#pragma once
// Built-in 5x7 bitmap font: 7 rows, bit 4 is the leftmost pixel. Lower case draws as upper case.
#include <cstdint>

namespace bench {

/// The glyph of `c` (a blank for characters the font lacks).
const uint8_t* glyph(char c);

} // namespace bench
