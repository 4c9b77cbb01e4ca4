// Paints a laid-out chart with QPainter: grid, step lines, markers, axes, labels, legend; image and PNG output.
#include "chart_fonts.hpp"
#include <QFontInfo>
#include <QImageWriter>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <QSaveFile>
#include <cmath>

namespace spt::plot {
namespace {

constexpr double kMaxSide = 16384; // device pixels a side, as in render_chart's documentation

// A line of `width` logical pixels at `v` lands on whole device pixels (no grey half-pixel smear).
double crisp(double v, double width, double dpr) {
    const double d = v * dpr;
    const long w = std::lround(width * dpr);
    return (w % 2 ? std::floor(d) + 0.5 : std::round(d)) / dpr;
}

// A box at `top`, `height` tall, for text `width` wide: centred over the plot area when it fits there, else over
// the whole image.
QRectF centred_over_plot(const ChartLayout& L, const detail::ChartFonts& f, double top, double height, double width) {
    if (width <= L.plot.width()) return QRectF(L.plot.left(), top, L.plot.width(), height);
    return QRectF(f.pad, top, L.size.width() - 2 * f.pad, height);
}

void draw_marker(QPainter& p, Marker m, QPointF c, double size, const QColor& fill, const QColor& outline) {
    p.setPen(outline.isValid() ? QPen(outline, 1) : QPen(Qt::NoPen));
    p.setBrush(fill);
    const double r = size / 2;
    switch (m) {
    case Marker::Disc: p.drawEllipse(c, r, r); break;
    case Marker::Square: p.drawRect(QRectF(c.x() - 0.9 * r, c.y() - 0.9 * r, 1.8 * r, 1.8 * r)); break;
    case Marker::Diamond: {
        const double h = 1.25 * r;
        p.drawPolygon(QPolygonF({{c.x(), c.y() - h}, {c.x() + h, c.y()}, {c.x(), c.y() + h}, {c.x() - h, c.y()}}));
        break;
    }
    case Marker::Triangle: { // centroid on the point
        const double R = 1.25 * r, s = R * std::sqrt(3.0) / 2;
        p.drawPolygon(QPolygonF({{c.x(), c.y() - R}, {c.x() + s, c.y() + R / 2}, {c.x() - s, c.y() + R / 2}}));
        break;
    }
    }
}

void draw_steps(QPainter& p, const ChartLayout& L, const StepLine& s) {
    QPainterPath path;
    bool started = false;
    QPointF last;
    for (QPointF d : s.points) {
        const QPointF q = L.to_pixels(d);
        if (!std::isfinite(q.x()) || !std::isfinite(q.y())) continue;
        if (!started) path.moveTo(q), started = true;
        else path.lineTo(q.x(), last.y()), path.lineTo(q);
        last = q;
    }
    if (!started) return;
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(s.colour, s.width, Qt::SolidLine, Qt::FlatCap, Qt::MiterJoin));
    p.drawPath(path);
    if (s.dashed_tail && last.x() < L.plot.right()) {
        p.setPen(QPen(s.colour, std::max(1.0, 0.75 * s.width), Qt::DashLine, Qt::FlatCap));
        p.drawLine(last, QPointF(L.plot.right(), last.y()));
    }
}

void draw_legend(QPainter& p, const Chart& chart, const ChartLayout& L, const detail::ChartFonts& f) {
    p.setFont(f.label);
    for (const LegendEntry& e : L.legend) {
        const double cy = e.box.center().y();
        double text_x;
        QString name;
        if (e.is_step) {
            const StepLine& s = chart.steps[size_t(e.index)];
            p.setPen(QPen(s.colour, s.width, Qt::SolidLine, Qt::FlatCap));
            p.drawLine(QPointF(e.box.left(), cy), QPointF(e.box.left() + f.line_swatch, cy));
            text_x = e.box.left() + f.line_swatch + f.swatch_gap, name = s.name;
        } else {
            const Series& s = chart.series[size_t(e.index)];
            draw_marker(p, s.marker, QPointF(e.box.left() + f.swatch / 2, cy), std::min(s.size, f.swatch - 2), s.colour,
                        s.outline);
            text_x = e.box.left() + f.swatch + f.swatch_gap, name = s.name;
        }
        p.setPen(chart.style.text);
        const double room = e.box.right() - text_x;
        p.drawText(QRectF(text_x, e.box.top(), room + 1, e.box.height()), Qt::AlignLeft | Qt::AlignVCenter,
                   f.label_m.elidedText(name, Qt::ElideRight, room + 0.5));
    }
}

void draw_axes(QPainter& p, const Chart& chart, const ChartLayout& L, const detail::ChartFonts& f, double dpr) {
    const QRectF& a = L.plot;
    const double line = f.label_m.height();
    p.setPen(QPen(chart.style.axis, 1, Qt::SolidLine, Qt::FlatCap));
    const double x0 = crisp(a.left(), 1, dpr), y0 = crisp(a.bottom(), 1, dpr);
    p.drawLine(QPointF(x0, a.top()), QPointF(x0, a.bottom() + f.tick));
    p.drawLine(QPointF(a.left() - f.tick, y0), QPointF(a.right(), y0));
    p.setFont(f.label);
    for (const Tick& t : L.x_ticks) {
        const double x = crisp(L.to_pixels({t.value, L.y_range.lo}).x(), 1, dpr);
        p.setPen(chart.style.axis);
        p.drawLine(QPointF(x, a.bottom()), QPointF(x, a.bottom() + f.tick));
        const double w = f.label_m.horizontalAdvance(t.label) + 2;
        p.setPen(chart.style.text);
        p.drawText(QRectF(x - w / 2, a.bottom() + f.tick + f.gap, w, line), Qt::AlignHCenter | Qt::AlignTop, t.label);
    }
    for (const Tick& t : L.y_ticks) {
        const double y = crisp(L.to_pixels({L.x_range.lo, t.value}).y(), 1, dpr);
        p.setPen(chart.style.axis);
        p.drawLine(QPointF(a.left() - f.tick, y), QPointF(a.left(), y));
        p.setPen(chart.style.text);
        p.drawText(QRectF(0, y - line / 2, a.left() - f.tick - f.gap, line), Qt::AlignRight | Qt::AlignVCenter, t.label);
    }
    p.setPen(chart.style.text);
    p.setFont(f.axis_title);
    const double at = f.axis_title_m.height();
    if (!chart.x.title.isEmpty()) {
        const QString t = f.axis_title_m.elidedText(chart.x.title, Qt::ElideRight, L.size.width() - 2 * f.pad);
        p.drawText(centred_over_plot(L, f, a.bottom() + f.tick + f.gap + line + std::round(0.35 * line), at,
                                     f.axis_title_m.horizontalAdvance(t)),
                   Qt::AlignHCenter | Qt::AlignTop, t);
    }
    if (!chart.y.title.isEmpty()) {
        p.save();
        p.translate(f.pad + at / 2, a.center().y());
        p.rotate(-90);
        const double room = a.height() + a.top() - f.pad;
        p.drawText(QRectF(-room / 2, -at / 2, room, at), Qt::AlignCenter, f.axis_title_m.elidedText(chart.y.title, Qt::ElideRight, room));
        p.restore();
    }
}

} // namespace

QString font_problem(const ChartStyle& style) {
    // With no font files fontconfig still lists its aliases (Sans Serif, ...), which resolve to nothing.
    if (!QFontInfo(detail::ChartFonts(style).label).family().isEmpty()) return {};
    return QStringLiteral("no fonts found through fontconfig, so charts would have no text (install fontconfig and "
                          "fonts-dejavu-core)");
}

void paint_chart(QPainter& p, const Chart& chart, QSizeF size) {
    const detail::ChartFonts f(chart.style);
    const ChartLayout L = detail::layout_chart(chart, size, f);
    const double dpr = p.device() ? p.device()->devicePixelRatioF() : 1.0;
    p.save();
    p.setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing);
    p.fillRect(QRectF(QPointF(0, 0), size), chart.style.background);
    // Grid under everything.
    p.setPen(QPen(chart.style.grid, 1));
    for (const Tick& t : L.x_ticks) {
        const double x = crisp(L.to_pixels({t.value, L.y_range.lo}).x(), 1, dpr);
        p.drawLine(QPointF(x, L.plot.top()), QPointF(x, L.plot.bottom()));
    }
    for (const Tick& t : L.y_ticks) {
        const double y = crisp(L.to_pixels({L.x_range.lo, t.value}).y(), 1, dpr);
        p.drawLine(QPointF(L.plot.left(), y), QPointF(L.plot.right(), y));
    }
    p.save();
    p.setClipRect(L.plot.adjusted(-2, -2, 2, 2));
    for (const StepLine& s : chart.steps) draw_steps(p, L, s);
    p.restore();
    draw_axes(p, chart, L, f, dpr);
    // Markers over the axes, so a point on an axis stays whole; points outside the ranges are left out.
    for (const Series& s : chart.series)
        for (QPointF d : s.points)
            if (L.shows(d)) draw_marker(p, s.marker, L.to_pixels(d), s.size, s.colour, s.outline);
    if (!chart.title.isEmpty()) {
        p.setPen(chart.style.text);
        p.setFont(f.title);
        const QString t = f.title_m.elidedText(chart.title, Qt::ElideRight, L.title_box.width());
        p.drawText(centred_over_plot(L, f, L.title_box.top(), L.title_box.height(), f.title_m.horizontalAdvance(t)),
                   Qt::AlignHCenter | Qt::AlignVCenter, t);
    }
    draw_legend(p, chart, L, f);
    p.restore();
}

QImage render_chart(const Chart& chart, QSize size, double device_pixel_ratio) {
    const double dpr = device_pixel_ratio > 0 && std::isfinite(device_pixel_ratio) ? device_pixel_ratio : 1.0;
    const double w = std::max(1.0, std::round(std::max(1, size.width()) * dpr));
    const double h = std::max(1.0, std::round(std::max(1, size.height()) * dpr));
    if (w > kMaxSide || h > kMaxSide) return QImage(); // a typo, not a chart: refuse before allocating gigabytes
    QImage image(int(w), int(h), QImage::Format_RGB32);
    if (image.isNull()) return image; // out of memory
    image.setDevicePixelRatio(dpr);
    image.fill(chart.style.background);
    QPainter p(&image);
    paint_chart(p, chart, QSizeF(image.width() / dpr, image.height() / dpr));
    return image;
}

bool save_chart_png(const Chart& chart, const QString& path, QSize size, double device_pixel_ratio, QString* error) {
    auto fail = [&](const QString& why) {
        if (error) *error = path + ": " + why;
        return false;
    };
    const QImage image = render_chart(chart, size, device_pixel_ratio);
    if (image.isNull()) return fail(QStringLiteral("an image of %1 x %2 logical pixels is too large").arg(size.width()).arg(size.height()));
    // Written beside the target and renamed over it, so a failed write leaves any earlier plot whole.
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) return fail(file.errorString());
    QImageWriter writer(&file, "png");
    if (!writer.write(image)) {
        file.cancelWriting();
        return fail(writer.errorString());
    }
    if (!file.commit()) return fail(file.errorString());
    return true;
}

} // namespace spt::plot
