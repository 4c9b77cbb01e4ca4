// Triangle-triangle distance. Two disjoint triangles are nearest either between two edges or
// between a corner of one and the face of the other, so the smallest of the nine edge pairs and
// the six corner-face distances is the answer; triangles that meet are told apart first by the
// exact test (the features alone would miss one triangle piercing the other).
#include "geometry/tri_distance.hpp"
#include "geometry/tri_tri.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace spt {

using V3 = Eigen::Vector3d;

double segment_closest_parameter(const V3& p0, const V3& p1, const V3& x) {
    const V3 d = p1 - p0;
    const double dd = d.squaredNorm();
    if (!(dd > 0)) return 0;
    return std::clamp((x - p0).dot(d) / dd, 0.0, 1.0);
}

double segments_closest(const V3& p0, const V3& p1, const V3& q0, const V3& q1, double& s, double& t) {
    // Ericson, Real-Time Collision Detection 5.1.9, with each degenerate case on its own branch.
    const V3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    if (!(a > 0) && !(e > 0)) {
        s = t = 0;
    } else if (!(a > 0)) {
        s = 0, t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = d1.dot(r);
        if (!(e > 0)) {
            t = 0, s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = d1.dot(d2), denom = a * e - b * b;
            // Parallel (denom ~ 0): any s works; take p0's end and let t follow.
            s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0) t = 0, s = std::clamp(-c / a, 0.0, 1.0);
            else if (t > 1) t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
        }
    }
    return (p0 + s * d1 - (q0 + t * d2)).squaredNorm();
}

V3 triangle_closest_point(const V3& a, const V3& b, const V3& c, const V3& x) {
    // Ericson 5.1.5: which Voronoi region of the triangle holds x.
    const V3 ab = b - a, ac = c - a, ax = x - a;
    const double d1 = ab.dot(ax), d2 = ac.dot(ax);
    if (d1 <= 0 && d2 <= 0) return a;
    const V3 bx = x - b;
    const double d3 = ab.dot(bx), d4 = ac.dot(bx);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
    const V3 cx = x - c;
    const double d5 = ab.dot(cx), d6 = ac.dot(cx);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double sum = va + vb + vc;
    if (!(std::abs(sum) > 0)) { // zero area: the nearest of its edges
        V3 best = a;
        double best_d = (x - a).squaredNorm();
        for (const auto& [p, q] : {std::pair<V3, V3>{a, b}, {b, c}, {c, a}}) {
            const V3 y = p + segment_closest_parameter(p, q, x) * (q - p);
            if (const double d = (x - y).squaredNorm(); d < best_d) best_d = d, best = y;
        }
        return best;
    }
    const double v = vb / sum, w = vc / sum;
    return a + ab * v + ac * w;
}

namespace {

// Where segment [p, q] crosses the plane of (a, b, c), if it does and the triangle is not flat.
bool crossing_point(const V3& p, const V3& q, const V3& a, const V3& b, const V3& c, V3& out) {
    const V3 n = (b - a).cross(c - a);
    const double dp = n.dot(p - a), dq = n.dot(q - a);
    if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) return false;
    out = p + (dp / (dp - dq)) * (q - p);
    return true;
}

} // namespace

TriangleGap triangle_gap(const V3& a0, const V3& a1, const V3& a2, const V3& b0, const V3& b1, const V3& b2,
                         bool may_meet, double limit) {
    const V3 A[3] = {a0, a1, a2}, B[3] = {b0, b1, b2};
    TriangleGap g;
    // Features are skipped by cheap bounds against the nearest so far (or the caller's limit):
    // a corner's distance to a plane bounds its distance to the face, an edge's ball (its middle,
    // half its length) bounds its distance to another edge.
    double best = limit < std::numeric_limits<double>::infinity() ? limit * limit : limit;
    double reach = limit; // sqrt(best)
    g.p = a0, g.q = b0;
    auto keep = [&](double d2, const V3& p, const V3& q) {
        if (d2 < best) best = d2, reach = std::sqrt(d2), g.p = p, g.q = q;
    };
    const V3 na = (a1 - a0).cross(a2 - a0), nb = (b1 - b0).cross(b2 - b0);
    const double la = na.norm(), lb = nb.norm();
    for (int i = 0; i < 3; ++i) {
        if (!(lb > 0) || std::abs(nb.dot(A[i] - b0)) < reach * lb) {
            const V3 y = triangle_closest_point(b0, b1, b2, A[i]);
            keep((A[i] - y).squaredNorm(), A[i], y);
        }
        if (!(la > 0) || std::abs(na.dot(B[i] - a0)) < reach * la) {
            const V3 x = triangle_closest_point(a0, a1, a2, B[i]);
            keep((B[i] - x).squaredNorm(), x, B[i]);
        }
    }
    V3 ma[3], mb[3];
    double ha[3], hb[3];
    for (int i = 0; i < 3; ++i) {
        ma[i] = 0.5 * (A[i] + A[(i + 1) % 3]), ha[i] = 0.5 * (A[(i + 1) % 3] - A[i]).norm();
        mb[i] = 0.5 * (B[i] + B[(i + 1) % 3]), hb[i] = 0.5 * (B[(i + 1) % 3] - B[i]).norm();
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double r = reach + ha[i] + hb[j];
            if ((ma[i] - mb[j]).squaredNorm() >= r * r) continue;
            double s = 0, t = 0;
            const V3 &p0 = A[i], &p1 = A[(i + 1) % 3], &q0 = B[j], &q1 = B[(j + 1) % 3];
            const double d2 = segments_closest(p0, p1, q0, q1, s, t);
            keep(d2, p0 + s * (p1 - p0), q0 + t * (q1 - q0));
        }
    g.distance = std::sqrt(best);
    if (may_meet && g.distance > 0 && triangles_intersect(a0, a1, a2, b0, b1, b2)) {
        // One pierces the other: an edge's crossing of the other's plane that lies in that
        // triangle is a common point (the features' minimum need not be 0 here).
        g.distance = 0;
        double nearest = std::numeric_limits<double>::infinity();
        auto pierce = [&](const V3* T, const V3* U) {
            for (int i = 0; i < 3; ++i) {
                V3 x;
                if (!crossing_point(T[i], T[(i + 1) % 3], U[0], U[1], U[2], x)) continue;
                const double d = (triangle_closest_point(U[0], U[1], U[2], x) - x).squaredNorm();
                if (d < nearest) nearest = d, g.p = g.q = x;
            }
        };
        pierce(A, B);
        pierce(B, A);
    }
    return g;
}

} // namespace spt
