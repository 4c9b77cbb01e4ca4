// The exact level's triangle tree: every triangle once, bounds hold, degenerate faces left out.
#include "query_fixtures.hpp"
#include "geometry/tri_tri.hpp"
#include "query/exact_data.hpp"
#include <gtest/gtest.h>

namespace spt {
namespace {

// Walks node i's subtree: checks every triangle below lies in the node's sphere and box.
void check_subtree(const ExactData& e, uint32_t i, std::vector<int>& seen, int& leaves) {
    const TriangleNode& n = e.tri_nodes[i];
    const Eigen::Vector3d c(n.center[0], n.center[1], n.center[2]);
    const Eigen::Vector3d bc(n.box.center[0], n.box.center[1], n.box.center[2]);
    std::vector<uint32_t> stack{i};
    while (!stack.empty()) {
        const TriangleNode& m = e.tri_nodes[stack.back()];
        stack.pop_back();
        if (!m.is_leaf()) {
            stack.push_back(uint32_t(&m - e.tri_nodes.data()) + 1), stack.push_back(m.first);
            continue;
        }
        for (uint32_t k = m.first; k < m.first + m.count; ++k)
            for (uint32_t v : e.triangles[e.tri_order[k]]) {
                const Eigen::Vector3d& p = e.positions[v];
                EXPECT_LE((p - c).norm(), double(n.radius)) << "node " << i;
                for (int k = 0; k < 3; ++k) {
                    const Eigen::Vector3d axis(n.box.axis[k][0], n.box.axis[k][1], n.box.axis[k][2]);
                    EXPECT_LE(std::abs(axis.dot(p - bc)), double(n.box.half[k])) << "node " << i;
                }
            }
    }
    if (n.is_leaf()) {
        ++leaves;
        EXPECT_EQ(n.count, 1u); // one triangle a leaf: the boxes do the pruning
        for (uint32_t k = n.first; k < n.first + n.count; ++k) ++seen[e.tri_order[k]];
    } else {
        check_subtree(e, i + 1, seen, leaves);
        check_subtree(e, n.first, seen, leaves);
    }
}

TEST(TriangleTree, EveryTriangleInOneLeafInsideEveryAncestorsSphereAndSlab) {
    // Far from the origin, so float rounding of centres and slab offsets matters.
    TriangleMesh m = make_torus(1.0, 0.35, 24, 12);
    for (auto& p : m.positions) p += Eigen::Vector3d(3e3, -2e3, 1e3);
    const auto o = test::make_object(m);
    const ExactData& e = o->model.exact();
    std::vector<int> seen(e.triangles.size(), 0);
    int leaves = 0;
    check_subtree(e, 0, seen, leaves);
    for (int s : seen) EXPECT_EQ(s, 1);
    EXPECT_EQ(e.tri_nodes.size(), size_t(2 * leaves - 1));
}

TEST(TriangleTree, ZeroAreaTrianglesAreLeftOutAndCounted) {
    TriangleMesh m = make_box({1, 1, 1}, 2);
    const uint32_t v = m.triangles[0][0];
    m.triangles.push_back({v, v, m.triangles[0][1]}); // repeated corner
    const size_t n = m.triangles.size();
    SptDocument doc = make_document(m, test::coarse());
    const CollisionModel model(doc, m);
    EXPECT_EQ(model.exact().degenerate_triangles, 1u);
    EXPECT_EQ(model.exact().tri_order.size(), n - 1);
}

} // namespace
} // namespace spt
