// Exact orientation predicates. The filter bounds are Shewchuk's (1997) for the
// same formulation; the exact path expands every difference and product into
// non-overlapping expansions, so no rounding is left when the sign is read.
#include "geometry/predicates.hpp"
#include <cmath>

namespace spt {
namespace {

constexpr double kEps = 1.1102230246251565e-16; // 2^-53
constexpr double kO3dBound = (7.0 + 56.0 * kEps) * kEps;
constexpr double kO2dBound = (3.0 + 16.0 * kEps) * kEps;

// Fixed-capacity expansion: no allocation, ever. 3x3 determinants of exact
// differences need at most 6 * 32 components.
struct Expansion {
    static constexpr int kCap = 256;
    double v[kCap];
    int n = 0;
    void push(double x) {
        if (x != 0) v[n++] = x;
    }
    int sign() const { return n == 0 ? 0 : (v[n - 1] > 0 ? 1 : -1); }
};

inline void two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    const double bv = x - a, av = x - bv;
    y = (a - av) + (b - bv);
}
inline void fast_two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    y = b - (x - a);
}
inline void two_diff(double a, double b, double& x, double& y) {
    x = a - b;
    const double bv = a - x, av = x + bv;
    y = (a - av) + (bv - b);
}
inline void two_product(double a, double b, double& x, double& y) {
    x = a * b;
    y = std::fma(a, b, -x); // exact error term of the product
}

// h = e + b (Shewchuk's GROW-EXPANSION with zero elimination).
void grow(const Expansion& e, double b, Expansion& h) {
    h.n = 0;
    double q = b;
    for (int i = 0; i < e.n; ++i) {
        double s, err;
        two_sum(q, e.v[i], s, err);
        h.push(err);
        q = s;
    }
    if (q != 0 || h.n == 0) h.v[h.n++] = q;
    if (h.n == 1 && h.v[0] == 0) h.n = 0;
}

// acc += e, keeping acc a non-overlapping expansion.
void add_to(Expansion& acc, const Expansion& e, Expansion& tmp) {
    for (int i = 0; i < e.n; ++i) {
        grow(acc, e.v[i], tmp);
        acc = tmp;
    }
}

// h = e * b (SCALE-EXPANSION with zero elimination).
void scale(const Expansion& e, double b, Expansion& h) {
    h.n = 0;
    if (e.n == 0 || b == 0) return;
    double q, hh;
    two_product(e.v[0], b, q, hh);
    h.push(hh);
    for (int i = 1; i < e.n; ++i) {
        double p1, p0, sum;
        two_product(e.v[i], b, p1, p0);
        two_sum(q, p0, sum, hh);
        h.push(hh);
        fast_two_sum(p1, sum, q, hh);
        h.push(hh);
    }
    h.push(q);
}

// h = e * f.
void multiply(const Expansion& e, const Expansion& f, Expansion& h) {
    h.n = 0;
    Expansion part, tmp;
    for (int i = 0; i < f.n; ++i) {
        scale(e, f.v[i], part);
        add_to(h, part, tmp);
    }
}

Expansion diff(double a, double b) {
    Expansion e;
    double x, y;
    two_diff(a, b, x, y);
    e.push(y);
    e.push(x);
    return e;
}

} // namespace

int orient3d_exact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, const Eigen::Vector3d& d) {
    // det [b-a; c-a; d-a] by cofactor expansion along the first row.
    const Expansion ux = diff(b.x(), a.x()), uy = diff(b.y(), a.y()), uz = diff(b.z(), a.z());
    const Expansion vx = diff(c.x(), a.x()), vy = diff(c.y(), a.y()), vz = diff(c.z(), a.z());
    const Expansion wx = diff(d.x(), a.x()), wy = diff(d.y(), a.y()), wz = diff(d.z(), a.z());
    Expansion det, t1, t2, tmp;
    auto add_term = [&](const Expansion& p, const Expansion& q, const Expansion& r, bool negate) {
        multiply(p, q, t1);
        multiply(t1, r, t2);
        if (negate)
            for (int i = 0; i < t2.n; ++i) t2.v[i] = -t2.v[i];
        add_to(det, t2, tmp);
    };
    add_term(ux, vy, wz, false);
    add_term(ux, vz, wy, true);
    add_term(uy, vz, wx, false);
    add_term(uy, vx, wz, true);
    add_term(uz, vx, wy, false);
    add_term(uz, vy, wx, true);
    return det.sign();
}

int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, const Eigen::Vector3d& d) {
    const double ux = b.x() - a.x(), uy = b.y() - a.y(), uz = b.z() - a.z();
    const double vx = c.x() - a.x(), vy = c.y() - a.y(), vz = c.z() - a.z();
    const double wx = d.x() - a.x(), wy = d.y() - a.y(), wz = d.z() - a.z();
    const double vywz = vy * wz, vzwy = vz * wy;
    const double vzwx = vz * wx, vxwz = vx * wz;
    const double vxwy = vx * wy, vywx = vy * wx;
    const double det = ux * (vywz - vzwy) + uy * (vzwx - vxwz) + uz * (vxwy - vywx);
    const double permanent = (std::abs(vywz) + std::abs(vzwy)) * std::abs(ux) +
                             (std::abs(vzwx) + std::abs(vxwz)) * std::abs(uy) +
                             (std::abs(vxwy) + std::abs(vywx)) * std::abs(uz);
    const double bound = kO3dBound * permanent;
    if (det > bound) return 1;
    if (-det > bound) return -1;
    return orient3d_exact(a, b, c, d);
}

int orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    const double l = (b.x() - a.x()) * (c.y() - a.y());
    const double r = (b.y() - a.y()) * (c.x() - a.x());
    const double det = l - r;
    const double bound = kO2dBound * (std::abs(l) + std::abs(r));
    if (det > bound) return 1;
    if (-det > bound) return -1;
    const Expansion ux = diff(b.x(), a.x()), uy = diff(b.y(), a.y());
    const Expansion vx = diff(c.x(), a.x()), vy = diff(c.y(), a.y());
    Expansion p, q, tmp;
    multiply(ux, vy, p);
    multiply(uy, vx, q);
    for (int i = 0; i < q.n; ++i) q.v[i] = -q.v[i];
    add_to(p, q, tmp);
    return p.sign();
}

} // namespace spt
