// Chart layout: axis ranges and ticks from the data, margins from the measured text, legend rows.
#include "chart_fonts.hpp"
#include <algorithm>
#include <cmath>

namespace spt::plot {
namespace detail {
namespace {

QFont make_font(const ChartStyle& style, int px, bool bold) {
    QFont f;
    f.setFamilies(style.families);
    f.setStyleHint(QFont::SansSerif);
    f.setPixelSize(std::max(1, px));
    f.setBold(bold);
    // Grey-level antialiasing only: sub-pixel colour fringes depend on the screen the image is later shown on.
    f.setStyleStrategy(QFont::StyleStrategy(QFont::PreferAntialias | QFont::NoSubpixelAntialias));
    return f;
}

} // namespace

ChartFonts::ChartFonts(const ChartStyle& style)
    : label(make_font(style, style.font_px, false)), title(make_font(style, style.title_px, true)),
      axis_title(make_font(style, style.font_px + 1, false)), label_m(label), title_m(title), axis_title_m(axis_title) {
    const double em = label_m.height();
    pad = std::round(0.8 * em), tick = 5, gap = 3, swatch = 14, line_swatch = 26, swatch_gap = 6;
    entry_gap = std::round(1.4 * em);
}

} // namespace detail

namespace {

struct Extent {
    double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
    void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
};

double widest(const std::vector<Tick>& ticks, const QFontMetricsF& m) {
    double w = 0;
    for (const Tick& t : ticks) w = std::max(w, m.horizontalAdvance(t.label));
    return w;
}

} // namespace

QPointF ChartLayout::to_pixels(QPointF data) const {
    const double fx = axis_fraction(x_scale, x_range, data.x()), fy = axis_fraction(y_scale, y_range, data.y());
    return {plot.left() + fx * plot.width(), plot.bottom() - fy * plot.height()};
}

bool ChartLayout::shows(QPointF data) const {
    const double fx = axis_fraction(x_scale, x_range, data.x()), fy = axis_fraction(y_scale, y_range, data.y());
    constexpr double e = 1e-9;
    return fx >= -e && fx <= 1 + e && fy >= -e && fy <= 1 + e; // false for NaN
}

ChartLayout layout_chart(const Chart& chart, QSizeF size) { return detail::layout_chart(chart, size, detail::ChartFonts(chart.style)); }

ChartLayout detail::layout_chart(const Chart& chart, QSizeF size, const ChartFonts& f) {
    ChartLayout L;
    L.size = size;
    L.x_scale = chart.x.scale, L.y_scale = chart.y.scale;
    // Ranges from every point that can be shown on both axes.
    Extent ex, ey;
    auto add = [&](QPointF p) {
        if (plottable(L.x_scale, p.x()) && plottable(L.y_scale, p.y())) ex.add(p.x()), ey.add(p.y());
    };
    for (const Series& s : chart.series)
        for (QPointF p : s.points) add(p);
    for (const StepLine& s : chart.steps)
        for (QPointF p : s.points) add(p);
    L.x_range = resolve_range(chart.x, ex.lo, ex.hi);
    L.y_range = resolve_range(chart.y, ey.lo, ey.hi);
    L.x_ticks = axis_ticks(chart.x, L.x_range);
    L.y_ticks = axis_ticks(chart.y, L.y_range);

    const double W = size.width(), H = size.height();
    const double line = f.label_m.height(), axis_line = f.axis_title_m.height();
    // Legend rows, centred; measured first because their number sets the bottom margin.
    std::vector<LegendEntry> entries;
    auto entry = [&](bool is_step, size_t i, const QString& name) {
        const double swatch = (is_step ? f.line_swatch : f.swatch) + f.swatch_gap;
        const double text = std::min(f.label_m.horizontalAdvance(name), std::max(0.0, W - 2 * f.pad - swatch)); // long: elided
        entries.push_back({is_step, int(i), QRectF(0, 0, swatch + text, line)});
    };
    for (size_t i = 0; i < chart.series.size(); ++i)
        if (!chart.series[i].name.isEmpty()) entry(false, i, chart.series[i].name);
    for (size_t i = 0; i < chart.steps.size(); ++i)
        if (!chart.steps[i].name.isEmpty()) entry(true, i, chart.steps[i].name);
    std::vector<std::vector<LegendEntry>> rows;
    double row_w = 0;
    for (const LegendEntry& e : entries) {
        const double w = e.box.width();
        if (rows.empty() || row_w + f.entry_gap + w > W - 2 * f.pad) rows.emplace_back(), row_w = -f.entry_gap;
        rows.back().push_back(e);
        row_w += f.entry_gap + w;
    }
    const double row_h = std::round(line * 1.35);
    const double legend_gap = std::round(0.9 * line); // sets the legend apart from the x axis title
    const double legend_h = rows.empty() ? 0 : double(rows.size()) * row_h + legend_gap;

    // Margins around the plot area.
    double top = f.pad;
    if (!chart.title.isEmpty()) {
        const double h = f.title_m.height();
        L.title_box = QRectF(f.pad, top, std::max(0.0, W - 2 * f.pad), h);
        top += h + std::round(0.6 * line);
    }
    top += std::ceil(line / 2); // the top y label is centred on the plot's top edge
    double left = f.pad + widest(L.y_ticks, f.label_m) + f.gap + f.tick;
    if (!chart.y.title.isEmpty()) left += axis_line + std::round(0.4 * line);
    double right = f.pad;
    if (!L.x_ticks.empty()) {
        left = std::max(left, f.pad + f.label_m.horizontalAdvance(L.x_ticks.front().label) / 2);
        right = std::max(right, f.label_m.horizontalAdvance(L.x_ticks.back().label) / 2 + f.gap);
    }
    double bottom = f.pad + legend_h + f.tick + f.gap + line;
    if (!chart.x.title.isEmpty()) bottom += std::round(0.35 * line) + axis_line;
    L.plot = QRectF(std::round(left), std::round(top), std::max(1.0, std::round(W - left - right)),
                    std::max(1.0, std::round(H - top - bottom)));

    double y = H - f.pad - legend_h + legend_gap;
    for (auto& row : rows) {
        double w = -f.entry_gap;
        for (const auto& e : row) w += f.entry_gap + e.box.width();
        double x = std::round((W - w) / 2);
        for (auto& e : row) {
            e.box.moveTopLeft(QPointF(x, y));
            x += e.box.width() + f.entry_gap;
            L.legend.push_back(e);
        }
        y += row_h;
    }
    return L;
}

} // namespace spt::plot
