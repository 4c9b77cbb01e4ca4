// `spt convert NEW --recipe OLD.spt` with splits made at a clip's pose (the editor's timeline):
// replayed with NEW posed as each split was made, a clip NEW lacks refused naming its clips, and
// a recipe without poses replayed as before.
#include "posed_bar.hpp"
#include "run_command.hpp"
#include "spt/animation.hpp"
#include "spt/convert.hpp"
#include "spt/deforming_model.hpp"
#include "spt/recipe.hpp"
#include "spt/selection.hpp"
#include "spt_reseal.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <fstream>

using namespace spt;
using namespace spt::test;

namespace {

// bending_bar.gltf converted, its tree split once by above_the_bar() at `pose` (at the bind pose,
// where that selects nothing, by x <= 1 instead), saved as `path`; returns the tree.
SamplingTree write_recipe(const std::string& path, const RecipePose& pose) {
    const auto mesh = std::make_shared<AnimatedMesh>(import_animated_mesh(anim_data("bending_bar.gltf")));
    SptDocument doc = make_document(mesh->imported.mesh);
    SamplingTree tree = unsplit_tree("authored", doc.samples);
    RecipeStep step{1, {above_the_bar()}, pose};
    std::vector<uint32_t> selection;
    if (pose.bind()) {
        step.strokes.front().rect = bar_band(-1, 1);
        selection = select_strokes(doc.samples, tree, step, &mesh->imported.mesh);
    } else {
        DeformingModel posed(doc, mesh, "", false);
        posed.pose(&mesh->clips[mesh->find_clip(pose.clip)], pose.time);
        selection = select_strokes(SamplePoints(posed.sample_points(), doc.samples.origin), tree, step, nullptr);
    }
    EXPECT_TRUE(tree.split(1, selection, doc.samples));
    tree.add_recipe_step(step);
    doc.trees = {tree};
    save_spt(doc, path);
    return tree;
}

} // namespace

TEST(ConvertCli, ARecipeMadeAtAPoseReplaysAtThatPoseOnTheNewMesh) {
    TempDir out("recipe-posed");
    const SamplingTree authored = write_recipe(out.file("old.spt"), {"step", 1.0});
    // The same bar exported again as GLB.
    const auto r = run_command(spt_binary() + " convert " + q(anim_data("bending_bar.glb")) + " --recipe " +
                               q(out.file("old.spt")) + " -o " + q(out.file("new.spt")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("tree 'authored': 1 of 1 splits replayed"), std::string::npos) << r.output;
    const SptDocument doc = load_spt(out.file("new.spt"));
    const SamplingTree* t = doc.tree("authored");
    ASSERT_NE(t, nullptr);
    ASSERT_NE(t->find(2), nullptr);
    EXPECT_EQ(t->find(2)->samples, authored.find(2)->samples);
    EXPECT_EQ(t->recipe().front().pose, (RecipePose{"step", 1.0})) << "the pose stays for the next export";
    EXPECT_EQ(spt_version_for(doc), 4u);
}

TEST(ConvertCli, ARecipesClipTheNewMeshLacksIsExitTwoNamingItsClips) {
    TempDir out("recipe-no-clip");
    write_recipe(out.file("old.spt"), {"step", 1.0});
    // A mesh without the clip: the same split asked of a figure with "walk" and "idle".
    auto r = run_command(spt_binary() + " convert " + q(std::string(SPT_SOURCE_DIR) + "/resources/models/walking_figure.gltf") +
                         " --recipe " + q(out.file("old.spt")) + " -o " + q(out.file("new.spt")));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    for (const char* what : {"'step'", "'walk'", "'idle'", "walking_figure.gltf"})
        EXPECT_NE(r.output.find(what), std::string::npos) << what << " in " << r.output;
    // A mesh without clips at all.
    r = run_command(spt_binary() + " convert " + q(project_meshes() + "/box.ply") + " --recipe " + q(out.file("old.spt")) +
                    " -o " + q(out.file("new.spt")));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("it has no clips"), std::string::npos) << r.output;
}

TEST(ConvertCli, ARecipeWithoutPosesReplaysAsBefore) {
    TempDir out("recipe-bind");
    const SamplingTree authored = write_recipe(out.file("old.spt"), {});
    EXPECT_EQ(spt_version_for(load_spt(out.file("old.spt"))), 3u);
    const auto r = run_command(spt_binary() + " convert " + q(anim_data("bending_bar.glb")) + " --recipe " +
                               q(out.file("old.spt")) + " -o " + q(out.file("new.spt")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const SptDocument doc = load_spt(out.file("new.spt"));
    EXPECT_EQ(doc.tree("authored")->find(2)->samples, authored.find(2)->samples);
    EXPECT_EQ(spt_version_for(doc), 3u);
}

TEST(ConvertCli, ARecipeWithGrowAndInvertStrokesReplaysFromVersion5) {
    TempDir out("recipe-v5");
    const auto mesh = std::make_shared<AnimatedMesh>(import_animated_mesh(anim_data("bending_bar.gltf")));
    SptDocument doc = make_document(mesh->imported.mesh);
    SamplingTree tree = unsplit_tree("authored", doc.samples);
    RecipeStroke band = above_the_bar();
    band.rect = bar_band(-1, 0);
    RecipeStroke grow, invert;
    grow.kind = StrokeKind::Grow, invert.kind = StrokeKind::Invert;
    const RecipeStep step{1, {band, grow, invert}};
    const SampleAdjacency adjacency(mesh->imported.mesh, doc.samples);
    ASSERT_TRUE(tree.split(1, select_strokes(doc.samples, tree, step, &mesh->imported.mesh, &adjacency), doc.samples));
    tree.add_recipe_step(step);
    doc.trees = {tree};
    save_spt(doc, out.file("old.spt"));
    const auto r = run_command(spt_binary() + " convert " + q(anim_data("bending_bar.glb")) + " --recipe " +
                               q(out.file("old.spt")) + " -o " + q(out.file("new.spt")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("tree 'authored': 1 of 1 splits replayed"), std::string::npos) << r.output;
    const SptDocument back = load_spt(out.file("new.spt"));
    const SamplingTree* t = back.tree("authored");
    ASSERT_NE(t, nullptr);
    ASSERT_NE(t->find(2), nullptr);
    EXPECT_EQ(t->find(2)->samples, tree.find(2)->samples);
    EXPECT_EQ(spt_version_for(back), 5u);
    // A damaged stroke kind: exit 2 naming the file and the byte.
    std::vector<uint8_t> bytes = encode_spt(doc);
    // The file ends with the invert stroke (156 bytes, no shape) and the step's pose (empty clip
    // name, time: 4 + 8 bytes); the stroke's kind byte follows its matrices (128 bytes) and 3 flags.
    const size_t invert_kind = bytes.size() - 12 - 156 + 128 + 3;
    ASSERT_EQ(bytes[invert_kind], uint8_t(StrokeKind::Invert));
    bytes[invert_kind] = 42;
    reseal(bytes);
    {
        std::ofstream f(out.file("bad.spt"), std::ios::binary);
        f.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    }
    const auto bad = run_command(spt_binary() + " convert " + q(anim_data("bending_bar.glb")) + " --recipe " +
                                 q(out.file("bad.spt")) + " -o " + q(out.file("new2.spt")));
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("bad.spt: byte "), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find("recipe stroke flags 0 0 0 42 are not valid"), std::string::npos) << bad.output;
}
