#pragma once
// The three fonts of a chart and the spacing derived from them, shared by layout and painting.
#include "spt/plot/chart.hpp"
#include <QFont>
#include <QFontMetricsF>

namespace spt::plot::detail {

/// The chart's fonts (pixel-sized, so the same on every screen) and the gaps that follow from them, logical pixels.
struct ChartFonts {
    explicit ChartFonts(const ChartStyle& style);
    QFont label, title, axis_title;
    QFontMetricsF label_m, title_m, axis_title_m;
    double pad;      ///< margin around the whole chart
    double tick;     ///< tick mark length, outside the plot area
    double gap;      ///< between a tick mark and its label
    double swatch;   ///< a legend marker's box
    double line_swatch; ///< a legend step line's length
    double swatch_gap;  ///< between a legend swatch and its text
    double entry_gap;   ///< between legend entries in a row
};

/// layout_chart with the fonts already made.
ChartLayout layout_chart(const Chart& chart, QSizeF size, const ChartFonts& fonts);

} // namespace spt::plot::detail
