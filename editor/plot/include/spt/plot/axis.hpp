#pragma once
// Chart axes: linear or log10 scales, the data range an axis shows, its ticks, and where a value falls along it.
#include <QString>
#include <functional>
#include <limits>
#include <vector>

namespace spt::plot {

/// How values are spaced along an axis.
enum class Scale { Linear, Log10 };

/// A labelled tick with its grid line, at a value in data units.
struct Tick {
    double value = 0; ///< data units
    QString label;    ///< text drawn next to the tick
};

/// What an axis shows. Range and ticks come from the data unless the axis gives them.
struct Axis {
    QString title;                ///< drawn along the axis; empty: none
    Scale scale = Scale::Linear;  ///< linear or log10
    double min = std::numeric_limits<double>::quiet_NaN(); ///< lower end, data units; NaN: from the data
    double max = std::numeric_limits<double>::quiet_NaN(); ///< upper end, data units; NaN: from the data
    double step = 0;              ///< linear tick spacing, data units; 0: automatic (1, 2 or 5 × 10^k)
    std::vector<Tick> ticks;      ///< explicit ticks, used as given; empty: automatic ticks
    std::function<QString(double)> format; ///< label of an automatic tick; empty: shortest decimal form
};

/// A closed interval of data values, lo < hi.
struct Range {
    double lo = 0; ///< data units
    double hi = 1; ///< data units
};

/// True if `value` can be placed on an axis of `scale`: finite, and positive on a log axis.
bool plottable(Scale scale, double value);

/// The range an axis shows for data spanning [data_lo, data_hi] (data_lo > data_hi: no data). Automatic ends
/// are rounded out to whole ticks (decades on a log axis); a zero-width span is widened; always lo < hi.
Range resolve_range(const Axis& axis, double data_lo, double data_hi);

/// The ticks inside `range`: the axis's own ticks if it has any, else whole decades (log) or multiples of the step.
std::vector<Tick> axis_ticks(const Axis& axis, const Range& range);

/// Where `value` falls along the axis: 0 at range.lo, 1 at range.hi, linear in the value or in its log10;
/// NaN if the value is not plottable.
double axis_fraction(Scale scale, const Range& range, double value);

} // namespace spt::plot
