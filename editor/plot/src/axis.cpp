// Axis ranges, ticks and the value-to-fraction map of linear and log10 axes.
#include "spt/plot/axis.hpp"
#include <algorithm>
#include <cmath>

namespace spt::plot {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxTicks = 1000; // a caller's step too fine for the range falls back to the automatic one
constexpr int kMaxDecadeTicks = 12;

// 1, 2 or 5 × 10^k, the smallest of those not below `raw` (> 0).
double nice_step(double raw) {
    if (!(raw > 0) || !std::isfinite(raw)) return 1;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / p;
    return (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * p;
}

double linear_step(const Axis& axis, double span) {
    const double automatic = nice_step(span / 8);
    if (!(axis.step > 0) || !std::isfinite(axis.step) || span / axis.step > kMaxTicks) return automatic;
    return axis.step;
}

QString label_of(const Axis& axis, double v) { return axis.format ? axis.format(v) : QString::number(v, 'g', 10); }

} // namespace

bool plottable(Scale scale, double value) { return std::isfinite(value) && (scale == Scale::Linear || value > 0); }

Range resolve_range(const Axis& axis, double data_lo, double data_hi) {
    const bool log = axis.scale == Scale::Log10;
    const bool fixed_lo = plottable(axis.scale, axis.min), fixed_hi = plottable(axis.scale, axis.max);
    const bool has_data = data_lo <= data_hi && plottable(axis.scale, data_lo) && plottable(axis.scale, data_hi);
    double lo = fixed_lo ? axis.min : has_data ? data_lo : log ? 1 : 0;
    double hi = fixed_hi ? axis.max : has_data ? data_hi : log ? 10 : 1;
    // A span of a value's own size: 10% of it (1 for 0) on a linear axis, half a decade on a log axis.
    auto above = [&](double v) { return log ? v * std::sqrt(10.0) : v + (v == 0 ? 1 : std::abs(v) * 0.1); };
    auto below = [&](double v) { return log ? v / std::sqrt(10.0) : v - (v == 0 ? 1 : std::abs(v) * 0.1); };
    if (fixed_lo && fixed_hi && lo > hi) std::swap(lo, hi);
    if (fixed_lo && !fixed_hi && hi <= lo) hi = above(lo); // the data lies below a fixed lower end
    if (fixed_hi && !fixed_lo && lo >= hi) lo = below(hi);
    if (lo == hi) lo = below(lo), hi = above(hi); // one value: centred in a span of its own

    if (log) {
        if (!fixed_lo) lo = std::pow(10.0, std::floor(std::log10(lo)));
        if (!fixed_hi) hi = std::pow(10.0, std::ceil(std::log10(hi)));
        if (!(lo < hi)) hi = lo * 10;
    } else {
        const double step = linear_step(axis, hi - lo);
        if (!fixed_lo) lo = std::floor(lo / step) * step;
        if (!fixed_hi) hi = std::ceil(hi / step) * step;
        if (!(lo < hi)) hi = lo + step;
    }
    return {lo, hi};
}

std::vector<Tick> axis_ticks(const Axis& axis, const Range& range) {
    std::vector<Tick> out;
    const double slack = (axis.scale == Scale::Log10 ? 1e-9 * range.hi : 1e-9 * (range.hi - range.lo));
    if (!axis.ticks.empty()) {
        for (const Tick& t : axis.ticks)
            if (plottable(axis.scale, t.value) && t.value >= range.lo - slack && t.value <= range.hi + slack) out.push_back(t);
        return out;
    }
    if (axis.scale == Scale::Log10) {
        const int e0 = int(std::ceil(std::log10(range.lo) - 1e-9)), e1 = int(std::floor(std::log10(range.hi) + 1e-9));
        const int stride = std::max(1, (e1 - e0 + kMaxDecadeTicks) / kMaxDecadeTicks);
        for (int e = e0; e <= e1; e += stride) {
            const double v = std::pow(10.0, e);
            out.push_back({v, label_of(axis, v)});
        }
        return out;
    }
    const double step = linear_step(axis, range.hi - range.lo);
    const long long i0 = (long long)std::ceil(range.lo / step - 1e-9), i1 = (long long)std::floor(range.hi / step + 1e-9);
    for (long long i = i0; i <= i1; ++i) {
        double v = double(i) * step;
        if (std::abs(v) < step * 1e-9) v = 0; // no "-0"
        out.push_back({v, label_of(axis, v)});
    }
    return out;
}

double axis_fraction(Scale scale, const Range& range, double value) {
    if (!plottable(scale, value)) return kNaN;
    if (scale == Scale::Log10)
        return (std::log10(value) - std::log10(range.lo)) / (std::log10(range.hi) - std::log10(range.lo));
    return (value - range.lo) / (range.hi - range.lo);
}

} // namespace spt::plot
