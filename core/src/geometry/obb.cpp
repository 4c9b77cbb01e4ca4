// Oriented bounding boxes: principal-axis fit rounded outwards, face-axis separation test in float.
#include "geometry/obb.hpp"
#include "base/float_round.hpp"
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

namespace spt {

Obb fit_obb_along(const std::vector<Eigen::Vector3d>& points, const float af[2][3]) {
    Obb box;
    if (points.empty()) return box;
    // Extents are measured along the float axes actually stored, around the stored centre.
    // The third axis is the float cross product of the first two (see third_axis), so that a
    // node can store two axes and rebuild the third bit for bit.
    Eigen::Vector3d a[3], lo, hi;
    for (int k = 0; k < 3; ++k) {
        a[k] = k < 2 ? Eigen::Vector3d(af[k][0], af[k][1], af[k][2]) : third_axis(af[0], af[1]).cast<double>();
        lo[k] = std::numeric_limits<double>::infinity(), hi[k] = -lo[k];
        for (const auto& p : points) {
            const double v = a[k].dot(p);
            lo[k] = std::min(lo[k], v), hi[k] = std::max(hi[k], v);
        }
    }
    // Centre from the middle of each extent; then every point's offset along each axis.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) centre += 0.5 * (lo[k] + hi[k]) * a[k];
    const Eigen::Vector3d c = detail::float_rounded(centre);
    for (int k = 0; k < 3; ++k) {
        double h = 0;
        for (const auto& p : points) h = std::max(h, std::abs(a[k].dot(p - c)));
        box.center[k] = float(c[k]);
        for (int j = 0; j < 3; ++j) box.axis[k][j] = float(a[k][j]);
        box.half[k] = detail::round_up(h);
    }
    return box;
}

Obb fit_obb(const std::vector<Eigen::Vector3d>& points) {
    Obb box;
    if (points.empty()) return box;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : points) mean += p;
    mean /= double(points.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : points) cov += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    Eigen::Matrix3d axes = eig.eigenvectors(); // columns; a right-handed orthonormal basis
    if (!axes.allFinite() || std::abs(axes.determinant()) < 0.5) axes.setIdentity();
    float af[2][3];
    for (int k = 0; k < 2; ++k) {
        const Eigen::Vector3d a = detail::float_rounded(axes.col(k).normalized());
        for (int j = 0; j < 3; ++j) af[k][j] = float(a[j]);
    }
    return fit_obb_along(points, af);
}

bool obbs_disjoint(const Obb& a, const Obb& b, const Eigen::Matrix3f& R, const Eigen::Vector3f& t, float margin) {
    return obbs_disjoint(a, placed(b, R, t), margin);
}

} // namespace spt
