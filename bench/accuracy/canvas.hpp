#pragma once
// A tiny RGB raster for the benchmark's plot: lines, markers, bitmap text, PNG out.
#include <cstdint>
#include <string>
#include <vector>

namespace bench {

struct Rgb {
    uint8_t r, g, b;
};

class Canvas {
public:
    Canvas(int w, int h, Rgb background);
    int width() const { return w_; }
    int height() const { return h_; }
    void set(int x, int y, Rgb c);
    /// Line of the given thickness (pixels) between two points.
    void line(double x0, double y0, double x1, double y1, Rgb c, int thickness = 1);
    /// Dashed line (dash and gap in pixels).
    void dashed(double x0, double y0, double x1, double y1, Rgb c, int dash = 4, int gap = 4);
    void fill_rect(int x0, int y0, int x1, int y1, Rgb c);
    void disc(double x, double y, double r, Rgb c);
    void square(double x, double y, double r, Rgb c);
    void diamond(double x, double y, double r, Rgb c);
    void triangle(double x, double y, double r, Rgb c);
    /// Text in the built-in 5x7 font, `scale` pixels a font pixel; returns the width drawn.
    int text(int x, int y, const std::string& s, Rgb c, int scale = 2);
    /// Writes an 8-bit RGB PNG; false on failure.
    bool save_png(const std::string& path) const;

private:
    int w_, h_;
    std::vector<uint8_t> px_;
};

/// Width in pixels of `s` drawn at `scale`.
int text_width(const std::string& s, int scale = 2);

} // namespace bench
