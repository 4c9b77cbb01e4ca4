// The accuracy-vs-time plot drawn with spt::plot: which kinds, their colours and markers, the Pareto front.
#include "plot.hpp"
#include "spt/plot/chart.hpp"
#include <algorithm>
#include <cmath>

namespace bench {
namespace {

using spt::plot::Marker;

struct KindStyle {
    PointKind kind;
    const char* legend;
    QColor colour;
    Marker marker;
    double size; // logical pixels
};

// Legend and drawing order: our three query levels, then the peers over them.
const KindStyle kKinds[] = {
    {PointKind::Bounds, "bounds", QColor(230, 150, 30), Marker::Disc, 8},
    {PointKind::Spheres, "spheres", QColor(40, 100, 220), Marker::Disc, 8},
    {PointKind::Exact, "exact", QColor(30, 160, 60), Marker::Disc, 8},
    {PointKind::Fcl, "FCL", QColor(0, 0, 0), Marker::Square, 12},
    {PointKind::Bullet, "Bullet", QColor(150, 50, 170), Marker::Diamond, 13},
    {PointKind::BruteForce, "brute force", QColor(120, 120, 120), Marker::Triangle, 13},
};
const QColor kFront(200, 40, 40);

// 1 ns, 10 ns, 100 ns, 1 µs, ...: the decades of the time axis.
QString time_label(double ns) {
    static const char* const units[] = {"ns", "µs", "ms", "s"};
    int u = 0;
    while (u < 3 && ns >= 1e3 * (1 - 1e-9)) ns /= 1e3, ++u;
    return QString::number(ns, 'g', 3) + QChar(0x2009) /* thin space */ + QString::fromUtf8(units[u]);
}

} // namespace

std::vector<PlotPoint> pareto_front(std::vector<PlotPoint> points) {
    std::sort(points.begin(), points.end(), [](const PlotPoint& a, const PlotPoint& b) {
        return a.ns != b.ns ? a.ns < b.ns : a.agreement > b.agreement;
    });
    std::vector<PlotPoint> front;
    for (const PlotPoint& p : points)
        if (std::isfinite(p.ns) && std::isfinite(p.agreement) && (front.empty() || p.agreement > front.back().agreement))
            front.push_back(p);
    return front;
}

bool draw_plot(const std::string& path, const std::string& mesh, const std::vector<PlotPoint>& points, std::string& error) {
    if (const QString problem = spt::plot::font_problem(); !problem.isEmpty()) {
        error = path + ": " + problem.toStdString();
        return false;
    }
    spt::plot::Chart chart;
    chart.title = QString::fromStdString(mesh) + ": agreement near contact vs median query time on random poses";
    chart.style.font_px = 14, chart.style.title_px = 18;
    chart.x.scale = spt::plot::Scale::Log10;
    chart.x.title = "median query time on random poses (log scale)";
    chart.x.format = time_label;
    // A point at 0 ns cannot sit on a log axis: the clock's resolution puts it at 1 ns.
    auto at = [](const PlotPoint& p) { return QPointF(std::max(1.0, p.ns), p.agreement); };
    double lowest = 100;
    for (const PlotPoint& p : points)
        if (std::isfinite(p.agreement)) lowest = std::min(lowest, p.agreement);
    const double span = 100 - lowest;
    chart.y.step = span > 40 ? 10 : span > 15 ? 5 : 1;
    chart.y.min = std::max(0.0, std::floor((lowest - 1) / chart.y.step) * chart.y.step);
    chart.y.max = 100.5; // room above 100% for the markers sitting there
    chart.y.title = "agreement with FCL near contact";
    chart.y.format = [](double v) { return QString::number(v, 'g', 4) + "%"; };
    for (const KindStyle& k : kKinds) {
        spt::plot::Series s;
        for (const PlotPoint& p : points)
            if (p.kind == k.kind) s.points.push_back(at(p));
        if (s.points.empty()) continue; // e.g. brute force in --quick runs
        s.name = k.legend, s.colour = k.colour, s.marker = k.marker, s.size = k.size, s.outline = Qt::white;
        chart.series.push_back(std::move(s));
    }
    spt::plot::StepLine front;
    front.name = "Pareto front", front.colour = kFront, front.width = 2, front.dashed_tail = true;
    for (const PlotPoint& p : pareto_front(points)) front.points.push_back(at(p));
    chart.steps.push_back(std::move(front));
    QString why;
    if (spt::plot::save_chart_png(chart, QString::fromStdString(path), QSize(1000, 640), 2, &why)) return true;
    error = why.toStdString();
    return false;
}

} // namespace bench
