#pragma once
// The accuracy-vs-time plot of one mesh: agreement near contact against median query time (log), Pareto front.
#include <string>
#include <vector>

namespace bench {

/// What a plotted point is: a query level of ours, or a peer.
enum class PointKind { Bounds, Spheres, Exact, Fcl, Bullet, BruteForce };

/// One row of the benchmark table as a point of the plot.
struct PlotPoint {
    std::string name;  ///< configuration or peer, as in the table
    double ns = 0;     ///< median query time on the random poses, nanoseconds
    double agreement = 0; ///< agreement with FCL on the near-contact poses, percent
    PointKind kind = PointKind::Spheres;
};

/// The Pareto front: sorted by time (ties: most accurate first), the points more accurate than every faster one.
std::vector<PlotPoint> pareto_front(std::vector<PlotPoint> points);

/// Draws the plot of `mesh` as a PNG at `path`; false with `error` saying why if it cannot be written.
/// Needs a QGuiApplication (spt::plot::HeadlessGui in a command-line program).
bool draw_plot(const std::string& path, const std::string& mesh, const std::vector<PlotPoint>& points, std::string& error);

} // namespace bench
