#include "bounds.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {
namespace {

// Largest |centre - c_i| + r_i: the radius a ball around `centre` needs.
double enclosing_radius(const Eigen::Vector3d& centre, const Eigen::Vector3f* c, const float* r, size_t n) {
    double best = 0;
    for (size_t i = 0; i < n; ++i) best = std::max(best, (c[i].cast<double>() - centre).norm() + r[i]);
    return best;
}

} // namespace

void bound_run(TreeNode& node, const Eigen::Vector3f* c, const float* r, const Eigen::Vector3f* p, size_t n,
               const Ball& hint, BoundsMethod method) {
    if (n == 0) {
        node.center.setZero();
        node.bv_radius = 0;
        return;
    }
    if (method == BoundsMethod::Paper) {
        Eigen::Vector3f lo = p[0], hi = p[0];
        for (size_t i = 1; i < n; ++i) lo = lo.cwiseMin(p[i]), hi = hi.cwiseMax(p[i]);
        node.center = (lo + hi) / 2;
        node.bv_radius = (hi - lo).maxCoeff() / 2;
        return;
    }
    // Tight: try a few centres, each with the exact radius that encloses every sphere.
    std::vector<Eigen::Vector3d> candidates;
    Eigen::Vector3d lo = c[0].cast<double>(), hi = lo;
    for (size_t i = 1; i < n; ++i) lo = lo.cwiseMin(c[i].cast<double>()), hi = hi.cwiseMax(c[i].cast<double>());
    candidates.push_back((lo + hi) / 2);
    if (hint.radius >= 0) candidates.push_back(hint.center);
    const bool equal_radii = std::all_of(r, r + n, [&](float x) { return x == r[0]; });
    if (n <= 64 && equal_radii) {
        // Equal radii: the smallest ball of the centres grown by r is the smallest enclosing ball.
        std::vector<Eigen::Vector3d> pts(n);
        for (size_t i = 0; i < n; ++i) pts[i] = c[i].cast<double>();
        candidates.push_back(smallest_ball(std::move(pts)).center);
    }
    double best_r = INFINITY;
    Eigen::Vector3d best_c = candidates[0];
    for (const auto& cand : candidates) {
        const double rad = enclosing_radius(cand, c, r, n);
        if (rad < best_r) best_r = rad, best_c = cand;
    }
    node.center = best_c.cast<float>();
    // Rounding to float may move the centre: measure again in float and round up.
    double rad = 0;
    for (size_t i = 0; i < n; ++i) rad = std::max(rad, double((c[i] - node.center).norm()) + r[i]);
    node.bv_radius = std::nextafter(float(rad * (1 + 1e-6)), INFINITY);
}

} // namespace spt::detail
