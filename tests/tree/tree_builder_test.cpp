// The automatic builder: leaf sizes, determinism, tight bounds.
#include "meshgen.hpp"
#include "spt/mesh.hpp"
#include "spt/tree_builder.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>

using namespace spt;

namespace {

std::vector<std::pair<std::string, TriangleMesh>> real_meshes() {
    std::vector<std::pair<std::string, TriangleMesh>> out;
    for (const char* f : {"/PLY/Wuson.ply", "/OBJ/spider.obj", "/STL/sphereWithHole.stl"})
        out.emplace_back(f, import_mesh(test::assimp_models() + f).mesh);
    for (const char* f : {"/figure.obj", "/cad_part.stl", "/torus.obj"})
        out.emplace_back(f, import_mesh(test::project_meshes() + f).mesh);
    return out;
}

} // namespace

TEST(BuildTree, LeavesRespectLeafSizeAndHoldEverySampleOnce) {
    const ImportedMesh m = meshgen::prepare(meshgen::torus(1, 0.3, 64, 32), "torus");
    const SampleSet s = test::vertex_samples(m.mesh);
    for (auto strategy : {SplitStrategy::Median, SplitStrategy::Volume})
        for (uint32_t leaf : {1u, 4u, 8u, 33u}) {
            BuildOptions o;
            o.strategy = strategy;
            o.leaf_size = leaf;
            const SamplingTree t = build_tree("t", s, o);
            EXPECT_EQ(t.validate(uint32_t(s.size())), "");
            for (const TreeNode* n : t.active_nodes()) EXPECT_LE(n->samples.size(), leaf);
        }
}

TEST(BuildTree, IsDeterministic) {
    const ImportedMesh m = meshgen::prepare(meshgen::figure(), "figure");
    const SampleSet s = test::vertex_samples(m.mesh);
    const SamplingTree a = build_tree("t", s), b = build_tree("t", s);
    ASSERT_EQ(a.node_count(), b.node_count());
    const auto na = a.nodes(), nb = b.nodes();
    for (size_t i = 0; i < na.size(); ++i) {
        EXPECT_EQ(na[i]->id, nb[i]->id);
        EXPECT_EQ(na[i]->samples, nb[i]->samples);
        EXPECT_EQ(na[i]->center, nb[i]->center);
        EXPECT_EQ(na[i]->bv_radius, nb[i]->bv_radius);
    }
}

TEST(BuildTree, SameTreeOnAnyThreadCountWhereSubtreesAreBuiltAndBoundedAtOnce) {
    // 160k samples: the subtrees of the top two levels are large enough to go to threads.
    const ImportedMesh m = meshgen::prepare(meshgen::torus(1, 0.3, 400, 400), "torus");
    const SampleSet s = test::vertex_samples(m.mesh);
    for (auto strategy : {SplitStrategy::Volume, SplitStrategy::Median})
        for (auto bounds : {BoundsMethod::Tight, BoundsMethod::Paper}) {
            BuildOptions o;
            o.strategy = strategy;
            o.bounds = bounds;
            const SamplingTree one = build_tree("t", s, o);
            for (int threads : {2, 3, 8}) {
                o.threads = threads;
                const SamplingTree many = build_tree("t", s, o);
                ASSERT_EQ(many.node_count(), one.node_count());
                const auto a = one.nodes(), b = many.nodes();
                for (size_t i = 0; i < a.size(); ++i) {
                    ASSERT_EQ(a[i]->id, b[i]->id);
                    ASSERT_EQ(a[i]->active, b[i]->active);
                    ASSERT_EQ(a[i]->samples, b[i]->samples);
                    ASSERT_EQ(a[i]->center, b[i]->center) << "node " << a[i]->id << ", " << threads << " threads";
                    ASSERT_EQ(a[i]->bv_radius, b[i]->bv_radius);
                    ASSERT_EQ(a[i]->ss_radius, b[i]->ss_radius);
                }
            }
        }
}

TEST(BuildTree, IdenticalPointsStillSplitToLeafSize) {
    SampleSet s;
    for (uint32_t i = 0; i < 100; ++i) s.add({1, 1, 1}, {0, 1, 0}, i, 0.1f);
    const SamplingTree t = build_tree("t", s);
    EXPECT_EQ(t.validate(100), "");
    for (const TreeNode* n : t.active_nodes()) EXPECT_LE(n->samples.size(), 8u);
}

TEST(TightBounds, EveryNodeContainsEverySamplingSphereBelowIt) {
    for (const auto& [name, mesh] : real_meshes()) {
        SCOPED_TRACE(name);
        const SampleSet s = test::vertex_samples(mesh);
        for (auto strategy : {SplitStrategy::Median, SplitStrategy::Volume}) {
            BuildOptions o;
            o.strategy = strategy;
            const SamplingTree t = build_tree("t", s, o);
            // Walk up from every sphere: each ancestor's bounding sphere must hold it (in double).
            size_t checked = 0;
            for (const TreeNode* leaf : t.active_nodes())
                for (uint32_t i : leaf->samples) {
                    const Eigen::Vector3d c = s.sphere_center(i, leaf->ss_radius).cast<double>();
                    for (NodeId id = leaf->id; id != 0; id = parent_of(id)) {
                        const TreeNode& n = *t.find(id);
                        const double reach = (c - n.center.cast<double>()).norm() + leaf->ss_radius;
                        ASSERT_LE(reach, double(n.bv_radius)) << "node " << id << " sample " << i;
                        ++checked;
                    }
                }
            EXPECT_GT(checked, s.size());
        }
    }
}

TEST(TightBounds, AreNoLargerThanThePaperBoundsGrownToContainment) {
    // The paper's sphere (box centre, half the longest side) can miss corners and the
    // sphere radii; the tight one never does, and is not much larger than needed.
    const ImportedMesh m = meshgen::prepare(meshgen::torus(1, 0.3, 64, 32), "torus");
    const SampleSet s = test::vertex_samples(m.mesh);
    BuildOptions paper;
    paper.bounds = BoundsMethod::Paper;
    const SamplingTree p = build_tree("p", s, paper), t = build_tree("t", s);
    size_t paper_misses = 0;
    for (const TreeNode* leaf : p.active_nodes())
        for (uint32_t i : leaf->samples) {
            const Eigen::Vector3f c = s.sphere_center(i, leaf->ss_radius);
            if ((c - leaf->center).norm() + leaf->ss_radius > leaf->bv_radius) ++paper_misses;
        }
    EXPECT_GT(paper_misses, 0u) << "the paper bounds were expected to miss some spheres";
    EXPECT_LE(t.find(1)->bv_radius, 1.3f + 0.05f); // torus outer radius 1.3, sphere radii tiny
}
