#include "plot.hpp"
#include "canvas.hpp"
#include <algorithm>
#include <cmath>

namespace bench {
namespace {

constexpr Rgb kWhite{255, 255, 255}, kBlack{0, 0, 0}, kGrid{225, 225, 225}, kFront{200, 40, 40};

Rgb colour(PointKind k) {
    switch (k) {
    case PointKind::Bounds: return {230, 150, 30};
    case PointKind::Spheres: return {40, 100, 220};
    case PointKind::Exact: return {30, 160, 60};
    case PointKind::Fcl: return {0, 0, 0};
    case PointKind::Bullet: return {150, 50, 170};
    case PointKind::BruteForce: return {120, 120, 120};
    }
    return kBlack;
}

void marker(Canvas& c, double x, double y, PointKind k) {
    const Rgb col = colour(k);
    switch (k) {
    case PointKind::Fcl: c.square(x, y, 6, col); break;
    case PointKind::Bullet: c.diamond(x, y, 6, col); break;
    case PointKind::BruteForce: c.triangle(x, y, 7, col); break;
    default: c.disc(x, y, 3.5, col);
    }
}

std::string time_label(double ns) {
    if (ns >= 1e9) return std::to_string(int(std::lround(ns / 1e9))) + " S";
    if (ns >= 1e6) return std::to_string(int(std::lround(ns / 1e6))) + " MS";
    if (ns >= 1e3) return std::to_string(int(std::lround(ns / 1e3))) + " US";
    return std::to_string(int(std::lround(ns))) + " NS";
}

} // namespace

bool draw_plot(const std::string& path, const std::string& title, const std::vector<PlotPoint>& pts) {
    const int W = 1000, H = 660, left = 90, right = 30, top = 70, bottom = 120;
    Canvas c(W, H, kWhite);
    double tmin = 1e300, tmax = 0, amin = 100;
    for (const auto& p : pts) tmin = std::min(tmin, p.ns), tmax = std::max(tmax, p.ns), amin = std::min(amin, p.agreement);
    const double lx0 = std::floor(std::log10(std::max(1.0, tmin))), lx1 = std::ceil(std::log10(std::max(10.0, tmax)));
    const double y0 = std::max(0.0, std::floor((amin - 1) / 5) * 5), y1 = 100.5;
    const int pw = W - left - right, ph = H - top - bottom;
    auto X = [&](double ns) { return left + (std::log10(ns) - lx0) / (lx1 - lx0) * pw; };
    auto Y = [&](double a) { return top + (y1 - a) / (y1 - y0) * ph; };
    // Grid and axes.
    for (double e = lx0; e <= lx1 + 1e-9; ++e) {
        const double x = X(std::pow(10.0, e));
        c.line(x, top, x, top + ph, kGrid);
        const std::string l = time_label(std::pow(10.0, e));
        c.text(int(x) - text_width(l) / 2, top + ph + 8, l, kBlack);
    }
    const double ystep = (y1 - y0) > 40 ? 10 : (y1 - y0) > 15 ? 5 : 1;
    for (double a = y0; a <= 100 + 1e-9; a += ystep) {
        c.line(left, Y(a), left + pw, Y(a), kGrid);
        const std::string l = std::to_string(int(a)) + "%";
        c.text(left - 8 - text_width(l), int(Y(a)) - 7, l, kBlack);
    }
    c.line(left, top, left, top + ph, kBlack, 2);
    c.line(left, top + ph, left + pw, top + ph, kBlack, 2);
    c.text(left + pw / 2 - text_width("MEDIAN QUERY TIME (LOG)") / 2, top + ph + 32, "MEDIAN QUERY TIME (LOG)", kBlack);
    c.text(left, 14, title, kBlack); // above the axis label, which sits just over the plot
    c.text(8, top - 22, "AGREEMENT", kBlack);
    // Pareto front: sorted by time, a point joins when it is more accurate than every faster one.
    std::vector<PlotPoint> sorted = pts;
    std::sort(sorted.begin(), sorted.end(), [](const PlotPoint& a, const PlotPoint& b) {
        return a.ns != b.ns ? a.ns < b.ns : a.agreement > b.agreement;
    });
    double best = -1, px = 0, py = 0;
    bool first = true;
    for (const auto& p : sorted) {
        if (!(p.agreement > best)) continue;
        const double x = X(p.ns), y = Y(p.agreement);
        if (!first) {
            c.line(px, py, x, py, kFront, 2);
            c.line(x, py, x, y, kFront, 2);
        }
        first = false, best = p.agreement, px = x, py = y;
    }
    if (!first) c.dashed(px, py, left + pw, py, kFront);
    for (const auto& p : pts) marker(c, X(p.ns), Y(p.agreement), p.kind);
    // Legend.
    const std::pair<PointKind, const char*> legend[] = {
        {PointKind::Bounds, "BOUNDS"}, {PointKind::Spheres, "SPHERES"}, {PointKind::Exact, "EXACT"},
        {PointKind::Fcl, "FCL"},       {PointKind::Bullet, "BULLET"},   {PointKind::BruteForce, "BRUTE FORCE"}};
    int lx = left, ly = H - 40;
    for (const auto& [k, name] : legend) {
        marker(c, lx + 6, ly + 7, k);
        lx += 18 + c.text(lx + 18, ly, name, kBlack) + 20;
    }
    c.line(lx, ly + 7, lx + 24, ly + 7, kFront, 2);
    c.text(lx + 30, ly, "PARETO FRONT", kBlack);
    return c.save_png(path);
}

} // namespace bench
