// Trees built for a recorded motion: valid, deterministic, grafted under a node, cheaper on the
// motion than the automatic tree, and kept by the .spt file.
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "spt/motion_tree.hpp"
#include "spt/spt_file.hpp"
#include "spt_reseal.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>

using namespace spt;

namespace {

std::string walk_scene(const std::string& name) { return std::string(SPT_SOURCE_DIR) + "/resources/scenes/" + name; }

struct Walk {
    std::shared_ptr<SptDocument> doc;
    MotionRecording rec;
};

const Walk& walk() {
    static const Walk w = [] {
        auto mesh = std::make_shared<AnimatedMesh>(
            import_animated_mesh(std::string(SPT_SOURCE_DIR) + "/resources/models/walking_figure.gltf"));
        auto doc = std::make_shared<SptDocument>(load_spt(walk_scene("figure_walk.spt")));
        MotionOptions o;
        o.steps = 100;
        return Walk{doc, record_motion(load_scene(walk_scene("walking.json")), "walker", {doc, "walk", mesh}, o)};
    }();
    return w;
}

} // namespace

TEST(MotionTree, IsAValidTreeTheSameOnAnyThreadCount) {
    const Walk& w = walk();
    MotionBuildOptions one, two;
    two.build.threads = 2;
    const SamplingTree a = build_motion_tree("motion", w.doc->samples, w.rec, one);
    const SamplingTree b = build_motion_tree("motion", w.doc->samples, w.rec, two);
    EXPECT_EQ(a.validate(uint32_t(w.doc->samples.size())), "");
    ASSERT_EQ(a.node_count(), b.node_count());
    const auto na = a.nodes(), nb = b.nodes();
    for (size_t i = 0; i < na.size(); ++i) {
        EXPECT_EQ(na[i]->id, nb[i]->id);
        EXPECT_EQ(na[i]->samples, nb[i]->samples);
    }
    for (const TreeNode* n : a.active_nodes()) EXPECT_LE(n->samples.size(), 8u);
}

TEST(MotionTree, WalksFewerNodePairsOnItsMotionThanTheAutomaticTree) {
    // Counters, not times: the same on any machine. docs/editor.md has the timings.
    const Walk& w = walk();
    const SamplingTree automatic = build_tree("auto", w.doc->samples);
    const SamplingTree motion = build_motion_tree("motion", w.doc->samples, w.rec);
    const std::vector<MotionCost> cost = measure_motion_cost(w.rec, {&automatic, &motion}, QueryOptions{}, 1);
    ASSERT_EQ(cost.size(), 2u);
    EXPECT_EQ(cost[0].queries, 100u);
    EXPECT_EQ(cost[0].collide_share, 1.0);
    EXPECT_EQ(cost[1].collide_share, 1.0) << "the same answers";
    EXPECT_LT(cost[1].mean_node_pairs, 0.9 * cost[0].mean_node_pairs);
    EXPECT_LT(cost[1].mean_sphere_tests, 0.9 * cost[0].mean_sphere_tests);
}

TEST(MotionTree, BuildUnderANodeKeepsTheRestOfTheTree) {
    const Walk& w = walk();
    SamplingTree tree = unsplit_tree("edited", w.doc->samples);
    // A manual split first: the upper body (y > 1) left, the rest right.
    std::vector<uint32_t> upper;
    for (uint32_t i = 0; i < w.doc->samples.size(); ++i)
        if (w.doc->samples.position(i).y() > 1) upper.push_back(i);
    ASSERT_TRUE(tree.split(1, upper, w.doc->samples));
    const std::vector<uint32_t> left = tree.find(2)->samples;
    ASSERT_TRUE(build_motion_subtree(tree, 3, w.doc->samples, w.rec));
    EXPECT_EQ(tree.validate(uint32_t(w.doc->samples.size())), "");
    ASSERT_NE(tree.find(2), nullptr);
    EXPECT_TRUE(tree.find(2)->active);
    EXPECT_EQ(tree.find(2)->samples, left);
    EXPECT_FALSE(tree.find(3)->active);
    EXPECT_FALSE(build_motion_subtree(tree, 3, w.doc->samples, w.rec)) << "node 3 is split now";
}

TEST(MotionTree, ARecordingOfOtherSamplesIsRefused) {
    const Walk& w = walk();
    SampleSet fewer = w.doc->samples;
    fewer.points.pop_back();
    EXPECT_THROW(build_motion_tree("x", fewer, w.rec), Error);
}

TEST(MotionTree, TheSptFileKeepsItsBuildsFromMotion) {
    const Walk& w = walk();
    SptDocument doc = *w.doc;
    SamplingTree tree = build_motion_tree("motion", doc.samples, w.rec);
    tree.add_motion_build({1, "walking.json", "walker", 100, 8, 0});
    doc.trees.push_back(tree);
    EXPECT_EQ(spt_version_for(doc), 6u);
    const std::vector<uint8_t> bytes = encode_spt(doc);
    const SptDocument back = decode_spt(bytes, "motion.spt");
    const SamplingTree* t = back.tree("motion");
    ASSERT_NE(t, nullptr);
    ASSERT_EQ(t->motion_builds().size(), 1u);
    EXPECT_EQ(t->motion_builds()[0].scene, "walking.json");
    EXPECT_EQ(t->motion_builds()[0].object, "walker");
    EXPECT_EQ(t->motion_builds()[0].steps, 100);
    EXPECT_EQ(encode_spt(back), bytes) << "one encoding";
    // Without the build the document is written as before.
    doc.trees.pop_back();
    EXPECT_LT(spt_version_for(doc), 6u);
}

TEST(MotionTree, ABuildFromMotionNamingALeafIsRefusedAtItsByte) {
    const Walk& w = walk();
    SptDocument doc = *w.doc;
    SamplingTree tree = build_motion_tree("motion", doc.samples, w.rec);
    const NodeId leaf = tree.active_nodes().front()->id;
    tree.add_motion_build({leaf, "walking.json", "walker", 0, 8, 0});
    doc.trees = {tree};
    try {
        decode_spt(encode_spt(doc), "bad.spt");
        FAIL() << "accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("has no inner node of that id"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("bad.spt: byte"), std::string::npos) << e.what();
    }
}

TEST(MotionTree, AMergeDropsTheBuildsUnderTheMergedNode) {
    const Walk& w = walk();
    SamplingTree tree = unsplit_tree("edited", w.doc->samples);
    ASSERT_TRUE(build_motion_subtree(tree, 1, w.doc->samples, w.rec));
    tree.add_motion_build({1, "walking.json", "walker", 100, 8, 0});
    ASSERT_TRUE(tree.merge(1, w.doc->samples));
    EXPECT_TRUE(tree.motion_builds().empty());
}

TEST(MotionTree, AFileWithStrokesOfVersion5AndABuildFromMotionIsVersion6AndKeepsBoth) {
    const Walk& w = walk();
    SptDocument doc = *w.doc;
    SamplingTree tree = unsplit_tree("edited", doc.samples);
    // A split whose recipe step is an invert stroke (a version 5 kind), then a build from motion
    // under its right child.
    std::vector<uint32_t> upper;
    for (uint32_t i = 0; i < doc.samples.size(); ++i)
        if (doc.samples.position(i).y() > 1) upper.push_back(i);
    ASSERT_TRUE(tree.split(1, upper, doc.samples));
    RecipeStroke invert;
    invert.kind = StrokeKind::Invert;
    tree.add_recipe_step(RecipeStep{1, {invert}});
    ASSERT_TRUE(build_motion_subtree(tree, 3, doc.samples, w.rec));
    tree.add_motion_build({3, "walking.json", "walker", 100, 8, 0});
    doc.trees = {tree};
    EXPECT_EQ(spt_version_for(doc), 6u);
    const std::vector<uint8_t> bytes = encode_spt(doc);
    const SptDocument back = decode_spt(bytes, "both.spt");
    const SamplingTree& t = back.trees.front();
    ASSERT_EQ(t.recipe().size(), 1u);
    EXPECT_EQ(t.recipe()[0].strokes.at(0).kind, StrokeKind::Invert);
    ASSERT_EQ(t.motion_builds().size(), 1u);
    EXPECT_EQ(t.motion_builds()[0].after_steps, 1u);
    EXPECT_EQ(encode_spt(back), bytes);
    // A document without a build from motion labelled version 6 (and a zero build count appended to
    // each tree, as version 6 would read it) is refused: one encoding a document.
    SptDocument plain = *w.doc;
    SamplingTree stepped = unsplit_tree("edited", plain.samples);
    ASSERT_TRUE(stepped.split(1, upper, plain.samples));
    stepped.add_recipe_step(RecipeStep{1, {invert}});
    plain.trees = {stepped};
    ASSERT_EQ(spt_version_for(plain), 5u);
    std::vector<uint8_t> relabelled = encode_spt(plain);
    relabelled[8] = 6;
    relabelled.insert(relabelled.end(), 4, 0);
    test::reseal(relabelled);
    try {
        decode_spt(relabelled, "relabelled.spt");
        FAIL() << "accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("version 6 file without a build from motion"), std::string::npos) << e.what();
    }
}
