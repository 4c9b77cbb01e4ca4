#pragma once
// A chart described as data (axes, scatter series, step lines, titles, legend) and drawn with QPainter.
#include "spt/plot/axis.hpp"
#include <QColor>
#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QSize>
#include <QString>
#include <QStringList>
#include <vector>

class QPainter;

namespace spt::plot {

/// The shape drawn at each point of a series.
enum class Marker { Disc, Square, Diamond, Triangle };

/// Scatter points sharing one marker, colour and legend entry.
struct Series {
    QString name;                ///< legend entry; empty: not in the legend
    Marker marker = Marker::Disc; ///< shape at each point
    QColor colour = Qt::black;   ///< marker fill
    QColor outline;              ///< thin marker outline (separates overlapping markers); invalid: none
    double size = 8;             ///< marker width, logical pixels
    std::vector<QPointF> points; ///< data units; points that cannot be shown (NaN, inf, ≤ 0 on a log axis) are skipped
};

/// A staircase through points in increasing x (a Pareto front): from each point across to the next one's x,
/// then up or down to it.
struct StepLine {
    QString name;                ///< legend entry; empty: not in the legend
    QColor colour = Qt::red;     ///< line colour
    double width = 2;            ///< line width, logical pixels
    std::vector<QPointF> points; ///< data units, sorted by x; points that cannot be shown are skipped
    bool dashed_tail = false;    ///< continue the last level, dashed, to the right edge of the plot area
};

/// Colours and type of a chart.
struct ChartStyle {
    QColor background{255, 255, 255}; ///< whole image
    QColor text{25, 25, 25};          ///< titles, labels, legend
    QColor axis{60, 60, 60};          ///< axis lines and tick marks
    QColor grid{226, 226, 226};       ///< grid lines at the ticks
    QStringList families{QStringLiteral("DejaVu Sans"), QStringLiteral("Liberation Sans")}; ///< font, first found wins
    int font_px = 13;                 ///< labels and legend, logical pixels
    int title_px = 17;                ///< chart title, logical pixels (bold)
};

/// Everything a chart shows. Markers are drawn over step lines, in series order.
struct Chart {
    QString title;                ///< above the plot; empty: none
    Axis x;                       ///< horizontal axis
    Axis y;                       ///< vertical axis
    std::vector<Series> series;   ///< scatter series
    std::vector<StepLine> steps;  ///< step lines, drawn under the markers
    ChartStyle style;             ///< colours and type
};

/// One legend entry placed in the image.
struct LegendEntry {
    bool is_step = false; ///< a step line's entry (else a series')
    int index = 0;        ///< into Chart::steps or Chart::series
    QRectF box;           ///< swatch and text, logical pixels
};

/// Where a chart's parts sit in an image of a given logical size. Logical pixels, origin top left, y down.
struct ChartLayout {
    QSizeF size;                      ///< the whole image
    QRectF plot;                      ///< the plot area: data ranges map onto its edges
    Scale x_scale = Scale::Linear;    ///< copied from Chart::x
    Scale y_scale = Scale::Linear;    ///< copied from Chart::y
    Range x_range;                    ///< data range shown across the plot area
    Range y_range;                    ///< data range shown up the plot area
    std::vector<Tick> x_ticks;        ///< ticks and grid lines along x
    std::vector<Tick> y_ticks;        ///< ticks and grid lines along y
    std::vector<LegendEntry> legend;  ///< legend entries, in rows below the x axis title
    QRectF title_box;                 ///< the title's text (empty if none)

    /// Logical-pixel position of a point in data units; NaN coordinates if it cannot be shown on these axes.
    QPointF to_pixels(QPointF data) const;
    /// True if a point in data units can be shown and lies inside the data ranges.
    bool shows(QPointF data) const;
};

/// Why charts in `style` would be drawn without text (fontconfig finds no font at all), or empty if text can be
/// drawn. Needs a QGuiApplication. Qt itself silently draws no text, so programs check first.
QString font_problem(const ChartStyle& style = {});

/// Lays the chart out in an image of `size` logical pixels (needs a QGuiApplication: fonts are measured).
ChartLayout layout_chart(const Chart& chart, QSizeF size);

/// Paints the chart filling `size` logical pixels from the painter's origin (a widget, an image, a printer).
void paint_chart(QPainter& painter, const Chart& chart, QSizeF size);

/// Renders the chart into a new image of `size` logical pixels at `device_pixel_ratio` (2: twice as many pixels
/// each way, same layout); needs a QGuiApplication (see headless_gui.hpp). The same input gives the same pixels.
/// A null image if a side would exceed 16384 device pixels or memory runs out.
QImage render_chart(const Chart& chart, QSize size, double device_pixel_ratio = 1);

/// Renders the chart and writes it as a PNG file; false with `error` (if given) saying why when it cannot be written.
bool save_chart_png(const Chart& chart, const QString& path, QSize size, double device_pixel_ratio = 1,
                    QString* error = nullptr);

} // namespace spt::plot
