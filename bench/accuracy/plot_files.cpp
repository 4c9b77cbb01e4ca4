// Plot files: the CSV and PNG of each mesh, and redrawing PNGs from their CSVs.
#include "exit_code.hpp"
#include "plot_files.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <iostream>
#include <vector>

namespace bench {

bool write_plot_files(const std::string& png_path, const PlotData& data) {
    std::string error;
    const std::string csv = std::filesystem::path(png_path).replace_extension(".csv").string();
    const bool ok = write_plot_csv(csv, data, error) && draw_plot(png_path, data.mesh, data.points, error);
    if (!ok) std::cerr << "error: " << error << "\n";
    return ok;
}

int replot(const std::filesystem::path& dir, const std::string& stem, const std::string& mesh) {
    namespace fs = std::filesystem;
    std::vector<fs::path> csvs;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string file = it->path().filename().string();
        if (it->is_regular_file(ec) && it->path().extension() == ".csv" && file.rfind(stem + "-", 0) == 0)
            csvs.push_back(it->path());
    }
    std::sort(csvs.begin(), csvs.end());
    int status = 0, drawn = 0;
    for (const fs::path& csv : csvs) {
        try {
            const PlotData data = read_plot_csv(csv.string());
            if (!mesh.empty() && data.mesh != mesh) continue;
            std::string png = fs::path(csv).replace_extension(".png").string(), error;
            if (!draw_plot(png, data.mesh, data.points, error)) {
                std::cerr << "error: " << error << "\n";
                status = std::max(status, spt::cli::exit_code(spt::ErrorKind::CannotWrite));
                continue;
            }
            std::cerr << "redrew " << png << " (" << data.points.size() << " points)\n";
            ++drawn;
        } catch (const spt::Error& e) {
            std::cerr << "error: " << e.what() << "\n";
            status = std::max(status, spt::cli::exit_code(e.kind()));
        }
    }
    if (drawn == 0 && status == 0) {
        std::cerr << "error: no plot CSV " << (dir / (stem + "-*.csv")).string()
                  << (mesh.empty() ? "" : " of mesh '" + mesh + "'") << " to redraw\n";
        return spt::cli::exit_code(spt::ErrorKind::BadInput);
    }
    return status;
}

} // namespace bench
