#pragma once
// The accuracy-vs-time scatter plot: x median query time (log), y agreement with exact.
#include <string>
#include <vector>

namespace bench {

enum class PointKind { Bounds, Spheres, Exact, Fcl, Bullet, BruteForce };

struct PlotPoint {
    double ns;        ///< median query time, nanoseconds
    double agreement; ///< percent
    PointKind kind;
};

/// Draws the points, the peers marked, and the Pareto front (faster and at least as accurate); false if the PNG cannot be written.
bool draw_plot(const std::string& path, const std::string& title, const std::vector<PlotPoint>& points);

} // namespace bench
