// The query layout: child order, sphere blocks, bytes per sample.
#include "meshgen.hpp"
#include "spt/compact_tree.hpp"
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
            const Eigen::Vector3f ctr = s.sphere_centre(sample, src.ss_radius);
            EXPECT_EQ(c.sphere_centre(n, n.first + k), ctr);
            EXPECT_EQ(c.centres(n)[k], ctr.x()); // block: x's, y's, z's
            EXPECT_EQ(c.centres(n)[n.count + k], ctr.y());
            EXPECT_EQ(c.centres(n)[2 * n.count + k], ctr.z());
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
