// Markers and step lines land on the pixels the axis mapping predicts, with their colour.
#include "chart_support.hpp"
#include <gtest/gtest.h>

using namespace spt::plot;
using namespace spt::plot::test;

namespace {

struct Expect {
    Marker marker;
    QColor colour;
    double x, y;
};

const Expect kMarkers[] = {
    {Marker::Disc, QColor(200, 30, 30), 10, 20},
    {Marker::Square, QColor(20, 160, 40), 100, 65},
    {Marker::Diamond, QColor(130, 40, 170), 3000, 90},
    {Marker::Triangle, QColor(20, 60, 210), 2.5, 40},
};

Chart marker_chart() {
    Chart c = fixed_chart();
    for (const Expect& e : kMarkers) {
        Series s;
        s.name = "m", s.marker = e.marker, s.colour = e.colour, s.size = 12, s.points = {{e.x, e.y}};
        c.series.push_back(s);
    }
    return c;
}

} // namespace

TEST(plot_markers, centre_lands_where_the_axis_mapping_predicts) {
    const Chart c = marker_chart();
    for (double dpr : {1.0, 2.0}) {
        const QImage image = render_chart(c, QSize(640, 420), dpr);
        ASSERT_EQ(image.width(), int(640 * dpr));
        const ChartLayout L = layout_chart(c, QSizeF(640, 420));
        for (const Expect& e : kMarkers) {
            const QPointF want = expected_pixel(L.plot, e.x, e.y);
            EXPECT_NEAR(L.to_pixels({e.x, e.y}).x(), want.x(), 1e-9);
            EXPECT_NEAR(L.to_pixels({e.x, e.y}).y(), want.y(), 1e-9);
            EXPECT_TRUE(same_rgb(pixel_at(image, want, dpr), e.colour))
                << "dpr " << dpr << " marker " << int(e.marker) << " at " << want.x() << "," << want.y() << " is "
                << pixel_at(image, want, dpr).name().toStdString();
            // Inside its half-width (12 / 2 = 6 logical pixels) the marker's colour, well beyond it not.
            for (QPointF d : {QPointF(2.5, 0), QPointF(-2.5, 0), QPointF(0, 2.5), QPointF(0, -2)})
                EXPECT_TRUE(same_rgb(pixel_at(image, want + d, dpr), e.colour)) << "dpr " << dpr << " marker " << int(e.marker);
            for (QPointF d : {QPointF(10, 0), QPointF(-10, 0), QPointF(0, 10), QPointF(0, -10)})
                EXPECT_FALSE(same_rgb(pixel_at(image, want + d, dpr), e.colour)) << "dpr " << dpr << " marker " << int(e.marker);
        }
    }
}

TEST(plot_markers, step_line_goes_across_then_up_with_a_dashed_tail) {
    Chart c = fixed_chart();
    const QColor red(210, 20, 20);
    StepLine s;
    s.colour = red, s.width = 2, s.points = {{10, 20}, {1000, 80}}, s.dashed_tail = true;
    c.steps.push_back(s);
    const QImage image = render_chart(c, QSize(640, 420), 1);
    const ChartLayout L = layout_chart(c, QSizeF(640, 420));
    const QPointF a = expected_pixel(L.plot, 10, 20), b = expected_pixel(L.plot, 1000, 80);
    // Across at the first point's level to the second point's x, then up to it.
    EXPECT_TRUE(same_rgb(pixel_at(image, {(a.x() + b.x()) / 2, a.y()}, 1), red));
    EXPECT_TRUE(same_rgb(pixel_at(image, {b.x(), (a.y() + b.y()) / 2}, 1), red));
    // Not the diagonal between them, and nothing at the second point's x below the first level.
    EXPECT_FALSE(same_rgb(pixel_at(image, (a + b) / 2, 1), red));
    EXPECT_FALSE(same_rgb(pixel_at(image, {b.x(), a.y() + 20}, 1), red));
    // The tail: reddish dashes and gaps between the last point and the right edge of the plot.
    int dash = 0, gap = 0;
    const int row = int(std::floor(b.y()));
    for (int x = int(b.x()) + 3; x < int(L.plot.right()) - 1; ++x) {
        const QColor p = image.pixelColor(x, row);
        (p.red() - p.green() > 60 ? dash : gap)++;
    }
    EXPECT_GT(dash, 20);
    EXPECT_GT(gap, 20);
}

TEST(plot_markers, step_line_without_a_tail_stops_at_its_last_point) {
    Chart c = fixed_chart();
    StepLine s;
    s.colour = QColor(210, 20, 20), s.points = {{10, 20}, {100, 80}};
    c.steps.push_back(s);
    const QImage image = render_chart(c, QSize(640, 420), 1);
    const ChartLayout L = layout_chart(c, QSizeF(640, 420));
    const QPointF b = expected_pixel(L.plot, 100, 80);
    for (int x = int(b.x()) + 4; x < int(L.plot.right()) - 1; ++x) {
        const QColor p = image.pixelColor(x, int(std::floor(b.y())));
        EXPECT_LT(p.red() - p.green(), 20) << "x " << x;
    }
}
