// Thinnest slab of a point set (least-spread principal axis), rounded outwards to float.
#include "geometry/slab.hpp"
#include "base/float_round.hpp"
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

namespace spt {

Slab fit_slab(const std::vector<Eigen::Vector3d>& points) {
    Slab s;
    if (points.empty()) return s;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : points) mean += p;
    mean /= double(points.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : points) cov += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    Eigen::Vector3d n = eig.eigenvectors().col(0); // smallest eigenvalue first
    if (!n.allFinite() || n.norm() < 0.5) n = Eigen::Vector3d::UnitZ();
    // Measure the extent along the float normal actually stored, so the float test holds.
    const Eigen::Vector3d nd = detail::float_rounded(n.normalized());
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : points) {
        const double v = nd.dot(p);
        lo = std::min(lo, v), hi = std::max(hi, v);
    }
    const double d = 0.5 * (lo + hi);
    s.n[0] = float(nd.x()), s.n[1] = float(nd.y()), s.n[2] = float(nd.z());
    s.d = detail::to_float(d);
    s.h = detail::round_up(0.5 * (hi - lo) + std::abs(double(s.d) - d));
    return s;
}

} // namespace spt
