// The query layout: child order, sphere blocks, bytes per sample.
#include "meshgen.hpp"
#include "spt/compact_tree.hpp"
#include "spt/convert.hpp"
#include "geometry/sample_disc.hpp"
#include "mesh/hard_shapes.hpp"
#include "mesh/shapes.hpp"
#include <Eigen/Geometry>
#include "spt/tree_builder.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>

using namespace spt;

TEST(CompactTree, LeftChildFollowsParentAndRightIsIndexed) {
    const ImportedMesh m = meshgen::prepare(meshgen::torus(1, 0.3, 32, 16), "torus");
    const SampleSet s = test::vertex_samples(m.mesh);
    const SamplingTree t = build_tree("t", s);
    const CompactTree c(t, s);
    const auto all = t.nodes();
    ASSERT_EQ(c.nodes().size(), t.node_count());
    size_t spheres = 0;
    for (size_t i = 0; i < c.nodes().size(); ++i) {
        const CompactNode& n = c.nodes()[i];
        const TreeNode& src = *all[n.tree_node];
        EXPECT_EQ(n.bv_radius, src.bv_radius);
        EXPECT_EQ(n.is_active(), src.active);
        if (!n.is_active()) {
            EXPECT_EQ(all[c.nodes()[i + 1].tree_node]->id, left_child(src.id));
            EXPECT_EQ(all[c.nodes()[n.first].tree_node]->id, right_child(src.id));
            continue;
        }
        for (uint32_t k = 0; k < n.count; ++k) {
            const uint32_t sample = c.sample_index()[n.first + k];
            const Eigen::Vector3f ctr = s.sphere_center(sample, src.ss_radius);
            EXPECT_EQ(c.sphere_center(n, n.first + k), ctr);
            EXPECT_EQ(c.centers(n)[k], ctr.x()); // block: x's, y's, z's
            EXPECT_EQ(c.centers(n)[n.count + k], ctr.y());
            EXPECT_EQ(c.centers(n)[2 * n.count + k], ctr.z());
            EXPECT_NEAR(c.nx()[n.first + k] / 127.0f, s.normals[sample].x(), 0.005f);
        }
        spheres += n.count;
    }
    EXPECT_EQ(spheres, s.size());
}

TEST(CompactTree, StaysUnderThirtyTwoBytesPerSample) {
    const ImportedMesh m = meshgen::prepare(meshgen::torus(1, 0.3, 300, 100), "torus");
    const SampleSet s = test::vertex_samples(m.mesh);
    const CompactTree c(build_tree("t", s), s);
    EXPECT_LE(double(c.memory_bytes()) / double(s.size()), 32.0);
}

// A node's disc must hold the disc of every two-sided sphere below it (the walk prunes by it):
// open meshes flat (a sheet), folded (a fan, an open box) and scattered (a soup). A flat
// sheet's nodes are discs all the way up; a closed mesh has none.
TEST(CompactTree, NodeDiscHoldsTheDiscOfEverySphereBelowIt) {
    const TriangleMesh meshes[] = {make_sheet(1.0, 6), make_fan(5), make_open_box({0.5, 0.5, 0.5}, 3),
                                   make_triangle_soup(60, 0.2, 3)};
    for (const TriangleMesh& mesh : meshes) {
        const SptDocument doc = make_document(mesh);
        const CompactTree c(doc.trees.front(), doc.samples);
        ASSERT_NE(c.node_disc(), nullptr) << mesh.name;
        const auto& nodes = c.nodes();
        size_t discs = 0;
        for (size_t i = 0; i < nodes.size(); ++i) {
            const float* d = c.node_disc() + 4 * i;
            if (!(d[3] >= 0)) continue;
            ++discs;
            const Eigen::Vector3f n(d[0], d[1], d[2]), centre(nodes[i].center[0], nodes[i].center[1], nodes[i].center[2]);
            EXPECT_NEAR(n.norm(), 1.0f, 1e-5f);
            // Every sphere below node i.
            std::vector<size_t> stack{i};
            while (!stack.empty()) {
                const CompactNode& m = nodes[stack.back()];
                stack.pop_back();
                if (!m.is_active()) {
                    stack.push_back(size_t(&m - nodes.data()) + 1), stack.push_back(m.first);
                    continue;
                }
                for (uint32_t k = m.first; k < m.first + m.count; ++k) {
                    const Eigen::Vector3f ns = Eigen::Vector3f(c.nx()[k], c.ny()[k], c.nz()[k]).normalized();
                    const Eigen::Vector3f cs = c.sphere_center(m, k);
                    const float reach = std::abs(n.dot(cs - centre)) + m.ss_radius * n.cross(ns).norm() +
                                        detail::kDiscHalfThickness * m.ss_radius;
                    ASSERT_LE(reach, d[3]) << mesh.name << " node " << i << " sphere " << k;
                    ASSERT_LE((cs - centre).norm() + m.ss_radius, nodes[i].bv_radius * (1 + 1e-5f))
                        << mesh.name << " node " << i << " sphere " << k;
                }
            }
        }
        EXPECT_GT(discs, nodes.size() / 4) << mesh.name;
        if (mesh.name == "sheet") {
            EXPECT_EQ(discs, nodes.size());
        }
    }
    const ImportedMesh closed = meshgen::prepare(meshgen::torus(1, 0.3, 32, 16), "torus");
    const SampleSet s = test::vertex_samples(closed.mesh);
    EXPECT_EQ(CompactTree(build_tree("t", s), s).node_disc(), nullptr);
}
