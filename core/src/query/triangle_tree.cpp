// Top-down median split on triangle centroids, across each node's longest box side; each node
// gets an oriented box and a bounding sphere around its centre, and is marked elongated or
// compact. Deterministic: std::nth_element with an index tie-break.
#include "query/triangle_tree.hpp"
#include "base/float_round.hpp"
#include "geometry/tri_tri.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {
namespace {

// Why these values (docs/queries.md, "How exact decides"): a walk over small compact nodes
// with cheap tests (sphere, one slab) is fastest on finely meshed surfaces; thin rods and
// needle triangles (FCL's env/rob pair) need whole boxes and a triangle a leaf.
constexpr uint32_t kLeafTriangles = 4; // most triangles in a leaf, all of them compact
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

} // namespace spt::detail
