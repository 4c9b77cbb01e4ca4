// Recording a scene's motion of one object: which samples were in contact, where the object was,
// and bad input named.
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "spt/motion.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>

using namespace spt;

namespace {

std::string scene_file(const std::string& name) { return std::string(SPT_SOURCE_DIR) + "/resources/scenes/" + name; }

// The walking figure's document and its animated mesh, as walking.json uses them.
MotionModel walker() {
    auto mesh = std::make_shared<AnimatedMesh>(
        import_animated_mesh(std::string(SPT_SOURCE_DIR) + "/resources/models/walking_figure.gltf"));
    auto doc = std::make_shared<SptDocument>(load_spt(scene_file("figure_walk.spt")));
    return {doc, "walk", mesh};
}

} // namespace

TEST(RecordMotion, TheWalkersContactSamplesAreItsFeetAtTheFloor) {
    const Scene scene = load_scene(scene_file("walking.json"));
    const MotionModel model = walker();
    MotionOptions options;
    options.steps = 60;
    int progress_calls = 0;
    options.progress = [&](int done, int total) {
        ++progress_calls;
        EXPECT_EQ(total, 60);
        EXPECT_EQ(done, progress_calls);
    };
    const MotionRecording rec = record_motion(scene, "walker", model, options);
    EXPECT_EQ(progress_calls, 60);
    ASSERT_EQ(rec.steps.size(), 60u);
    EXPECT_EQ(rec.clip, "walk");
    EXPECT_EQ(rec.steps_in_contact, 60u) << "the figure walks 1 cm into the floor";
    ASSERT_EQ(rec.contact_steps.size(), model.document->samples.size());
    EXPECT_GT(rec.most_contact_steps, 0u);
    // Every sample in contact is near the soles (the figure's bind pose stands on y = 0, 1.9 tall).
    size_t in_contact = 0;
    for (size_t i = 0; i < rec.contact_steps.size(); ++i) {
        if (!rec.contact_steps[i]) continue;
        ++in_contact;
        EXPECT_LT(model.document->samples.position(i).y(), 0.12) << "sample " << i;
    }
    EXPECT_GT(in_contact, 10u);
    // Poses follow the path (z from -1.4 towards 1.4); clip times advance with the steps.
    EXPECT_LT(rec.steps.front().pose.translation.z(), rec.steps.back().pose.translation.z());
    EXPECT_GT(rec.steps[10].clip_time, rec.steps[0].clip_time);
    for (const MotionStep& st : rec.steps) {
        ASSERT_EQ(st.partners.size(), 1u);
        EXPECT_EQ(st.partners.front().object, 0u) << "the floor";
        EXPECT_TRUE(st.partners.front().contact);
    }
    // Samples near the floor are recorded at evenly spread steps, the last among them.
    ASSERT_FALSE(rec.reaches.empty());
    EXPECT_EQ(rec.reaches.back().step, 59u);
    for (const MotionReach& r : rec.reaches)
        for (const auto& [s, gap] : r.near) EXPECT_TRUE(gap >= 0 && gap < rec.reach);
}

TEST(RecordMotion, TheSameSceneAndModelRecordTheSame) {
    const Scene scene = load_scene(scene_file("fig8.json"));
    auto doc = std::make_shared<SptDocument>(load_or_convert(std::string(SPT_SOURCE_DIR) + "/resources/meshes/torus.obj"));
    const MotionRecording a = record_motion(scene, "torus", {doc, "", nullptr});
    MotionOptions two;
    two.threads = 2;
    const MotionRecording b = record_motion(scene, "torus", {doc, "", nullptr}, two);
    EXPECT_EQ(a.contact_steps, b.contact_steps);
    ASSERT_EQ(a.steps.size(), b.steps.size());
    for (size_t k = 0; k < a.steps.size(); ++k) {
        EXPECT_EQ(a.steps[k].pose.translation, b.steps[k].pose.translation);
        EXPECT_EQ(a.steps[k].partners.size(), b.steps[k].partners.size());
    }
    ASSERT_EQ(a.reaches.size(), b.reaches.size());
    for (size_t k = 0; k < a.reaches.size(); ++k) EXPECT_EQ(a.reaches[k].near, b.reaches[k].near);
    EXPECT_GT(a.steps_in_contact, 0u) << "the torus meets the part";
}

TEST(RecordMotion, AnObjectTheSceneLacksIsNamedWithTheOnesItHas) {
    const Scene scene = load_scene(scene_file("fig8.json"));
    auto doc = std::make_shared<SptDocument>(load_or_convert(std::string(SPT_SOURCE_DIR) + "/resources/meshes/torus.obj"));
    try {
        record_motion(scene, "teapot", {doc, "", nullptr});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        const std::string what = e.what();
        EXPECT_NE(what.find("'teapot'"), std::string::npos) << what;
        EXPECT_NE(what.find("'torus', 'part'"), std::string::npos) << what;
    }
}

TEST(RecordMotion, ADocumentOfAnotherMeshIsRefusedForAnAnimatedObject) {
    const Scene scene = load_scene(scene_file("walking.json"));
    auto doc = std::make_shared<SptDocument>(load_or_convert(std::string(SPT_SOURCE_DIR) + "/resources/meshes/torus.obj"));
    EXPECT_THROW(record_motion(scene, "walker", {doc, "", nullptr}), Error);
}

TEST(RecordMotion, CancelStopsBetweenSteps) {
    const Scene scene = load_scene(scene_file("fig8.json"));
    auto doc = std::make_shared<SptDocument>(load_or_convert(std::string(SPT_SOURCE_DIR) + "/resources/meshes/torus.obj"));
    std::atomic<bool> cancel{false};
    MotionOptions options;
    options.cancel = &cancel;
    options.progress = [&](int done, int) {
        if (done == 5) cancel = true;
    };
    EXPECT_THROW(record_motion(scene, "torus", {doc, "", nullptr}, options), Cancelled);
}
