#include "spt/slab.hpp"
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
    // Scalar volatile casts: GCC 12 with Eigen 3.4 folds x.cast<float>().cast<double>()
    // into x at -O2 (see bounds.cpp), which would measure along the wrong normal.
    n.normalize();
    volatile float fx = float(n.x()), fy = float(n.y()), fz = float(n.z());
    const float nf[3] = {fx, fy, fz};
    const Eigen::Vector3d nd{double(nf[0]), double(nf[1]), double(nf[2])};
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : points) {
        const double v = nd.dot(p);
        lo = std::min(lo, v), hi = std::max(hi, v);
    }
    const double d = 0.5 * (lo + hi);
    s.n[0] = nf[0], s.n[1] = nf[1], s.n[2] = nf[2];
    volatile float fd = float(d);
    s.d = fd;
    const double h = 0.5 * (hi - lo) + std::abs(double(fd) - d);
    s.h = std::nextafter(float(h * (1 + 1e-6)), std::numeric_limits<float>::infinity());
    return s;
}

} // namespace spt
