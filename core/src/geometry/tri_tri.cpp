// Guigue-Devillers triangle-triangle overlap test with every sign taken from the
// exact predicates. The permutation tables follow the paper: first bring the
// vertex of each triangle that is alone on its side of the other's plane to
// the front, then two orientation tests decide whether the intervals on the
// line of intersection overlap.
#include "geometry/tri_tri.hpp"
#include "geometry/predicates.hpp"
#include <cmath>

namespace spt {
namespace {

using V3 = Eigen::Vector3d;
using V2 = Eigen::Vector2d;

bool check_min_max(const V3& p1, const V3& q1, const V3& r1, const V3& p2, const V3& q2, const V3& r2) {
    if (orient3d(q1, p2, p1, q2) > 0) return false;
    if (orient3d(p1, p2, r1, r2) > 0) return false;
    return true;
}

bool segments_intersect_2d(const V2& a, const V2& b, const V2& c, const V2& d) {
    const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d), o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    auto on_segment = [](const V2& p, const V2& q, const V2& x) { // x collinear with pq
        return std::min(p.x(), q.x()) <= x.x() && x.x() <= std::max(p.x(), q.x()) &&
               std::min(p.y(), q.y()) <= x.y() && x.y() <= std::max(p.y(), q.y());
    };
    if (o1 == 0 && on_segment(a, b, c)) return true;
    if (o2 == 0 && on_segment(a, b, d)) return true;
    if (o3 == 0 && on_segment(c, d, a)) return true;
    if (o4 == 0 && on_segment(c, d, b)) return true;
    return false;
}

bool point_in_triangle_2d(const V2& x, const V2& a, const V2& b, const V2& c) {
    const int s1 = orient2d(a, b, x), s2 = orient2d(b, c, x), s3 = orient2d(c, a, x);
    const bool has_neg = s1 < 0 || s2 < 0 || s3 < 0, has_pos = s1 > 0 || s2 > 0 || s3 > 0;
    return !(has_neg && has_pos);
}

// Coplanar triangles: project onto the coordinate plane the normal is most
// aligned with (the projection is then one-to-one on the plane) and test edges
// and containment with exact 2D orientations.
bool coplanar_intersect(const V3& p1, const V3& q1, const V3& r1, const V3& p2, const V3& q2, const V3& r2) {
    const V3 n = (q1 - p1).cross(r1 - p1).cwiseAbs();
    int drop = 2;
    if (n.x() >= n.y() && n.x() >= n.z()) drop = 0;
    else if (n.y() >= n.z()) drop = 1;
    const int i = drop == 0 ? 1 : 0, j = drop == 2 ? 1 : 2;
    const V2 a[3] = {{p1[i], p1[j]}, {q1[i], q1[j]}, {r1[i], r1[j]}};
    const V2 b[3] = {{p2[i], p2[j]}, {q2[i], q2[j]}, {r2[i], r2[j]}};
    for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
            if (segments_intersect_2d(a[k], a[(k + 1) % 3], b[l], b[(l + 1) % 3])) return true;
    return point_in_triangle_2d(a[0], b[0], b[1], b[2]) || point_in_triangle_2d(b[0], a[0], a[1], a[2]);
}

bool tri_tri_3d(const V3& p1, const V3& q1, const V3& r1, const V3& p2, const V3& q2, const V3& r2, int dp2, int dq2,
                int dr2, const V3* coplanar[6]) {
    if (dp2 > 0) {
        if (dq2 > 0) return check_min_max(p1, r1, q1, r2, p2, q2);
        if (dr2 > 0) return check_min_max(p1, r1, q1, q2, r2, p2);
        return check_min_max(p1, q1, r1, p2, q2, r2);
    }
    if (dp2 < 0) {
        if (dq2 < 0) return check_min_max(p1, q1, r1, r2, p2, q2);
        if (dr2 < 0) return check_min_max(p1, q1, r1, q2, r2, p2);
        return check_min_max(p1, r1, q1, p2, q2, r2);
    }
    if (dq2 < 0) {
        if (dr2 >= 0) return check_min_max(p1, r1, q1, q2, r2, p2);
        return check_min_max(p1, q1, r1, p2, q2, r2);
    }
    if (dq2 > 0) {
        if (dr2 > 0) return check_min_max(p1, r1, q1, p2, q2, r2);
        return check_min_max(p1, q1, r1, q2, r2, p2);
    }
    if (dr2 > 0) return check_min_max(p1, q1, r1, r2, p2, q2);
    if (dr2 < 0) return check_min_max(p1, r1, q1, r2, p2, q2);
    return coplanar_intersect(*coplanar[0], *coplanar[1], *coplanar[2], *coplanar[3], *coplanar[4], *coplanar[5]);
}

} // namespace

bool is_degenerate_triangle(const V3& a, const V3& b, const V3& c) {
    // Collinear exactly when every coordinate-plane projection is collinear.
    return orient2d({a.x(), a.y()}, {b.x(), b.y()}, {c.x(), c.y()}) == 0 &&
           orient2d({a.y(), a.z()}, {b.y(), b.z()}, {c.y(), c.z()}) == 0 &&
           orient2d({a.z(), a.x()}, {b.z(), b.x()}, {c.z(), c.x()}) == 0;
}

bool triangles_intersect(const V3& p1, const V3& q1, const V3& r1, const V3& p2, const V3& q2, const V3& r2) {
    const int dp1 = orient3d(p2, q2, r2, p1), dq1 = orient3d(p2, q2, r2, q1), dr1 = orient3d(p2, q2, r2, r1);
    if (dp1 * dq1 > 0 && dp1 * dr1 > 0) return false;
    const int dp2 = orient3d(p1, q1, r1, p2), dq2 = orient3d(p1, q1, r1, q2), dr2 = orient3d(p1, q1, r1, r2);
    if (dp2 * dq2 > 0 && dp2 * dr2 > 0) return false;
    // All-zero orientations also come from a degenerate triangle; the plane tests
    // above mean nothing then, so rule those out before trusting them.
    if ((dp1 == 0 && dq1 == 0 && dr1 == 0 && is_degenerate_triangle(p2, q2, r2)) ||
        (dp2 == 0 && dq2 == 0 && dr2 == 0 && is_degenerate_triangle(p1, q1, r1)))
        return false;
    const V3* cop[6] = {&p1, &q1, &r1, &p2, &q2, &r2};
    if (dp1 > 0) {
        if (dq1 > 0) return tri_tri_3d(r1, p1, q1, p2, r2, q2, dp2, dr2, dq2, cop);
        if (dr1 > 0) return tri_tri_3d(q1, r1, p1, p2, r2, q2, dp2, dr2, dq2, cop);
        return tri_tri_3d(p1, q1, r1, p2, q2, r2, dp2, dq2, dr2, cop);
    }
    if (dp1 < 0) {
        if (dq1 < 0) return tri_tri_3d(r1, p1, q1, p2, q2, r2, dp2, dq2, dr2, cop);
        if (dr1 < 0) return tri_tri_3d(q1, r1, p1, p2, q2, r2, dp2, dq2, dr2, cop);
        return tri_tri_3d(p1, q1, r1, p2, r2, q2, dp2, dr2, dq2, cop);
    }
    if (dq1 < 0) {
        if (dr1 >= 0) return tri_tri_3d(q1, r1, p1, p2, r2, q2, dp2, dr2, dq2, cop);
        return tri_tri_3d(p1, q1, r1, p2, q2, r2, dp2, dq2, dr2, cop);
    }
    if (dq1 > 0) {
        if (dr1 > 0) return tri_tri_3d(p1, q1, r1, p2, r2, q2, dp2, dr2, dq2, cop);
        return tri_tri_3d(q1, r1, p1, p2, q2, r2, dp2, dq2, dr2, cop);
    }
    if (dr1 > 0) return tri_tri_3d(r1, p1, q1, p2, q2, r2, dp2, dq2, dr2, cop);
    if (dr1 < 0) return tri_tri_3d(r1, p1, q1, p2, r2, q2, dp2, dr2, dq2, cop);
    return coplanar_intersect(p1, q1, r1, p2, q2, r2);
}

} // namespace spt
