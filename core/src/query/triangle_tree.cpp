// Top-down median split on triangle centroids, longest axis first; each node gets a
// bounding sphere and an oriented box. Deterministic: std::nth_element with an index tie-break.
#include "query/triangle_tree.hpp"
#include "base/float_round.hpp"
#include "geometry/tri_tri.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {
namespace {

constexpr uint32_t kLeafTriangles = 1;

struct Builder {
    ExactData& e;
    std::vector<Eigen::Vector3d> centroid;
    std::vector<Eigen::Vector3d> corners; // reused per node

    // Bounding sphere and box of tri_order[begin, end).
    TriangleNode bound(uint32_t begin, uint32_t end) {
        corners.clear();
        Eigen::AlignedBox3d box;
        for (uint32_t k = begin; k < end; ++k)
            for (uint32_t v : e.triangles[e.tri_order[k]]) corners.push_back(e.positions[v]), box.extend(e.positions[v]);
        TriangleNode n;
        const Eigen::Vector3d fc = float_rounded(box.center()); // measure around the stored centre
        n.center[0] = float(fc.x()), n.center[1] = float(fc.y()), n.center[2] = float(fc.z());
        double r = 0;
        for (const auto& p : corners) r = std::max(r, (p - fc).norm());
        n.radius = round_up(r);
        n.box = fit_obb(corners);
        return n;
    }

    void build(uint32_t begin, uint32_t end) {
        const uint32_t self = uint32_t(e.tri_nodes.size());
        e.tri_nodes.push_back(bound(begin, end));
        if (end - begin <= kLeafTriangles) {
            e.tri_nodes[self].first = begin, e.tri_nodes[self].count = end - begin;
            return;
        }
        // Split across the box's longest side, at the median centroid along it.
        const Obb& box = e.tri_nodes[self].box;
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
    Builder b{e, {}, {}};
    b.centroid.resize(e.triangles.size());
    for (uint32_t f = 0; f < e.triangles.size(); ++f) {
        const auto& t = e.triangles[f];
        const Eigen::Vector3d &p = e.positions[t[0]], &q = e.positions[t[1]], &r = e.positions[t[2]];
        b.centroid[f] = (p + q + r) / 3.0;
        if (is_degenerate_triangle(p, q, r)) ++e.degenerate_triangles;
        else e.tri_order.push_back(f);
    }
    if (e.tri_order.empty()) return;
    e.tri_nodes.reserve(2 * e.tri_order.size() / kLeafTriangles + 2);
    b.build(0, uint32_t(e.tri_order.size()));
}

} // namespace spt::detail
