#pragma once
// A mesh's plot files, PNG and the CSV of its points side by side, and `--replot`, which redraws PNGs from CSVs.
#include "plot_csv.hpp"
#include <filesystem>
#include <string>

namespace bench {

/// Writes the points as CSV next to `png_path` (same name, .csv) and draws the PNG; false, after printing why,
/// if either cannot be written.
bool write_plot_files(const std::string& png_path, const PlotData& data);

/// Redraws every <dir>/<stem>-*.png from the CSV beside it (only `mesh`'s if not empty), printing each file drawn and
/// each problem; returns the exit code: 0, 2 for a bad or missing CSV, 3 for a PNG that cannot be written.
int replot(const std::filesystem::path& dir, const std::string& stem, const std::string& mesh);

} // namespace bench
