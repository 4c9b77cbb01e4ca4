// Authoring recipes: kept through .spt version 3 byte for byte, dropped by a merge, and
// replayed on a changed mesh (vertices moved, re-triangulated) the splits come out the same
// by region; a step that selects nothing any more is reported.
#include "mesh/shapes.hpp"
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "spt/recipe.hpp"
#include "spt/selection.hpp"
#include "spt/spt_file.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>

using namespace spt;

namespace {

// Orthographic view down -Z: object x, y in [-2, 2] fill a 400x400 framebuffer, window x = (x + 2) * 100.
ViewProjection wide_front_view() {
    ViewProjection v;
    v.view(2, 3) = -10;
    v.projection = Eigen::Matrix4f::Identity();
    v.projection(0, 0) = v.projection(1, 1) = 0.5f;
    v.projection(2, 2) = -0.05f;
    v.width = v.height = 400;
    return v;
}

// A stroke selecting object x in [x0, x1] (all y).
RecipeStroke band(float x0, float x1, SelectionMode mode = SelectionMode::Replace) {
    return {wide_front_view(), {(x0 + 2) * 100, 0, (x1 + 2) * 100, 400}, mode, false};
}

struct Authored {
    SptDocument doc;
    TriangleMesh mesh;
};

// A torus tree split twice: node 2 = x < 0.013 (a band, minus a strip), then node 3's x > 0.61.
Authored authored(int nu, int nv, double wobble) {
    Authored a;
    a.mesh = make_torus(1.0, 0.3, nu, nv);
    for (auto& p : a.mesh.positions) p.z() += wobble * std::sin(7 * p.x()); // moved vertices
    a.mesh = prepare_mesh("torus.obj", a.mesh.positions, a.mesh.triangles).mesh;
    a.doc.samples = test::vertex_samples(a.mesh);
    SamplingTree t = unsplit_tree("walking", a.doc.samples);
    const RecipeStep first{1, {band(-2, 0.013f), band(-0.31f, -0.29f, SelectionMode::Subtract)}};
    EXPECT_TRUE(t.split(1, select_strokes(a.doc.samples, t, first, &a.mesh), a.doc.samples));
    t.add_recipe_step(first);
    const RecipeStep second{3, {band(0.61f, 2)}};
    EXPECT_TRUE(t.split(3, select_strokes(a.doc.samples, t, second, &a.mesh), a.doc.samples));
    t.add_recipe_step(second);
    a.doc.mesh = {"torus.obj", uint32_t(a.mesh.positions.size()), uint32_t(a.mesh.triangles.size()),
                  a.mesh.content_hash(), a.mesh.diagonal()};
    a.doc.trees.push_back(std::move(t));
    return a;
}

// Samples whose object-frame x lies in the region, computed from positions alone.
std::vector<uint32_t> where_x(const SampleSet& s, bool (*in)(double)) {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < s.size(); ++i)
        if (in(s.position(i).x())) out.push_back(i);
    return out;
}

} // namespace

TEST(Recipe, Version3KeepsTheRecipeByteForByteAndOldVersionsStay) {
    const Authored a = authored(40, 20, 0.0);
    const std::vector<uint8_t> bytes = encode_spt(a.doc);
    EXPECT_EQ(spt_version_for(a.doc), 3u);
    uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 8, 4);
    EXPECT_EQ(version, 3u);
    const SptDocument back = decode_spt(bytes);
    ASSERT_EQ(back.trees.front().recipe().size(), 2u);
    EXPECT_EQ(back.trees.front().recipe()[0].strokes.size(), 2u);
    EXPECT_EQ(back.trees.front().recipe()[0].strokes[1].mode, SelectionMode::Subtract);
    EXPECT_EQ(encode_spt(back), bytes);
    // Without a recipe the same document is version 1 again, and a version 3 header on it is refused.
    SptDocument plain = back;
    plain.trees.front().set_recipe({});
    std::vector<uint8_t> v1 = encode_spt(plain);
    std::memcpy(&version, v1.data() + 8, 4);
    EXPECT_EQ(version, 1u);
    EXPECT_EQ(encode_spt(decode_spt(v1)), v1);
}

TEST(Recipe, AMergeDropsTheStepsOfTheMergedSplits) {
    Authored a = authored(40, 20, 0.0);
    SamplingTree& t = a.doc.trees.front();
    ASSERT_TRUE(t.merge(3, a.doc.samples));
    ASSERT_EQ(t.recipe().size(), 1u);
    EXPECT_EQ(t.recipe().front().node, NodeId(1));
    ASSERT_TRUE(t.merge(1, a.doc.samples));
    EXPECT_TRUE(t.recipe().empty());
}

TEST(Recipe, ReplayOnAChangedMeshGivesTheSameSplitsByRegion) {
    const Authored old = authored(40, 20, 0.0);
    const Authored changed = authored(57, 23, 0.02); // other vertices, other triangles
    ReplayReport report;
    const SamplingTree t = replay_recipe(old.doc.trees.front(), changed.doc.samples, changed.mesh, &report);
    EXPECT_EQ(report.replayed, 2u);
    EXPECT_TRUE(report.skipped.empty());
    EXPECT_EQ(t.name(), "walking");
    EXPECT_EQ(t.validate(uint32_t(changed.doc.samples.size())), "");
    EXPECT_EQ(t.recipe().size(), 2u);
    const SampleSet& s = changed.doc.samples;
    EXPECT_EQ(t.find(2)->samples, where_x(s, [](double x) { return x <= 0.013 && !(x >= -0.31 && x <= -0.29); }));
    EXPECT_EQ(t.find(6)->samples, where_x(s, [](double x) { return x >= 0.61; }));
    // The rest of node 3: the middle, and the strip the first step subtracted.
    EXPECT_EQ(t.find(7)->samples,
              where_x(s, [](double x) { return (x > 0.013 && x < 0.61) || (x >= -0.31 && x <= -0.29); }));
}

TEST(Recipe, AStepThatSelectsNothingIsReportedNotGuessed) {
    Authored a = authored(40, 20, 0.0);
    SamplingTree t = a.doc.trees.front();
    // A third step whose band lies beyond the torus: nothing to split by.
    t.add_recipe_step({7, {band(1.5f, 2)}});
    ReplayReport report;
    const SamplingTree replayed = replay_recipe(t, a.doc.samples, a.mesh, &report);
    EXPECT_EQ(report.replayed, 2u);
    ASSERT_EQ(report.skipped.size(), 1u);
    EXPECT_NE(report.skipped.front().find("step 3"), std::string::npos) << report.skipped.front();
    EXPECT_NE(report.skipped.front().find("none"), std::string::npos) << report.skipped.front();
    EXPECT_TRUE(replayed.find(7)->active);
}

TEST(Recipe, ReplayTreesReplaysTreesWithARecipeAndBuildsTheOthers) {
    const Authored old = authored(40, 20, 0.0);
    SptDocument recipes = old.doc;
    recipes.trees.push_back(unsplit_tree("plain", old.doc.samples)); // no recipe
    Authored changed = authored(57, 23, 0.02);
    BuildOptions build;
    build.leaf_size = 16;
    const std::vector<TreeReplay> done = replay_trees(changed.doc, changed.mesh, recipes, build);
    ASSERT_EQ(done.size(), 2u);
    EXPECT_EQ(done[0].tree, "walking");
    EXPECT_FALSE(done[0].built_automatically);
    EXPECT_EQ(done[0].steps, 2u);
    EXPECT_EQ(done[0].report.replayed, 2u);
    EXPECT_TRUE(done[1].built_automatically);
    ASSERT_EQ(changed.doc.trees.size(), 2u);
    EXPECT_EQ(changed.doc.trees[0].recipe().size(), 2u);
    EXPECT_EQ(changed.doc.trees[1].name(), "plain");
    for (const TreeNode* n : changed.doc.trees[1].active_nodes()) EXPECT_LE(n->samples.size(), 16u);
    for (const SamplingTree& t : changed.doc.trees) EXPECT_EQ(t.validate(uint32_t(changed.doc.samples.size())), "");
}

TEST(Recipe, AppendTreeAddsANamedTreeAndReplacesItOnlyWhenAsked) {
    Authored a = authored(40, 20, 0.0);
    BuildOptions build;
    build.leaf_size = 2;
    ConvertStats st;
    const SamplingTree& walk = append_tree(a.doc, a.mesh, "walk", build, false, "t.spt", &st);
    EXPECT_EQ(walk.name(), "walk");
    for (const TreeNode* n : walk.active_nodes()) EXPECT_LE(n->samples.size(), 2u);
    EXPECT_EQ(st.vertex_samples + st.face_samples, a.doc.samples.size());
    ASSERT_EQ(a.doc.trees.size(), 2u);
    try {
        append_tree(a.doc, a.mesh, "walk", build, false, "t.spt");
        ADD_FAILURE() << "the same name was taken without replace";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::CannotWrite);
        EXPECT_NE(std::string(e.what()).find("t.spt"), std::string::npos) << e.what();
    }
    append_tree(a.doc, a.mesh, "walk", BuildOptions{}, true, "t.spt");
    EXPECT_EQ(a.doc.trees.size(), 2u);
    // Another mesh: refused, the document as it was.
    const Authored other = authored(57, 23, 0.02);
    try {
        append_tree(a.doc, other.mesh, "x", build, false, "t.spt");
        ADD_FAILURE() << "a tree was added over another mesh's samples";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    }
    EXPECT_EQ(a.doc.trees.size(), 2u);
}
