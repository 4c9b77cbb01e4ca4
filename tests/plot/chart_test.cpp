// Whole charts: determinism, grid placement, empty and degenerate data, points that cannot be shown, legend room.
#include "chart_support.hpp"
#include "spt/plot/headless_gui.hpp"
#include <QFontInfo>
#include <QGuiApplication>
#include <cstring>
#include <gtest/gtest.h>

using namespace spt::plot;
using namespace spt::plot::test;

namespace {

Chart busy_chart() {
    Chart c;
    c.title = "Agreement vs time";
    c.x.scale = Scale::Log10, c.x.title = "median time", c.y.title = "agreement (%)";
    c.x.format = [](double v) { return QString("%1 ns").arg(v); };
    Series a, b;
    a.name = "spheres", a.colour = QColor(40, 100, 220), a.outline = Qt::white;
    b.name = "FCL", b.marker = Marker::Square, b.colour = Qt::black, b.size = 12;
    for (int i = 0; i < 40; ++i) a.points.push_back({100.0 + 37.0 * i, 50.0 + i});
    b.points = {{15000, 100}};
    c.series = {a, b};
    StepLine s;
    s.name = "Pareto front", s.colour = QColor(200, 40, 40), s.points = {{100, 50}, {500, 70}, {1500, 89}}, s.dashed_tail = true;
    c.steps = {s};
    return c;
}

bool same_bytes(const QImage& a, const QImage& b) {
    return a.size() == b.size() && a.format() == b.format() && a.sizeInBytes() == b.sizeInBytes() &&
           std::memcmp(a.constBits(), b.constBits(), size_t(a.sizeInBytes())) == 0;
}

} // namespace

TEST(plot_chart, runs_on_the_offscreen_platform_even_when_the_environment_names_xcb) {
    // headless_environment.cpp set QT_QPA_PLATFORM=xcb and removed DISPLAY before HeadlessGui started.
    EXPECT_EQ(QGuiApplication::platformName(), "offscreen");
    HeadlessGui second; // an application exists: nothing happens
    EXPECT_EQ(QGuiApplication::platformName(), "offscreen");
}

TEST(plot_chart, renders_the_same_bytes_twice) {
    const Chart c = busy_chart();
    for (double dpr : {1.0, 2.0}) {
        const QImage a = render_chart(c, QSize(700, 450), dpr), b = render_chart(c, QSize(700, 450), dpr);
        ASSERT_FALSE(a.isNull());
        EXPECT_TRUE(same_bytes(a, b)) << "dpr " << dpr;
    }
}

TEST(plot_chart, device_pixel_ratio_scales_pixels_not_layout) {
    const Chart c = busy_chart();
    const QImage one = render_chart(c, QSize(700, 450), 1), two = render_chart(c, QSize(700, 450), 2);
    EXPECT_EQ(one.size(), QSize(700, 450));
    EXPECT_EQ(two.size(), QSize(1400, 900));
    EXPECT_DOUBLE_EQ(two.devicePixelRatio(), 2.0);
    // The FCL marker (black square) sits at the same logical place in both.
    const QPointF p = layout_chart(c, QSizeF(700, 450)).to_pixels({15000, 100});
    EXPECT_TRUE(same_rgb(pixel_at(one, p, 1), Qt::black));
    EXPECT_TRUE(same_rgb(pixel_at(two, p, 2), Qt::black));
}

TEST(plot_chart, log_axis_grid_lines_fall_on_evenly_spaced_decades) {
    Chart c = fixed_chart();
    const QImage image = render_chart(c, QSize(640, 420), 1);
    const ChartLayout L = layout_chart(c, QSizeF(640, 420));
    ASSERT_EQ(L.x_ticks.size(), 5u);
    for (size_t i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(L.x_ticks[i].value, std::pow(10.0, double(i)));
    // A row between the horizontal grid lines (y = 10): grid colour at each decade, background between.
    const QPointF row = expected_pixel(L.plot, 1, 10);
    for (int i = 1; i < 4; ++i) {
        const double x = L.plot.left() + L.plot.width() * i / 4;
        EXPECT_TRUE(same_rgb(pixel_at(image, {x, row.y()}, 1), c.style.grid)) << "decade " << i;
        EXPECT_TRUE(same_rgb(pixel_at(image, {x - 3, row.y()}, 1), c.style.background)) << "decade " << i;
        EXPECT_TRUE(same_rgb(pixel_at(image, {x + 3, row.y()}, 1), c.style.background)) << "decade " << i;
    }
    // Halfway between 10 and 100 in log terms (31.6) is the middle between their grid lines, and blank.
    const QPointF mid = expected_pixel(L.plot, std::sqrt(1000.0), 10);
    EXPECT_NEAR(mid.x(), L.plot.left() + L.plot.width() * 1.5 / 4, 1e-9);
    EXPECT_TRUE(same_rgb(pixel_at(image, mid, 1), c.style.background));
}

TEST(plot_chart, no_series_and_empty_series_draw_axes_and_legend_only) {
    Chart none = fixed_chart();
    Chart empty = fixed_chart();
    Series s;
    s.name = "nothing yet";
    empty.series.push_back(s);
    empty.steps.push_back(StepLine{});
    for (const Chart* c : {&none, &empty}) {
        const QImage image = render_chart(*c, QSize(500, 360), 1);
        ASSERT_FALSE(image.isNull());
        const ChartLayout L = layout_chart(*c, QSizeF(500, 360));
        EXPECT_GT(L.plot.width(), 100);
        EXPECT_TRUE(same_rgb(pixel_at(image, expected_pixel(L.plot, 31.6, 60), 1), c->style.background));
    }
    EXPECT_EQ(layout_chart(empty, QSizeF(500, 360)).legend.size(), 1u);
    // Automatic axes with no data at all still get a range and ticks.
    Chart bare;
    bare.x.scale = Scale::Log10;
    const ChartLayout L = layout_chart(bare, QSizeF(400, 300));
    EXPECT_LT(L.x_range.lo, L.x_range.hi);
    EXPECT_FALSE(L.x_ticks.empty());
    EXPECT_FALSE(render_chart(bare, QSize(400, 300)).isNull());
}

TEST(plot_chart, single_point_is_drawn_inside_the_plot) {
    for (Scale scale : {Scale::Linear, Scale::Log10}) {
        Chart c;
        c.x.scale = scale;
        Series s;
        s.colour = QColor(30, 160, 60), s.size = 10, s.points = {{123, 45}};
        c.series.push_back(s);
        const QImage image = render_chart(c, QSize(400, 300), 1);
        const ChartLayout L = layout_chart(c, QSizeF(400, 300));
        const QPointF p = L.to_pixels({123, 45});
        EXPECT_GT(p.x(), L.plot.left() + 5);
        EXPECT_LT(p.x(), L.plot.right() - 5);
        EXPECT_GT(p.y(), L.plot.top() + 5);
        EXPECT_LT(p.y(), L.plot.bottom() - 5);
        EXPECT_TRUE(same_rgb(pixel_at(image, p, 1), s.colour));
    }
}

TEST(plot_chart, nan_infinite_and_nonpositive_log_points_are_skipped) {
    const Chart clean = busy_chart();
    Chart dirty = clean;
    const double nan = std::nan(""), inf = INFINITY;
    for (QPointF p : {QPointF(nan, 50), QPointF(inf, 60), QPointF(-inf, 70), QPointF(300, nan), QPointF(300, inf),
                      QPointF(0, 80), QPointF(-40, 90)}) {
        dirty.series[0].points.insert(dirty.series[0].points.begin() + 3, p);
        dirty.series[1].points.push_back(p);
    }
    dirty.steps[0].points.insert(dirty.steps[0].points.begin() + 1, QPointF(nan, nan));
    const ChartLayout a = layout_chart(clean, QSizeF(700, 450)), b = layout_chart(dirty, QSizeF(700, 450));
    EXPECT_EQ(a.x_range.lo, b.x_range.lo);
    EXPECT_EQ(a.x_range.hi, b.x_range.hi);
    EXPECT_EQ(a.y_range.lo, b.y_range.lo);
    EXPECT_EQ(a.y_range.hi, b.y_range.hi);
    EXPECT_TRUE(same_bytes(render_chart(clean, QSize(700, 450)), render_chart(dirty, QSize(700, 450))));
}

TEST(plot_chart, points_outside_fixed_ranges_are_left_out) {
    const Chart clean = fixed_chart();
    Chart outside = clean;
    Series s;
    s.colour = QColor(200, 30, 30), s.size = 14, s.points = {{1e6, 50}, {100, 140}, {100, -20}, {0.01, 50}};
    outside.series.push_back(s);
    EXPECT_TRUE(same_bytes(render_chart(clean, QSize(500, 360)), render_chart(outside, QSize(500, 360))));
}

TEST(plot_chart, legend_wraps_into_rows_that_fit_a_narrow_image) {
    Chart c = busy_chart();
    for (const char* n : {"bounds, tight, leaf 8", "exact with triangles", "Bullet 3.24 GImpact",
                          "brute force over every pair of sampling spheres of both trees, on a subset of the poses"}) {
        Series s;
        s.name = n, s.points = {{1000, 75}};
        c.series.push_back(s);
    }
    const QSizeF size(340, 420);
    const ChartLayout L = layout_chart(c, size);
    ASSERT_EQ(L.legend.size(), 7u);
    int rows = 1;
    for (size_t i = 0; i < L.legend.size(); ++i) {
        const QRectF& e = L.legend[i].box;
        EXPECT_GE(e.left(), 0);
        EXPECT_LE(e.right(), size.width());
        EXPECT_LE(e.bottom(), size.height());
        EXPECT_GT(e.top(), L.plot.bottom()) << "legend under the plot";
        for (size_t j = 0; j < i; ++j) EXPECT_FALSE(e.intersects(L.legend[j].box)) << i << " overlaps " << j;
        if (i > 0 && e.top() > L.legend[i - 1].box.top()) ++rows;
    }
    EXPECT_GE(rows, 3);
    EXPECT_GT(L.plot.height(), 50);
    EXPECT_FALSE(render_chart(c, size.toSize()).isNull());
}

TEST(plot_chart, tiny_sizes_and_odd_ratios_do_not_crash) {
    const Chart c = busy_chart();
    EXPECT_EQ(render_chart(c, QSize(1, 1)).size(), QSize(1, 1));
    EXPECT_EQ(render_chart(c, QSize(0, -5)).size(), QSize(1, 1));
    EXPECT_EQ(render_chart(c, QSize(100, 80), std::nan("")).size(), QSize(100, 80));
    EXPECT_EQ(render_chart(c, QSize(100, 80), -2).size(), QSize(100, 80));
    EXPECT_EQ(render_chart(c, QSize(100, 80), 1.5).size(), QSize(150, 120));
}

TEST(plot_chart, absurd_size_gives_a_null_image_not_an_allocation) {
    EXPECT_TRUE(render_chart(busy_chart(), QSize(100000, 100000)).isNull());
    EXPECT_TRUE(render_chart(busy_chart(), QSize(8000, 8000), 4).isNull());
}

TEST(plot_chart, text_is_drawn_in_the_requested_font) {
    // Without a font package Qt draws no text at all and says so only on stderr (debian-packages.txt lists one).
    EXPECT_EQ(font_problem().toStdString(), "");
    Chart c;
    c.title = "Agreement near contact";
    QFont f;
    f.setFamilies(c.style.families);
    f.setPixelSize(c.style.title_px);
    EXPECT_TRUE(c.style.families.contains(QFontInfo(f).family())) << QFontInfo(f).family().toStdString();
    const QImage image = render_chart(c, QSize(500, 300), 1);
    const QRect box = layout_chart(c, QSizeF(500, 300)).title_box.toAlignedRect();
    int ink = 0;
    for (int y = box.top(); y <= box.bottom(); ++y)
        for (int x = box.left(); x <= box.right(); ++x) ink += qGray(image.pixel(x, y)) < 128;
    EXPECT_GT(ink, 200) << "title pixels";
    // Wider text covers more pixels: glyphs, not boxes of a fixed size.
    c.title += " vs median query time";
    const QImage longer = render_chart(c, QSize(500, 300), 1);
    int more = 0;
    for (int y = box.top(); y <= box.bottom(); ++y)
        for (int x = box.left(); x <= box.right(); ++x) more += qGray(longer.pixel(x, y)) < 128;
    EXPECT_GT(more, ink * 1.3);
}
