#include "canvas.hpp"
#include "font.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <png.h>

namespace bench {

Canvas::Canvas(int w, int h, Rgb bg) : w_(w), h_(h), px_(size_t(w) * size_t(h) * 3) {
    for (size_t i = 0; i < px_.size(); i += 3) px_[i] = bg.r, px_[i + 1] = bg.g, px_[i + 2] = bg.b;
}

void Canvas::set(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
    uint8_t* p = &px_[(size_t(y) * size_t(w_) + size_t(x)) * 3];
    p[0] = c.r, p[1] = c.g, p[2] = c.b;
}

void Canvas::line(double x0, double y0, double x1, double y1, Rgb c, int thickness) {
    const double len = std::hypot(x1 - x0, y1 - y0);
    const int steps = std::max(1, int(std::ceil(len * 2)));
    const int lo = -(thickness - 1) / 2, hi = thickness / 2;
    for (int i = 0; i <= steps; ++i) {
        const double t = double(i) / steps;
        const int x = int(std::lround(x0 + t * (x1 - x0))), y = int(std::lround(y0 + t * (y1 - y0)));
        for (int dx = lo; dx <= hi; ++dx)
            for (int dy = lo; dy <= hi; ++dy) set(x + dx, y + dy, c);
    }
}

void Canvas::dashed(double x0, double y0, double x1, double y1, Rgb c, int dash, int gap) {
    const double len = std::hypot(x1 - x0, y1 - y0);
    for (double s = 0; s < len; s += dash + gap) {
        const double e = std::min(len, s + dash);
        line(x0 + (x1 - x0) * s / len, y0 + (y1 - y0) * s / len, x0 + (x1 - x0) * e / len, y0 + (y1 - y0) * e / len, c);
    }
}

void Canvas::fill_rect(int x0, int y0, int x1, int y1, Rgb c) {
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) set(x, y, c);
}

void Canvas::disc(double cx, double cy, double r, Rgb c) {
    for (int y = int(cy - r) - 1; y <= int(cy + r) + 1; ++y)
        for (int x = int(cx - r) - 1; x <= int(cx + r) + 1; ++x)
            if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) set(x, y, c);
}

void Canvas::square(double cx, double cy, double r, Rgb c) {
    fill_rect(int(std::lround(cx - r)), int(std::lround(cy - r)), int(std::lround(cx + r)), int(std::lround(cy + r)), c);
}

void Canvas::diamond(double cx, double cy, double r, Rgb c) {
    for (int y = int(cy - r) - 1; y <= int(cy + r) + 1; ++y)
        for (int x = int(cx - r) - 1; x <= int(cx + r) + 1; ++x)
            if (std::abs(x - cx) + std::abs(y - cy) <= r * 1.3) set(x, y, c);
}

void Canvas::triangle(double cx, double cy, double r, Rgb c) {
    for (int y = int(cy - r) - 1; y <= int(cy + r) + 1; ++y) {
        const double f = (y - (cy - r)) / (2 * r); // 0 at the apex, 1 at the base
        if (f < 0 || f > 1) continue;
        for (int x = int(cx - r) - 1; x <= int(cx + r) + 1; ++x)
            if (std::abs(x - cx) <= f * r * 1.15) set(x, y, c);
    }
}

int text_width(const std::string& s, int scale) { return int(s.size()) * 6 * scale; }

int Canvas::text(int x, int y, const std::string& s, Rgb c, int scale) {
    int cx = x;
    for (char ch : s) {
        const uint8_t* g = glyph(ch);
        for (int row = 0; row < 7; ++row)
            for (int col = 0; col < 5; ++col)
                if (g[row] & (0x10 >> col)) fill_rect(cx + col * scale, y + row * scale, cx + col * scale + scale - 1, y + row * scale + scale - 1, c);
        cx += 6 * scale;
    }
    return cx - x;
}

bool Canvas::save_png(const std::string& path) const {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
        return false;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(w_), png_uint_32(h_), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < h_; ++y) png_write_row(png, &px_[size_t(y) * size_t(w_) * 3]);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return std::fclose(f) == 0;
}

} // namespace bench
