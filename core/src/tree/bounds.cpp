// Bounding spheres of runs of sampling spheres: tight (contain every sphere) or the paper's.
#include "tree/bounds.hpp"
#include "base/float_round.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {
namespace {

// Largest |centre_k - c_i| + r_i for each of `m` candidate centres: the radius a ball around
// each needs, in one pass over the spheres. With equal radii (every leaf, most inner nodes)
// one square root per candidate is enough.
void enclosing_radii(const Eigen::Vector3d* centre, size_t m, const Eigen::Vector3f* c, const float* r, size_t n,
                     bool equal_radii, double* out) {
    if (equal_radii) {
        // Differences in double: in float they err by the coordinates' magnitude, which can
        // far exceed a small node's radius.
        double d2[3] = {0, 0, 0};
        for (size_t i = 0; i < n; ++i) {
            const Eigen::Vector3d ci = c[i].cast<double>();
            for (size_t k = 0; k < m; ++k) d2[k] = std::max(d2[k], (ci - centre[k]).squaredNorm());
        }
        for (size_t k = 0; k < m; ++k) out[k] = std::sqrt(d2[k]) + r[0];
        return;
    }
    double best[3] = {0, 0, 0};
    for (size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d ci = c[i].cast<double>();
        for (size_t k = 0; k < m; ++k) best[k] = std::max(best[k], (ci - centre[k]).norm() + r[i]);
    }
    for (size_t k = 0; k < m; ++k) out[k] = best[k];
}

} // namespace

double run_extent(const Eigen::Vector3d& centre, const Eigen::Vector3f* c, const float* r, size_t n, bool equal_radii) {
    double best = 0;
    for (size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d ci = c[i].cast<double>();
        best = std::max(best, equal_radii ? (ci - centre).squaredNorm() : (ci - centre).norm() + r[i]);
    }
    return best;
}

void bound_run(TreeNode& node, const Eigen::Vector3f* c, const float* r, const Eigen::Vector3f* p, size_t n,
               const Ball& hint, BoundsMethod method, const RunFacts& facts) {
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
    // Centres are rounded to float first, so the radius measured is the stored centre's.
    Eigen::Vector3d candidates[3];
    size_t m = 0;
    auto add = [&](const Eigen::Vector3d& x) { candidates[m++] = float_rounded(x); };
    Eigen::AlignedBox3f box;
    if (facts.centre_box) box = *facts.centre_box;
    else for (size_t i = 0; i < n; ++i) box.extend(c[i]);
    add(box.center().cast<double>());
    if (hint.radius >= 0) add(hint.center);
    const bool equal_radii =
        facts.equal_radii >= 0 ? facts.equal_radii == 1 : std::all_of(r, r + n, [&](float x) { return x == r[0]; });
    if (n <= 32 && equal_radii) {
        // Equal radii: the smallest ball of the centres grown by r is the smallest enclosing ball.
        Eigen::Vector3d pts[32];
        for (size_t i = 0; i < n; ++i) pts[i] = c[i].cast<double>();
        add(smallest_ball(pts, n).center);
    }
    double radii[3];
    if (facts.farthest) facts.farthest->radii(candidates, m, equal_radii, radii);
    else enclosing_radii(candidates, m, c, r, n, equal_radii, radii);
    double rad = INFINITY;
    for (size_t k = 0; k < m; ++k) {
        const Eigen::Vector3d& cand = candidates[k];
        // Candidates hold float values, so the radius measured is the stored centre's.
        if (radii[k] < rad)
            rad = radii[k], node.center = Eigen::Vector3f(float(cand.x()), float(cand.y()), float(cand.z()));
    }
    node.bv_radius = round_up(rad);
}

} // namespace spt::detail
