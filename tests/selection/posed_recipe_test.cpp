// Selection and recipes at a pose of an animated mesh: a rectangle selects the samples where the
// pose puts them (SamplePoints), a split's pose is kept by .spt version 4, and a recipe made at a
// pose replays at that pose (the editor's timeline; docs/deforming.md, docs/spt-format.md).
#include "spt/animation.hpp"
#include "spt/convert.hpp"
#include "spt/deforming_model.hpp"
#include "spt/error.hpp"
#include "spt/recipe.hpp"
#include "spt/selection.hpp"
#include "spt/spt_file.hpp"
#include "posed_bar.hpp"
#include "spt_reseal.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <cstring>

using namespace spt;

namespace {

// The bar with its clips, converted with the defaults.
struct Bar {
    std::shared_ptr<const AnimatedMesh> mesh = std::make_shared<AnimatedMesh>(import_animated_mesh(test::anim_data("bending_bar.gltf")));
    SptDocument doc = make_document(mesh->imported.mesh);
};

const Bar& bar() {
    static const Bar b;
    return b;
}

const Clip* clip(const Bar& b, const std::string& name) { return &b.mesh->clips[b.mesh->find_clip(name)]; }

ViewProjection posed_bar_front_view() { return test::bar_front_view(); }
RecipeStroke above() { return test::above_the_bar(); }

// Samples whose surface point at `points` (local frame) lies above object y = 0.45.
std::vector<uint32_t> above_in(const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3d& origin) {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < points.size(); ++i)
        if (origin.y() + points[i].y() >= 0.45) out.push_back(i);
    return out;
}

// The document with tree "t" split once by `above()` at clip `name`'s time `t`, recorded.
SptDocument split_at_pose(const Bar& b, const std::string& name, double t) {
    SptDocument doc = b.doc;
    DeformingModel posed(doc, b.mesh, "", false);
    posed.pose(clip(b, name), t);
    SamplingTree tree = unsplit_tree("t", doc.samples);
    const RecipeStep step{1, {above()}, {name, t}};
    const SamplePoints points(posed.sample_points(), doc.samples.origin);
    EXPECT_TRUE(tree.split(1, select_strokes(points, tree, step, nullptr), doc.samples));
    tree.add_recipe_step(step);
    doc.trees = {std::move(tree)};
    return doc;
}

void append(std::vector<uint8_t>& bytes, const void* p, size_t n) {
    const auto* b = static_cast<const uint8_t*>(p);
    bytes.insert(bytes.end(), b, b + n);
}

std::vector<uint8_t> resealed(std::vector<uint8_t> bytes) {
    test::reseal(bytes);
    return bytes;
}

uint32_t file_version(const std::vector<uint8_t>& bytes) {
    uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 8, 4);
    return version;
}

} // namespace

TEST(Selection, PosedPointsSelectTheSamplesWhereThePosePutsThem) {
    const Bar& b = bar();
    const SamplingTree& tree = b.doc.trees.front();
    DeformingModel posed(b.doc, b.mesh, "", false);
    posed.pose(clip(b, "step"), 1.0);
    const SamplePoints points(posed.sample_points(), b.doc.samples.origin);
    const std::vector<uint32_t> hits = samples_in_rect(points, tree, root_id(), posed_bar_front_view(), above().rect);
    EXPECT_EQ(hits, above_in(posed.sample_points(), b.doc.samples.origin));
    ASSERT_FALSE(hits.empty());
    // The tip's samples: at the bind pose they lie along the bar's far half, where the same
    // rectangle selects nothing.
    for (uint32_t i : hits) EXPECT_GT(b.doc.samples.position(i).x(), 1.3) << "sample " << i;
    EXPECT_TRUE(samples_in_rect(b.doc.samples, tree, root_id(), posed_bar_front_view(), above().rect).empty());
    // The same as a sample set whose own points are the posed ones.
    SampleSet moved = b.doc.samples;
    moved.points = posed.sample_points();
    EXPECT_EQ(samples_in_rect(moved, tree, root_id(), posed_bar_front_view(), above().rect), hits);
}

TEST(Selection, FewerPointsThanTheTreesSamplesIsAUsageError) {
    const Bar& b = bar();
    const std::vector<Eigen::Vector3f> few(b.doc.samples.points.begin(), b.doc.samples.points.end() - 1);
    try {
        samples_in_rect(SamplePoints(few, b.doc.samples.origin), b.doc.trees.front(), root_id(), posed_bar_front_view(), above().rect);
        ADD_FAILURE() << "points of another sample set were read";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Usage) << e.what();
    }
}

TEST(Recipe, Version4KeepsEachStepsPoseAndOnlyAPosedStepNeedsIt) {
    const SptDocument doc = split_at_pose(bar(), "step", 1.0);
    const std::vector<uint8_t> bytes = encode_spt(doc);
    EXPECT_EQ(spt_version_for(doc), 4u);
    EXPECT_EQ(file_version(bytes), 4u);
    const SptDocument back = decode_spt(bytes);
    ASSERT_EQ(back.trees.front().recipe().size(), 1u);
    EXPECT_EQ(back.trees.front().recipe().front().pose, (RecipePose{"step", 1.0}));
    EXPECT_EQ(encode_spt(back), bytes);
    // The same steps at the bind pose are version 3, as they were before poses.
    SptDocument bind = back;
    std::vector<RecipeStep> steps = bind.trees.front().recipe();
    steps.front().pose = {};
    bind.trees.front().set_recipe(steps);
    const std::vector<uint8_t> v3 = encode_spt(bind);
    EXPECT_EQ(file_version(v3), 3u);
    EXPECT_EQ(encode_spt(decode_spt(v3)), v3);
    EXPECT_EQ(bytes.size(), v3.size() + 4 + 4 + 8) << "version 4 adds a clip name and a time to the step";
}

TEST(Recipe, AStepsPoseIsCheckedWhenRead) {
    const SptDocument doc = split_at_pose(bar(), "step", 1.0);
    const std::vector<uint8_t> good = encode_spt(doc);
    // The file ends with the one step's pose: u32 4, "step", f64 1.0.
    const size_t pose_at = good.size() - (4 + 4 + 8);
    auto refused = [](const std::vector<uint8_t>& bytes, const std::string& why) {
        try {
            decode_spt(bytes, "posed.spt");
            ADD_FAILURE() << "read a file with " << why;
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::BadInput) << e.what();
            EXPECT_NE(std::string(e.what()).find("posed.spt: byte "), std::string::npos) << e.what();
        }
    };
    for (double bad : {std::nan(""), -1.0, double(INFINITY)}) {
        std::vector<uint8_t> bytes = good;
        std::memcpy(bytes.data() + bytes.size() - 8, &bad, 8);
        refused(resealed(bytes), "the time " + std::to_string(bad));
    }
    // The bind pose (no clip) has one encoding: time 0.
    std::vector<uint8_t> bind_with_time(good.begin(), good.begin() + long(pose_at));
    const uint32_t empty = 0;
    const double one = 1.0;
    append(bind_with_time, &empty, 4), append(bind_with_time, &one, 8);
    refused(resealed(bind_with_time), "a time at the bind pose");
    // A version 4 header on steps that all hold the bind pose: the file is version 3.
    std::vector<uint8_t> no_pose(good.begin(), good.begin() + long(pose_at));
    const double zero = 0;
    append(no_pose, &empty, 4), append(no_pose, &zero, 8);
    refused(resealed(no_pose), "version 4 without a pose");
    EXPECT_EQ(encode_spt(decode_spt(resealed(std::vector<uint8_t>(good)))), good);
}

TEST(Recipe, ARecipeMadeAtAPoseReplaysToTheSameTreeOnTheSameMesh) {
    const Bar& b = bar();
    const SptDocument authored = split_at_pose(b, "step", 1.0);
    const SamplingTree& t = authored.trees.front();
    ReplayReport report;
    const SamplingTree again = replay_recipe(t, b.doc, b.mesh, &report);
    EXPECT_EQ(report.replayed, 1u);
    EXPECT_TRUE(report.skipped.empty());
    EXPECT_EQ(encode_spt({b.doc.mesh, b.doc.samples, {again}}), encode_spt(authored));
    // At the bind pose the same rectangle selects nothing: it is the pose that made the split.
    SamplingTree unposed = t;
    std::vector<RecipeStep> steps = t.recipe();
    steps.front().pose = {};
    unposed.set_recipe(steps);
    ReplayReport at_bind;
    EXPECT_TRUE(replay_recipe(unposed, b.doc, b.mesh, &at_bind).find(root_id())->active);
    ASSERT_EQ(at_bind.skipped.size(), 1u);
    EXPECT_NE(at_bind.skipped.front().find("none"), std::string::npos) << at_bind.skipped.front();
}

TEST(Recipe, AnOldRecipeWithoutPosesReplaysAsBefore) {
    // Two steps at the bind pose: the overload that poses gives what the one without a mesh's
    // animation gives.
    const Bar& b = bar();
    SamplingTree t = unsplit_tree("t", b.doc.samples);
    const RecipeStep first{1, {{posed_bar_front_view(), test::bar_band(-1, 1.5f), SelectionMode::Replace, false}}};
    ASSERT_TRUE(t.split(1, select_strokes(b.doc.samples, t, first, &b.mesh->imported.mesh), b.doc.samples));
    t.add_recipe_step(first);
    const RecipeStep second{3, {{posed_bar_front_view(), test::bar_band(-1, 1.75f), SelectionMode::Replace, true}}};
    ASSERT_TRUE(t.split(3, select_strokes(b.doc.samples, t, second, &b.mesh->imported.mesh), b.doc.samples));
    t.add_recipe_step(second);
    ReplayReport old_report, posed_report;
    const SamplingTree old_way = replay_recipe(t, b.doc.samples, b.mesh->imported.mesh, &old_report);
    const SamplingTree posed_way = replay_recipe(t, b.doc, b.mesh, &posed_report);
    EXPECT_EQ(old_report.replayed, 2u);
    EXPECT_EQ(posed_report.replayed, 2u);
    EXPECT_EQ(encode_spt({b.doc.mesh, b.doc.samples, {posed_way}}), encode_spt({b.doc.mesh, b.doc.samples, {old_way}}));
    EXPECT_EQ(encode_spt({b.doc.mesh, b.doc.samples, {old_way}}), encode_spt({b.doc.mesh, b.doc.samples, {t}}));
}

TEST(Recipe, AClipTheNewMeshLacksIsBadInputNamingTheClipsItHas) {
    const Bar& b = bar();
    SamplingTree t = split_at_pose(b, "step", 1.0).trees.front();
    std::vector<RecipeStep> steps = t.recipe();
    steps.front().pose.clip = "run";
    t.set_recipe(steps);
    try {
        replay_recipe(t, b.doc, b.mesh);
        ADD_FAILURE() << "a clip the mesh lacks was replayed";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        for (const char* name : {"'run'", "'linear'", "'step'", "'cubic'", "bending_bar.gltf"})
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
    // Without the mesh's animation a posed step cannot be replayed either.
    try {
        replay_recipe(split_at_pose(b, "step", 1.0).trees.front(), b.doc.samples, b.mesh->imported.mesh);
        ADD_FAILURE() << "a posed step was replayed at the bind pose";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        EXPECT_NE(std::string(e.what()).find("no clips"), std::string::npos) << e.what();
    }
}

TEST(Recipe, ReplayTreesPosesTheSamplesForAPosedRecipe) {
    const Bar& b = bar();
    const SptDocument recipes = split_at_pose(b, "step", 1.0);
    EXPECT_TRUE(recipe_has_poses(recipes));
    EXPECT_FALSE(recipe_has_poses(b.doc));
    SptDocument doc = b.doc;
    const std::vector<TreeReplay> done = replay_trees(doc, b.mesh->imported.mesh, recipes, BuildOptions{}, b.mesh);
    ASSERT_EQ(done.size(), 1u);
    EXPECT_EQ(done.front().report.replayed, 1u);
    EXPECT_EQ(encode_spt(doc), encode_spt(recipes));
    SptDocument without = b.doc;
    EXPECT_THROW(replay_trees(without, b.mesh->imported.mesh, recipes, BuildOptions{}), Error);
    EXPECT_EQ(encode_spt(without), encode_spt(b.doc)) << "a failed replay leaves the document as it was";
}
