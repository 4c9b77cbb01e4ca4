// Top-down median split on triangle centroids, across each node's longest box side; each node
// gets an oriented box and a bounding sphere around its centre, and is marked elongated or
// compact. Deterministic: std::nth_element with an index tie-break.
#include "query/triangle_tree.hpp"
#include "base/float_round.hpp"
#include "geometry/tri_tri.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace spt::detail {
namespace {

// Why these values (docs/queries.md, "How exact decides"): a walk over small compact nodes
// with cheap tests (sphere, one slab) is fastest on finely meshed surfaces; thin rods and
// needle triangles (FCL's env/rob pair) need whole boxes and a triangle a leaf.
constexpr double kCompactTriangle = 0.25; // compact: twice the area >= this * longest edge^2 (height >= 1/4 of it)
constexpr float kElongatedNode = 0.3f;    // elongated: the box's middle half extent < this * the sphere's radius
constexpr float kFlatLeaf = 0.1f;         // several triangles a leaf only if the box's thinnest half extent < this * radius

struct Builder {
    ExactData& e;
    std::vector<Eigen::Vector3d> centroid;
    std::vector<uint8_t> compact; // per triangle
    std::vector<Eigen::Vector3d> corners; // reused per node

    // Box of tri_order[begin, end), the bounding sphere around the box's centre, and whether
    // the node is elongated.
    TriangleNode bound(uint32_t begin, uint32_t end) {
        corners.clear();
        for (uint32_t k = begin; k < end; ++k)
            for (uint32_t v : e.triangles[e.tri_order[k]]) corners.push_back(e.positions[v]);
        const Obb box = fit_obb(corners);
        TriangleNode n;
        const Eigen::Vector3d c(box.center[0], box.center[1], box.center[2]); // the stored floats
        double r = 0;
        for (const auto& p : corners) r = std::max(r, (p - c).norm());
        n.radius = round_up(r);
        for (int k = 0; k < 3; ++k) {
            n.center[k] = box.center[k], n.half[k] = box.half[k];
            n.axis[0][k] = box.axis[0][k], n.axis[1][k] = box.axis[1][k];
        }
        float h[3] = {box.half[0], box.half[1], box.half[2]};
        std::sort(h, h + 3);
        n.boxed = h[1] < kElongatedNode * n.radius;
        return n;
    }

    // A leaf: one triangle, or up to kLeafTriangles compact ones in a compact, flat node (a
    // patch of one surface). Within a leaf, triangle pairs are told apart by the triangles'
    // own spheres only, which fit compact triangles and not needles, and a leaf's box fits
    // a patch and not a handful of triangles at random angles.
    bool leaf(const TriangleNode& n, uint32_t begin, uint32_t end) const {
        if (end - begin <= 1) return true;
        if (end - begin > kLeafTriangles || n.boxed) return false;
        const float thinnest = std::min({n.half[0], n.half[1], n.half[2]});
        if (thinnest >= kFlatLeaf * n.radius) return false; // not a patch of one surface (a soup)
        for (uint32_t k = begin; k < end; ++k)
            if (!compact[e.tri_order[k]]) return false;
        return true;
    }

    void build(uint32_t begin, uint32_t end) {
        const uint32_t self = uint32_t(e.tri_nodes.size());
        e.tri_nodes.push_back(bound(begin, end));
        if (leaf(e.tri_nodes[self], begin, end)) {
            e.tri_nodes[self].first = begin, e.tri_nodes[self].count = end - begin;
            return;
        }
        // Split across the box's longest side, at the median centroid along it.
        const Obb box = e.tri_nodes[self].box();
        int longest = 0;
        for (int k = 1; k < 3; ++k)
            if (box.half[k] > box.half[longest]) longest = k;
        const Eigen::Vector3d axis(box.axis[longest][0], box.axis[longest][1], box.axis[longest][2]);
        const uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(e.tri_order.begin() + begin, e.tri_order.begin() + mid, e.tri_order.begin() + end,
                         [&](uint32_t a, uint32_t b) {
                             const double ca = axis.dot(centroid[a]), cb = axis.dot(centroid[b]);
                             return ca < cb || (ca == cb && a < b);
                         });
        build(begin, mid); // left child follows its parent
        e.tri_nodes[self].first = uint32_t(e.tri_nodes.size());
        e.tri_nodes[self].count = 0;
        build(mid, end);
    }
};

} // namespace

void build_triangle_tree(ExactData& e) {
    e.tri_nodes.clear();
    e.tri_order.clear();
    e.degenerate_triangles = 0;
    Builder b{e, {}, {}, {}};
    b.centroid.resize(e.triangles.size());
    b.compact.resize(e.triangles.size());
    for (uint32_t f = 0; f < e.triangles.size(); ++f) {
        const auto& t = e.triangles[f];
        const Eigen::Vector3d &p = e.positions[t[0]], &q = e.positions[t[1]], &r = e.positions[t[2]];
        b.centroid[f] = (p + q + r) / 3.0;
        const double longest2 = std::max({(q - p).squaredNorm(), (r - q).squaredNorm(), (p - r).squaredNorm()});
        b.compact[f] = (q - p).cross(r - p).norm() >= kCompactTriangle * longest2;
        if (is_degenerate_triangle(p, q, r)) ++e.degenerate_triangles;
        else e.tri_order.push_back(f);
    }
    if (e.tri_order.empty()) return;
    e.tri_nodes.reserve(2 * e.tri_order.size());
    b.build(0, uint32_t(e.tri_order.size()));
}

void refit_triangle_tree(ExactData& e) {
    std::vector<Eigen::Vector3d> corners;
    // Children follow their parent: from the last node back, every child is refit before its parent.
    for (size_t i = e.tri_nodes.size(); i-- > 0;) {
        TriangleNode& n = e.tri_nodes[i];
        if (n.is_leaf()) {
            corners.clear();
            for (uint32_t k = n.first; k < n.first + n.count; ++k)
                for (uint32_t v : e.triangles[e.tri_order[k]]) corners.push_back(e.positions[v]);
            const Obb box = fit_obb_along(corners, n.axis);
            const Eigen::Vector3d c(box.center[0], box.center[1], box.center[2]);
            double r = 0;
            for (const auto& p : corners) r = std::max(r, (p - c).norm());
            for (int k = 0; k < 3; ++k) n.center[k] = box.center[k], n.half[k] = box.half[k];
            n.radius = round_up(r);
            continue;
        }
        // An inner node holds its children's boxes: each child's extent along the node's axis k
        // is its centre's projection plus the sum of its half extents times |axis k . its axis j|.
        const Eigen::Vector3f w = third_axis(n.axis[0], n.axis[1]);
        const Eigen::Vector3d axis[3] = {Eigen::Vector3d(n.axis[0][0], n.axis[0][1], n.axis[0][2]),
                                         Eigen::Vector3d(n.axis[1][0], n.axis[1][1], n.axis[1][2]), w.cast<double>()};
        struct Child {
            Eigen::Vector3d c;
            double ext[3], half_norm, radius;
        } child[2];
        const uint32_t ids[2] = {uint32_t(i + 1), n.first};
        const double inf = std::numeric_limits<double>::infinity();
        double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
        for (int h = 0; h < 2; ++h) {
            const TriangleNode& m = e.tri_nodes[ids[h]];
            const Eigen::Vector3f mw = third_axis(m.axis[0], m.axis[1]);
            const Eigen::Vector3d u[3] = {Eigen::Vector3d(m.axis[0][0], m.axis[0][1], m.axis[0][2]),
                                          Eigen::Vector3d(m.axis[1][0], m.axis[1][1], m.axis[1][2]), mw.cast<double>()};
            Child& ch = child[h];
            ch.c = Eigen::Vector3d(m.center[0], m.center[1], m.center[2]);
            ch.half_norm = Eigen::Vector3d(m.half[0], m.half[1], m.half[2]).norm();
            ch.radius = m.radius;
            for (int k = 0; k < 3; ++k) {
                ch.ext[k] = 0;
                for (int j = 0; j < 3; ++j) ch.ext[k] += double(m.half[j]) * std::abs(axis[k].dot(u[j]));
                const double at = axis[k].dot(ch.c);
                lo[k] = std::min(lo[k], at - ch.ext[k]);
                hi[k] = std::max(hi[k], at + ch.ext[k]);
            }
        }
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        for (int k = 0; k < 3; ++k) centre += 0.5 * (lo[k] + hi[k]) * axis[k];
        const Eigen::Vector3d c = float_rounded(centre);
        double balls = 0, boxes = 0;
        for (int k = 0; k < 3; ++k) {
            double h = 0;
            for (const Child& ch : child) h = std::max(h, std::abs(axis[k].dot(ch.c - c)) + ch.ext[k]);
            n.center[k] = float(c[k]);
            n.half[k] = round_up(h);
        }
        // The children's balls, or the corners of their boxes, whichever is tighter.
        for (const Child& ch : child) {
            balls = std::max(balls, (ch.c - c).norm() + ch.radius);
            boxes = std::max(boxes, (ch.c - c).norm() + ch.half_norm);
        }
        n.radius = round_up(std::min(balls, boxes));
    }
}

} // namespace spt::detail
