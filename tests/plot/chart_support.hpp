#pragma once
// Helpers for chart pixel tests: reading device pixels, small charts with fixed axes.
#include "spt/plot/chart.hpp"
#include <QImage>
#include <cmath>

namespace spt::plot::test {

/// The device pixel containing the logical point `p` of an image of device pixel ratio `dpr`.
inline QColor pixel_at(const QImage& image, QPointF p, double dpr) {
    return image.pixelColor(int(std::floor(p.x() * dpr)), int(std::floor(p.y() * dpr)));
}

/// True if two colours have the same red, green and blue.
inline bool same_rgb(const QColor& a, const QColor& b) { return a.rgb() == b.rgb(); }

/// A chart with a log10 x axis over [1, 10^4] and a linear y axis over [0, 100], no data.
inline Chart fixed_chart() {
    Chart c;
    c.title = "Fixed axes";
    c.x.scale = Scale::Log10, c.x.min = 1, c.x.max = 1e4, c.x.title = "time";
    c.y.min = 0, c.y.max = 100, c.y.step = 25, c.y.title = "percent";
    return c;
}

/// Where a point in data units of fixed_chart() lies, worked out from the plot rectangle alone.
inline QPointF expected_pixel(const QRectF& plot, double x, double y) {
    return {plot.left() + std::log10(x) / 4 * plot.width(), plot.bottom() - y / 100 * plot.height()};
}

} // namespace spt::plot::test
