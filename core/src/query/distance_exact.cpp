// Exact distance between two triangle soups: best-first branch and bound over pairs of nodes of
// their triangle trees, each pair's lower bound the largest of its bounding spheres' gap and the
// boxes' gaps along a few separating directions (a flat patch's box is far tighter than its
// sphere); leaves by triangle_gap after cheaper bounds of each triangle pair.
#include "query/distance_exact.hpp"
#include "query/best_first.hpp"
#include "geometry/tri_distance.hpp"
#include "query/exact_data.hpp"
#include "query/model_access.hpp"
#include "query/query_run.hpp"
#include "query/scratch.hpp"
#include "query/triangle_tree.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace spt::detail {
namespace {

Eigen::Vector3f v3(const float* p) { return {p[0], p[1], p[2]}; }

// Half the length of box `b`'s shadow on unit axis u.
float shadow(const Obb& b, const Eigen::Vector3f& u) {
    float s = 0;
    for (int k = 0; k < 3; ++k) s += std::abs(u.dot(v3(b.axis[k]))) * b.half[k];
    return s;
}

// The point of box `b` nearest to x.
Eigen::Vector3f clamp_into(const Obb& b, const Eigen::Vector3f& x) {
    const Eigen::Vector3f c = v3(b.center), d = x - c;
    Eigen::Vector3f p = c;
    for (int k = 0; k < 3; ++k) p += std::clamp(v3(b.axis[k]).dot(d), -b.half[k], b.half[k]) * v3(b.axis[k]);
    return p;
}

// A lower bound of the distance between the contents of boxes `a` and `b` (one frame), tightened
// step by step until it reaches `enough` (then no tighter bound is of use): their gap along their
// thinnest faces' normals, the line of centres, the line between a near point of each, then the
// other face normals.
float box_gap(const Obb& a, const Obb& b, float gap, float enough) {
    if (a.half[0] < 0 || b.half[0] < 0) return gap; // an empty box: leave it to the spheres
    const Eigen::Vector3f d = v3(b.center) - v3(a.center);
    auto along_face = [&](int k) { // each box's k-th face normal
        const Eigen::Vector3f u = v3(a.axis[k]), w = v3(b.axis[k]);
        gap = std::max(gap, std::abs(u.dot(d)) - a.half[k] - shadow(b, u));
        gap = std::max(gap, std::abs(w.dot(d)) - b.half[k] - shadow(a, w));
    };
    // A flat patch's own normal first (axis 0, of least spread): facing patches are told by it.
    along_face(0);
    if (gap >= enough) return gap;
    // The line of centres: boxes apart along a diagonal are told by it, not by a face.
    const float length = d.norm();
    if (length > 0) gap = std::max(gap, length - shadow(a, d / length) - shadow(b, d / length));
    if (gap >= enough) return gap;
    // B's centre clamped into A's box, that point clamped into B's: one step of alternating
    // projections, near the direction of the boxes' closest pair.
    const Eigen::Vector3f pa = clamp_into(a, v3(b.center)), pb = clamp_into(b, pa), e = pb - pa;
    if (const float n = e.norm(); n > 0) {
        const Eigen::Vector3f u = e / n;
        gap = std::max(gap, std::abs(u.dot(d)) - shadow(a, u) - shadow(b, u));
        if (gap >= enough) return gap;
    }
    along_face(1), along_face(2);
    return gap;
}

// A lower bound of the distance between a triangle with corners `t` and unit normal `n` and
// one with corners `u`: how far u lies beyond t's plane when all of u is on one side (0 if not).
double plane_gap(const Eigen::Vector3d* t, const Eigen::Vector3d& n, const Eigen::Vector3d* u) {
    const double h0 = n.dot(u[0] - t[0]), h1 = n.dot(u[1] - t[0]), h2 = n.dot(u[2] - t[0]);
    if (h0 > 0 && h1 > 0 && h2 > 0) return std::min({h0, h1, h2});
    if (h0 < 0 && h1 < 0 && h2 < 0) return -std::max({h0, h1, h2});
    return 0;
}

// A lower bound of the distance between triangles `t` and `u`: the gap between their shadows on
// the line through their centroids (each shadow is exact: its corners' extremes).
double centroid_gap(const Eigen::Vector3d* t, const Eigen::Vector3d* u) {
    const Eigen::Vector3d d = (u[0] + u[1] + u[2]) - (t[0] + t[1] + t[2]);
    const double t_far = std::max({d.dot(t[0]), d.dot(t[1]), d.dot(t[2])});
    const double u_near = std::min({d.dot(u[0]), d.dot(u[1]), d.dot(u[2])});
    const double n = d.norm();
    return n > 0 ? (u_near - t_far) / n : 0;
}

// A lower bound of the distance between box `other` and a leaf's triangles, each triangle lying
// in its plane (`plane_of`: unit normal and offset, ExactData::tri_plane; `pad`: how far off
// it): the least of the box's gaps from those planes, or `floor` if that is more. A curved
// patch's triangles tilt away from its box's slab, so their planes bound it more tightly.
template <class PlaneOf>
float planes_gap(const ExactData& e, const TriangleNode& leaf, const Obb& other, float pad, float floor,
                 PlaneOf&& plane_of) {
    const Eigen::Vector3f c = v3(other.center);
    float least = std::numeric_limits<float>::infinity();
    for (uint32_t k = 0; k < leaf.count && least > floor; ++k) {
        const float* p = plane_of(e.tri_order[leaf.first + k]);
        const Eigen::Vector3f n(p[0], p[1], p[2]);
        least = std::min(least, std::abs(n.dot(c) - p[3]) - shadow(other, n) - pad);
    }
    return std::max(floor, least);
}

// A lower bound of the distance between triangle-tree nodes na (A's) and nb (B's, box bb in A's
// frame) that the boxes leave in doubt (`gap` below `stop`), from a leaf's triangles' planes
// (where its model has them: not at a deformed pose). Out of line, so that the bound's common
// path stays small enough to inline. A plane along the leaf's slab axis tightens the slab by
// its thickness at most, so where more is needed the planes are not tried.
[[gnu::noinline]] float leaf_planes_gap(const ExactData& ea, const TriangleNode& na, const ExactData& eb,
                                        const TriangleNode& nb, const Obb& bb, MovedB& moved, float gap, float stop) {
    if (nb.is_leaf() && !eb.tri_plane.empty() && stop - gap < 2 * bb.half[0])
        gap = planes_gap(eb, nb, na.box(), eb.plane_pad, gap, [&](uint32_t t) { return moved.tri_plane(t); });
    if (gap < stop && na.is_leaf() && !ea.tri_plane.empty() && stop - gap < 2 * na.half[0])
        gap = planes_gap(ea, na, bb, ea.plane_pad, gap, [&](uint32_t t) { return &ea.tri_plane[4 * size_t(t)]; });
    return gap;
}

// A leaf's triangles, their corners (one frame), unit normals and bounding spheres.
struct LeafTriangles {
    static constexpr int kMost = int(kLeafTriangles);
    Eigen::Vector3d corner[kMost][3], normal[kMost];
    const float* sphere[kMost];
    int count = 0;
    template <class Vertex, class Sphere>
    void gather(const ExactData& e, const TriangleNode& leaf, Vertex&& vertex, Sphere&& sphere_of) {
        count = int(leaf.count); // at most kLeafTriangles (build_triangle_tree)
        for (int k = 0; k < count; ++k) {
            const uint32_t t = e.tri_order[leaf.first + uint32_t(k)];
            const Triangle& x = e.triangles[t];
            for (int c = 0; c < 3; ++c) corner[k][c] = vertex(x[c]);
            normal[k] = (corner[k][1] - corner[k][0]).cross(corner[k][2] - corner[k][0]).normalized();
            sphere[k] = sphere_of(t);
        }
    }
};

} // namespace

void exact_gap(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a, const DistanceOptions& options,
               QueryScratch& scratch, DistanceResult& res) {
    const ExactData &ea = exact_of(a), &eb = exact_of(b);
    const auto &an = ea.tri_nodes, &bn = eb.tri_nodes;
    res.beyond = true;
    if (an.empty() || bn.empty()) return;
    const QueryFrame f(a, b, b_in_a, 0);
    ScratchBuffers& s = buffers_of(scratch);
    prepare_scratch(s, a, b, true);
    detail::MovedB moved{s, eb, f}; // B's vertices, triangle spheres and boxes, where the walk needs them
    // Float bounds are lowered by the frame's rounding margin so that rounding never prunes the
    // nearest pair.
    // `enough`: a bound there prunes the pair, so the tightening stops.
    auto lower_bound = [&](uint32_t i, uint32_t j, double enough) {
        const Obb& bb = moved.tri_box(j);
        const float centres = (v3(an[i].center) - v3(bb.center)).norm() - an[i].radius - bn[j].radius;
        const float stop = float(std::min(enough, 1e30)) + f.margin;
        if (centres >= stop) return centres - f.margin;
        const float gap = box_gap(an[i].box(), bb, centres, stop);
        if (gap >= stop || !(an[i].is_leaf() || bn[j].is_leaf())) return gap - f.margin;
        return leaf_planes_gap(ea, an[i], eb, bn[j], bb, moved, gap, stop) - f.margin;
    };
    double best = options.max_distance;
    // A pair is worth a visit while it could beat the best by more than the allowances.
    const double keep = 1 - options.relative_error;
    auto worth = [&](double gap) { return gap < best * keep - options.absolute_error; };
    Eigen::Vector3d best_a, best_b;
    bool found = false;
    using Bound = ScratchBuffers::GapBound;
    BestFirst<float> open(s.gap_heap);
    ++res.counters.bound_tests;
    if (const float g = lower_bound(0, 0, best); g < best) open.push(g, 0, 0);
    for (Bound top; open.take(top);) {
        if (!worth(top.gap)) break;
        ++res.counters.node_pairs;
        const TriangleNode &na = an[top.a], &nb = bn[top.b];
        if (na.is_leaf() && nb.is_leaf()) {
            // Each leaf's triangles (at most kLeafTriangles) with their planes and spheres, made
            // once for the leaf pair's pairs: B's in A's frame.
            LeafTriangles la, lb;
            la.gather(ea, na, [&](uint32_t v) { return ea.positions[v]; },
                      [&](uint32_t t) { return &ea.tri_sphere[4 * size_t(t)]; });
            lb.gather(eb, nb, [&](uint32_t v) { return moved.vertex(v); }, [&](uint32_t t) { return moved.tri_sphere(t); });
            for (int p = 0; p < la.count; ++p)
                for (int q = 0; q < lb.count; ++q) {
                    const float *sa = la.sphere[p], *sb = lb.sphere[q];
                    if (!worth((v3(sa) - v3(sb)).norm() - sa[3] - sb[3] - f.margin)) continue;
                    ++res.counters.triangle_tests;
                    const Eigen::Vector3d *ta3 = la.corner[p], *tb3 = lb.corner[q];
                    // Facing patches are nearest corner to face: each plane's gap is then the
                    // distance itself; triangles side by side are told apart along the line of
                    // their centroids. Both at a fraction of the full test's cost.
                    if (!worth(std::max(plane_gap(ta3, la.normal[p], tb3), plane_gap(tb3, lb.normal[q], ta3)))) continue;
                    if (!worth(centroid_gap(ta3, tb3))) continue;
                    const TriangleGap g = triangle_gap(ta3[0], ta3[1], ta3[2], tb3[0], tb3[1], tb3[2], false, best);
                    if (g.distance < best) best = g.distance, best_a = g.p, best_b = g.q, found = true;
                }
            continue;
        }
        // Descend the larger sphere (a leaf never): both children of that side.
        const bool side_a = nb.is_leaf() || (!na.is_leaf() && na.radius >= nb.radius);
        const uint32_t first = side_a ? top.a + 1 : top.b + 1, second = side_a ? na.first : nb.first;
        Bound kids[2];
        int n = 0;
        for (uint32_t c : {first, second}) {
            const uint32_t i = side_a ? c : top.a, j = side_a ? top.b : c;
            ++res.counters.bound_tests;
            if (const float g = lower_bound(i, j, best * keep - options.absolute_error); worth(g)) kids[n++] = {g, i, j};
        }
        open.push_children(kids, n);
    }
    if (!found) return;
    res.beyond = false;
    res.distance = best;
    res.point_a = best_a + a.origin();
    res.point_b = best_b + a.origin();
}

} // namespace spt::detail
