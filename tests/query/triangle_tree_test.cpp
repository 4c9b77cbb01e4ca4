// The exact level's triangle tree: every triangle once, bounds hold, degenerate faces left out.
#include "query/model_access.hpp"
#include "query_fixtures.hpp"
#include "geometry/tri_tri.hpp"
#include "query/exact_data.hpp"
#include "query/node_slab.hpp"
#include <cmath>
#include <gtest/gtest.h>

namespace spt {
namespace {

// Walks node i's subtree: checks every triangle below lies in the node's sphere and box.
void check_subtree(const ExactData& e, uint32_t i, std::vector<int>& seen, int& leaves) {
    const TriangleNode& n = e.tri_nodes[i];
    const Eigen::Vector3d c(n.center[0], n.center[1], n.center[2]);
    const Obb box = n.box();
    const Eigen::Vector3d bc(box.center[0], box.center[1], box.center[2]);
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
                    const Eigen::Vector3d axis(box.axis[k][0], box.axis[k][1], box.axis[k][2]);
                    EXPECT_LE(std::abs(axis.dot(p - bc)), double(box.half[k])) << "node " << i;
                }
            }
    }
    if (n.is_leaf()) {
        ++leaves;
        EXPECT_LE(n.count, 4u);
        if (n.count > 1) {
            EXPECT_EQ(n.boxed, 0u) << "node " << i; // several triangles only in a compact node
        }
        for (uint32_t k = n.first; k < n.first + n.count; ++k) ++seen[e.tri_order[k]];
    } else {
        check_subtree(e, i + 1, seen, leaves);
        check_subtree(e, n.first, seen, leaves);
    }
}

TEST(TriangleTree, EveryTriangleInOneLeafInsideEveryAncestorsSphereAndBox) {
    // Far from the origin, so float rounding of centres and slab offsets matters.
    TriangleMesh m = make_torus(1.0, 0.35, 24, 12);
    for (auto& p : m.positions) p += Eigen::Vector3d(3e3, -2e3, 1e3);
    const auto o = test::make_object(m);
    const ExactData& e = detail::exact_of(o->model);
    std::vector<int> seen(e.triangles.size(), 0);
    int leaves = 0;
    check_subtree(e, 0, seen, leaves);
    for (int s : seen) EXPECT_EQ(s, 1);
    EXPECT_EQ(e.tri_nodes.size(), size_t(2 * leaves - 1));
}

// Needles (height a hundredth of their length) get a leaf each and elongated nodes: a leaf's
// triangle pairs are told apart only by the triangles' spheres, which do not fit needles.
TEST(TriangleTree, NeedleTrianglesGetALeafEachAndBoxes) {
    std::vector<Eigen::Vector3d> p;
    std::vector<Triangle> t;
    for (int i = 0; i < 16; ++i) {
        const uint32_t v = uint32_t(p.size());
        const double x = 0.05 * i;
        p.push_back({x, 0, 0}), p.push_back({x, 1, 0}), p.push_back({x + 0.01, 0.5, 0});
        t.push_back({v, v + 1, v + 2});
    }
    const TriangleMesh m = prepare_mesh("needles", std::move(p), std::move(t)).mesh;
    const auto o = test::make_object(m);
    const ExactData& e = detail::exact_of(o->model);
    int leaves = 0;
    for (const TriangleNode& n : e.tri_nodes)
        if (n.is_leaf()) {
            ++leaves;
            EXPECT_EQ(n.count, 1u);
            EXPECT_EQ(n.boxed, 1u);
        }
    EXPECT_EQ(leaves, 16);
}

// A finely meshed smooth surface (compact triangles) shares leaves of up to four triangles,
// and its small nodes are compact (sphere and slab).
TEST(TriangleTree, CompactTrianglesShareLeaves) {
    const auto o = test::make_object(make_torus(1.0, 0.35, 48, 24));
    const ExactData& e = detail::exact_of(o->model);
    size_t leaves = 0, boxed_leaves = 0;
    for (const TriangleNode& n : e.tri_nodes)
        if (n.is_leaf()) ++leaves, boxed_leaves += n.boxed;
    EXPECT_LT(leaves, e.tri_order.size() / 2);
    EXPECT_LT(boxed_leaves, leaves / 10);
}

TEST(TriangleTree, ZeroAreaTrianglesAreLeftOutAndCounted) {
    TriangleMesh m = make_box({1, 1, 1}, 2);
    const uint32_t v = m.triangles[0][0];
    m.triangles.push_back({v, v, m.triangles[0][1]}); // repeated corner
    const size_t n = m.triangles.size();
    SptDocument doc = make_document(m, test::coarse());
    const CollisionModel model(doc, m);
    EXPECT_EQ(detail::exact_of(model).degenerate_triangles, 1u);
    EXPECT_EQ(detail::exact_of(model).tri_order.size(), n - 1);
}

TEST(TriangleTree, NoBoundOfFlatAxisAlignedPartsIsStoredAsADenormal) {
    // Walls in the planes of the axes (as FCL's env.obj is made): their boxes are 0 thick. A
    // denormal there made each product with it an x86 microcode assist, which was half the time
    // of the exact distance on env/rob; 0 costs nothing. Default sampling, so face samples and
    // two-sided discs are made too.
    for (TriangleMesh m : {make_box({2, 1, 0.5}, 3), make_sheet(2.0, 4), make_bracket()}) {
        const auto o = test::make_object(m, ConvertOptions{});
        int denormals = 0;
        auto scan = [&](const float* x, size_t n) {
            for (size_t k = 0; k < n; ++k) denormals += std::fpclassify(x[k]) == FP_SUBNORMAL;
        };
        const ExactData& e = detail::exact_of(o->model);
        ASSERT_FALSE(e.tri_nodes.empty());
        for (const TriangleNode& n : e.tri_nodes) {
            const Obb b = n.box();
            scan(b.center, 3), scan(&b.axis[0][0], 9), scan(b.half, 3), scan(&n.radius, 1);
        }
        scan(e.tri_sphere.data(), e.tri_sphere.size());
        const CompactTree& t = o->model.tree();
        for (const CompactNode& n : t.nodes()) {
            scan(n.center, 3), scan(&n.bv_radius, 1), scan(&n.ss_radius, 1);
            if (n.is_active()) scan(t.centers(n), 3 * size_t(n.count));
        }
        if (const float* slab = detail::node_slab_of(o->model)) scan(slab, detail::kSlabStride * t.nodes().size());
        if (const float* disc = t.node_disc()) scan(disc, 4 * t.nodes().size());
        EXPECT_EQ(denormals, 0) << m.positions.size() << " vertices";
    }
}

} // namespace
} // namespace spt
