// Smallest enclosing ball of points (Welzl) and of two balls.
#include "tree/miniball.hpp"
#include <Eigen/Dense>
#include <cmath>

namespace spt::detail {
namespace {

Ball ball_from(const Eigen::Vector3d* s, int n) {
    Ball b;
    if (n == 0) return b;
    if (n == 1) return {s[0], 0};
    if (n == 2) return {(s[0] + s[1]) / 2, (s[0] - s[1]).norm() / 2};
    if (n == 3) {
        const Eigen::Vector3d a = s[1] - s[0], c = s[2] - s[0];
        const Eigen::Vector3d axc = a.cross(c);
        const double d = 2 * axc.squaredNorm();
        if (d < 1e-30) { // collinear: the farthest pair decides
            Ball best = ball_from(s, 2);
            for (auto [i, j] : {std::pair{0, 2}, std::pair{1, 2}}) {
                const Eigen::Vector3d pair[2] = {s[i], s[j]};
                Ball t = ball_from(pair, 2);
                if (t.radius > best.radius) best = t;
            }
            return best;
        }
        const Eigen::Vector3d o = (c.squaredNorm() * axc.cross(a) + a.squaredNorm() * c.cross(axc)) / d;
        return {s[0] + o, o.norm()};
    }
    // Four points: solve 2 (p_i - p_0) . x = |p_i - p_0|^2.
    Eigen::Matrix3d m;
    Eigen::Vector3d rhs;
    for (int i = 1; i < 4; ++i) {
        const Eigen::Vector3d d = s[i] - s[0];
        m.row(i - 1) = 2 * d.transpose();
        rhs(i - 1) = d.squaredNorm();
    }
    if (std::abs(m.determinant()) < 1e-30) return ball_from(s, 3);
    const Eigen::Vector3d o = m.partialPivLu().solve(rhs);
    return {s[0] + o, o.norm()};
}

bool inside(const Ball& b, const Eigen::Vector3d& p) {
    return b.radius >= 0 && (p - b.center).norm() <= b.radius * (1 + 1e-12) + 1e-15;
}

Ball welzl(Eigen::Vector3d* p, size_t n, Eigen::Vector3d* support, int ns) {
    Ball b = ball_from(support, ns);
    if (ns == 4) return b;
    for (size_t i = 0; i < n; ++i) {
        if (inside(b, p[i])) continue;
        support[ns] = p[i];
        b = welzl(p, i, support, ns + 1);
        // Move-to-front keeps the expected time linear.
        const Eigen::Vector3d q = p[i];
        for (size_t k = i; k > 0; --k) p[k] = p[k - 1];
        p[0] = q;
    }
    return b;
}

} // namespace

Ball smallest_ball(Eigen::Vector3d* points, size_t n) {
    Eigen::Vector3d support[4];
    return welzl(points, n, support, 0);
}

Ball merge_balls(const Ball& a, const Ball& b) {
    if (a.radius < 0) return b;
    if (b.radius < 0) return a;
    const Eigen::Vector3d d = b.center - a.center;
    const double dist = d.norm();
    if (dist + b.radius <= a.radius) return a;
    if (dist + a.radius <= b.radius) return b;
    const double r = (dist + a.radius + b.radius) / 2;
    return {a.center + d * ((r - a.radius) / dist), r};
}

} // namespace spt::detail
