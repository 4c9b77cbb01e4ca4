#pragma once
// The plotted points of one mesh as CSV, written next to its PNG so that `--replot` can redraw it.
#include "plot.hpp"
#include <string>
#include <vector>

namespace bench {

/// The header line of a plot CSV.
inline constexpr const char* kPlotCsvHeader = "mesh,kind,configuration,median_time_ns,agree_near_percent";

/// The points of one mesh's plot.
struct PlotData {
    std::string mesh;               ///< mesh name, as in the title
    std::vector<PlotPoint> points;  ///< in table order
};

/// Writes `data` as CSV at `path`; false with `error` saying why if it cannot be written.
bool write_plot_csv(const std::string& path, const PlotData& data, std::string& error);

/// Reads a plot CSV; throws spt::Error (BadInput) naming the file, the line and the problem.
PlotData read_plot_csv(const std::string& path);

} // namespace bench
