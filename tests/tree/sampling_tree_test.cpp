// Split and merge as the paper defines them, bounds after edits, validation.
#include "meshgen.hpp"
#include "spt/compact_tree.hpp"
#include "spt/sampling_tree.hpp"
#include "spt/tree_builder.hpp"
#include "mesh/shapes.hpp"
#include "tree/bounds.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <functional>
#include <random>

using namespace spt;

namespace {

SampleSet line_samples(uint32_t n) {
    SampleSet s;
    for (uint32_t i = 0; i < n; ++i) s.add({float(i), 0, 0}, {0, 0, 1}, i, 1.0f);
    return s;
}

} // namespace

TEST(Split, LeftIsNodeAndSelectionRightIsTheRest) {
    const SampleSet s = line_samples(10);
    SamplingTree t("t", 10);
    ASSERT_TRUE(t.split(1, {2, 3, 4, 42}, s));
    EXPECT_FALSE(t.find(1)->active);
    EXPECT_TRUE(t.find(1)->samples.empty());
    EXPECT_EQ(t.find(2)->samples, (std::vector<uint32_t>{2, 3, 4}));
    EXPECT_EQ(t.find(3)->samples, (std::vector<uint32_t>{0, 1, 5, 6, 7, 8, 9}));
    EXPECT_TRUE(t.find(2)->active && t.find(3)->active);
    EXPECT_EQ(t.validate(10), "");
}

TEST(Split, EmptySelectionIsRejectedWithReason) {
    const SampleSet s = line_samples(4);
    SamplingTree t("t", 4);
    const EditResult r = t.split(1, {}, s);
    EXPECT_FALSE(r);
    EXPECT_NE(r.reason.find("none"), std::string::npos);
    EXPECT_EQ(t.node_count(), 1u);
}

TEST(Split, FullSelectionIsRejectedWithReason) {
    const SampleSet s = line_samples(4);
    SamplingTree t("t", 4);
    const EditResult r = t.split(1, {0, 1, 2, 3}, s);
    EXPECT_FALSE(r);
    EXPECT_NE(r.reason.find("all"), std::string::npos);
}

TEST(Split, InactiveOrMissingNodeIsRejected) {
    const SampleSet s = line_samples(4);
    SamplingTree t("t", 4);
    ASSERT_TRUE(t.split(1, {0}, s));
    EXPECT_FALSE(t.split(1, {1}, s));
    EXPECT_FALSE(t.split(99, {1}, s));
}

TEST(Merge, UndoesSplitExactly) {
    const SampleSet s = line_samples(16);
    SamplingTree t("t", 16);
    t.assign_radii(s, {});
    t.compute_bounds(s, BoundsMethod::Tight);
    const TreeNode before = *t.find(1);
    ASSERT_TRUE(t.split(1, {1, 5, 9}, s));
    ASSERT_TRUE(t.split(3, {0, 2}, s));
    ASSERT_TRUE(t.merge(1, s));
    EXPECT_EQ(t.node_count(), 1u);
    const TreeNode& after = *t.find(1);
    EXPECT_EQ(after.samples, before.samples);
    EXPECT_EQ(after.center, before.center);
    EXPECT_EQ(after.bv_radius, before.bv_radius);
    EXPECT_EQ(after.ss_radius, before.ss_radius);
    EXPECT_FALSE(t.merge(1, s)); // active: nothing to merge
}

TEST(Split, EveryBoundingSphereStillHoldsItsSpheresAfterEdits) {
    const ImportedMesh m = meshgen::prepare(meshgen::torus(1, 0.3, 32, 16), "torus");
    const SampleSet s = test::vertex_samples(m.mesh);
    SamplingTree t("t", uint32_t(s.size()));
    t.assign_radii(s, {});
    t.compute_bounds(s, BoundsMethod::Tight);
    std::vector<uint32_t> right_half, top;
    for (uint32_t i = 0; i < s.size(); ++i) {
        if (s.position(i).x() > 0.5) right_half.push_back(i);
        if (s.position(i).z() > 0.1) top.push_back(i);
    }
    ASSERT_TRUE(t.split(1, right_half, s));
    ASSERT_TRUE(t.split(3, top, s));
    ASSERT_TRUE(t.split(2, top, s));
    ASSERT_TRUE(t.merge(3, s));
    for (const TreeNode* leaf : t.active_nodes())
        for (uint32_t i : leaf->samples) {
            const Eigen::Vector3d c = s.sphere_center(i, leaf->ss_radius).cast<double>();
            for (NodeId id = leaf->id; id != 0; id = parent_of(id)) {
                const TreeNode& n = *t.find(id);
                EXPECT_LE((c - n.center.cast<double>()).norm() + leaf->ss_radius, double(n.bv_radius))
                    << "node " << id << " sample " << i;
            }
        }
}

TEST(OneSidedTree, DepthFortyStaysLinearInMemory) {
    // Peeling one sample off at every level: paper ids reach 2^40, the layout must not.
    const uint32_t n = 41;
    const SampleSet s = line_samples(n);
    SamplingTree t("deep", n);
    NodeId node = 1;
    for (uint32_t i = 0; i < 40; ++i) {
        ASSERT_TRUE(t.split(node, {i}, s)) << i;
        node = right_child(node);
    }
    EXPECT_EQ(t.depth(), 40);
    EXPECT_EQ(t.node_count(), 81u);
    EXPECT_EQ(t.validate(n), "");
    const CompactTree c(t, s);
    EXPECT_EQ(c.nodes().size(), 81u);
    EXPECT_EQ(c.sphere_count(), n);
    EXPECT_LT(c.memory_bytes(), 81 * sizeof(CompactNode) + 64 * 20);
}

TEST(Validate, FindsBrokenStructure) {
    std::vector<TreeNode> nodes(3);
    nodes[0].id = 1, nodes[0].active = false, nodes[0].ss_radius = 1;
    nodes[1].id = 2, nodes[1].samples = {0}, nodes[1].ss_radius = 1;
    nodes[2].id = 3, nodes[2].samples = {0, 1}, nodes[2].ss_radius = 1; // sample 0 twice
    EXPECT_NE(SamplingTree("t", nodes).validate(2).find("two active nodes"), std::string::npos);
    nodes[2].samples = {1};
    EXPECT_EQ(SamplingTree("t", nodes).validate(2), "");
    EXPECT_NE(SamplingTree("t", nodes).validate(3).find("no active node"), std::string::npos);
    nodes[2].ss_radius = 0;
    EXPECT_NE(SamplingTree("t", nodes).validate(2).find("radius"), std::string::npos);
    nodes[2].ss_radius = 1;
    nodes[1].center.x() = std::numeric_limits<float>::infinity();
    EXPECT_NE(SamplingTree("t", nodes).validate(2).find("finite"), std::string::npos);
}

// The parent and child checks walk the nodes in id order (no look-up per node): every way a
// node's parent or a child can be missing or wrong is still named.
TEST(Validate, NamesAMissingChildParentOrAnActiveParent) {
    auto node = [](NodeId id, bool active, std::vector<uint32_t> samples) {
        TreeNode n;
        n.id = id, n.active = active, n.samples = std::move(samples), n.ss_radius = 1;
        return n;
    };
    // Root 1 split into 2 and 3; 3 split into 6 and 7.
    const std::vector<TreeNode> good = {node(1, false, {}), node(2, true, {0}), node(3, false, {}),
                                        node(6, true, {1}), node(7, true, {2})};
    EXPECT_EQ(SamplingTree("t", good).validate(3), "");
    auto without = [&](NodeId id) {
        std::vector<TreeNode> v;
        for (const TreeNode& n : good)
            if (n.id != id) v.push_back(n);
        return v;
    };
    auto why = [](std::vector<TreeNode> v, uint32_t count) { return SamplingTree("t", std::move(v)).validate(count); };
    EXPECT_EQ(why(without(7), 3), "node 3: inactive node lacks a child"); // no right child
    EXPECT_EQ(why(without(6), 3), "node 3: inactive node lacks a child"); // no left child
    EXPECT_EQ(why(without(2), 3), "node 1: inactive node lacks a child");
    EXPECT_EQ(why(without(3), 3), "node 1: inactive node lacks a child");
    std::vector<TreeNode> orphan = good;
    orphan.push_back(node(5, true, {}));  // parent 2 is active
    EXPECT_EQ(why(orphan, 3), "node 5: parent 2 is active");
    orphan.back() = node(10, true, {}); // parent 5 is missing
    EXPECT_EQ(why(orphan, 3), "node 10: parent 5 is missing");
    orphan.back() = node(15, true, {}); // parent 7 is active, found past other nodes' parents
    EXPECT_EQ(why(orphan, 3), "node 15: parent 7 is active");
    EXPECT_EQ(why({node(2, true, {0})}, 1), "tree has no root node");
}

TEST(Radius, DefaultIsMedianSpacingTimesScaleAndFixedOverrides) {
    SampleSet s;
    for (int i = 0; i < 5; ++i) s.add({float(i), 0, 0}, {0, 0, 1}, uint32_t(i), float(i + 1)); // spacing 1..5
    std::vector<uint32_t> all{0, 1, 2, 3, 4};
    EXPECT_FLOAT_EQ(node_radius(all, s, {}), 3.0f);
    EXPECT_FLOAT_EQ(node_radius(all, s, {0, 2.0f}), 6.0f);
    EXPECT_FLOAT_EQ(node_radius(all, s, {0.25f, 1.0f}), 0.25f);
}

TEST(SetRadius, ChangesAnActiveNodeAndItsPathOnly) {
    const SampleSet s = line_samples(16);
    SamplingTree t("t", 16);
    ASSERT_TRUE(t.split(1, {0, 1, 2, 3}, s));
    const TreeNode right_before = *t.find(3);
    ASSERT_TRUE(t.set_radius(2, 3.0f, s));
    EXPECT_EQ(t.find(2)->ss_radius, 3.0f);
    EXPECT_EQ(t.find(1)->ss_radius, std::max(3.0f, right_before.ss_radius));
    EXPECT_EQ(t.find(3)->ss_radius, right_before.ss_radius);
    // Node 2's bounding sphere holds its larger spheres: line points at x 0..3, radius 3.
    EXPECT_GE(t.find(2)->bv_radius, 1.5f + 3.0f - 1e-4f);
    EXPECT_FALSE(t.set_radius(1, 2.0f, s));
    EXPECT_FALSE(t.set_radius(2, 0.0f, s));
    EXPECT_EQ(t.validate(16), "");
}

TEST(BuildSubtree, BuildsUnderTheNodeAndLeavesTheRestAlone) {
    const SampleSet s = line_samples(64);
    SamplingTree t("t", 64);
    std::vector<uint32_t> first_half;
    for (uint32_t i = 0; i < 32; ++i) first_half.push_back(i);
    ASSERT_TRUE(t.split(1, first_half, s));
    const TreeNode right_before = *t.find(3);
    BuildOptions o;
    o.leaf_size = 4;
    ASSERT_TRUE(t.build_subtree(2, s, o));
    EXPECT_EQ(t.validate(64), "");
    EXPECT_EQ(t.find(3)->samples, right_before.samples);
    EXPECT_FALSE(t.find(2)->active);
    size_t below = 0;
    for (const TreeNode* n : t.active_nodes()) {
        NodeId a = n->id;
        while (a > 2) a = parent_of(a);
        if (a != 2) continue;
        EXPECT_LE(n->samples.size(), 4u);
        below += n->samples.size();
    }
    EXPECT_EQ(below, 32u);
    EXPECT_FALSE(t.build_subtree(2, s, o)); // already split
    o.leaf_size = 64;
    EXPECT_FALSE(t.build_subtree(3, s, o)); // 32 samples: no more than the leaf size
}

TEST(Split, HalvesOfARingAreBoundedNoLargerThanTheRing) {
    // Half a ring seen from the centre of its own box needs a sphere larger than the ring's;
    // from the ring's centre it needs no more than the ring's.
    const SampleSet s = test::vertex_samples(make_torus(1.0, 0.25, 48, 12));
    SamplingTree t("t", uint32_t(s.size()));
    t.assign_radii(s, {});
    t.compute_bounds(s, BoundsMethod::Tight);
    std::vector<uint32_t> east;
    for (uint32_t i = 0; i < s.size(); ++i)
        if (s.position(i).x() > 0) east.push_back(i);
    ASSERT_TRUE(t.split(1, east, s));
    for (NodeId half : {NodeId(2), NodeId(3)}) {
        ASSERT_EQ(t.find(half)->ss_radius, t.find(1)->ss_radius); // the same spheres, only regrouped
        EXPECT_LE(t.find(half)->bv_radius, t.find(1)->bv_radius) << "node " << half;
    }
    EXPECT_EQ(t.validate(uint32_t(s.size())), "");
}

TEST(Split, EveryNodeOnADeepPathIsBoundedByItsOwnSamplesAlone) {
    // Each split re-bounds the path from the root with one gathering of the spheres below the
    // top, each node taking its own run of it: a run one node off would give some node another's
    // box. The paper's bounds are the box of the samples' points, whatever their order.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1, 1);
    SampleSet s;
    for (uint32_t i = 0; i < 300; ++i) s.add({u(rng), u(rng), u(rng)}, {0, 0, 1}, i, 0.05f);
    SamplingTree t("t", 300);
    t.assign_radii(s, {});
    t.compute_bounds(s, BoundsMethod::Paper);
    NodeId rest = root_id();
    for (int step = 0; step < 40; ++step) { // a chain 40 deep; every fifth left part split too
        const TreeNode& n = *t.find(rest);
        const std::vector<uint32_t> picked(n.samples.begin(), n.samples.begin() + 3 + step % 4);
        ASSERT_TRUE(t.split(rest, picked, s, {}, BoundsMethod::Paper));
        if (step % 5 == 4) {
            ASSERT_TRUE(t.split(left_child(rest), {picked[0]}, s, {}, BoundsMethod::Paper));
        }
        rest = right_child(rest);
    }
    ASSERT_EQ(t.validate(300), "");
    std::function<void(NodeId, Eigen::AlignedBox3f&)> box_below = [&](NodeId id, Eigen::AlignedBox3f& box) {
        const TreeNode& n = *t.find(id);
        for (uint32_t i : n.samples) box.extend(s.points[i]);
        if (!n.active) box_below(left_child(id), box), box_below(right_child(id), box);
    };
    for (const TreeNode* n : t.nodes()) {
        Eigen::AlignedBox3f box;
        box_below(n->id, box);
        EXPECT_EQ(n->center, Eigen::Vector3f((box.min() + box.max()) / 2)) << "node " << n->id;
        EXPECT_EQ(n->bv_radius, (box.max() - box.min()).maxCoeff() / 2) << "node " << n->id;
    }
}
