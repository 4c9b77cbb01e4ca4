// Scene files: defaults, the issue's example, keyframed paths, and bad files refused with
// the file and the JSON path of the problem.
#include "scene_fixture.hpp"
#include "spt/error.hpp"
#include "spt/scene.hpp"
#include <cstdlib>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

using namespace spt;

std::string refusal(const std::string& text) { return test::parse_refusal(text); }

const char* kIssueExample = R"({
  "spt_scene": 1, "dt": 0.01, "steps": 300, "gravity": [0, -9.81, 0],
  "effects": ["motion", "gravity", "contacts", "depth", "response"],
  "response": {"rule": "backtrack", "restitution": 0.3},
  "level": "spheres",
  "objects": [
    {"name": "floor", "model": "floor.spt", "static": true, "position": [0, -1, 0]},
    {"name": "walker", "model": "figure.obj", "tree": "walk", "scale": 1.0,
     "position": [0, 0.5, 0], "orientation": [1, 0, 0, 0],
     "velocity": [1, 0, 0], "angular_velocity": [0, 0, 0]},
    {"name": "door", "model": "box.ply",
     "path": [{"t": 0, "position": [2, 0, 0], "orientation": [1, 0, 0, 0]},
              {"t": 1.5, "position": [2, 0, 1], "orientation": [0.7071068, 0, 0.7071068, 0]}]}
  ]
})";

TEST(SceneParse, TheIssueExampleReadsAsWritten) {
    const Scene s = parse_scene(kIssueExample, "example.json", "/scenes");
    EXPECT_EQ(s.steps, 300);
    EXPECT_EQ(s.response.rule, BacktrackRule::Exact);
    EXPECT_DOUBLE_EQ(s.response.restitution, 0.3);
    EXPECT_EQ(s.effects.names(), "motion,gravity,contacts,depth,response");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(s.objects[0].motion, MotionKind::Static);
    EXPECT_EQ(s.objects[0].model_path, "/scenes/floor.spt"); // relative to the scene file
    EXPECT_EQ(s.objects[1].motion, MotionKind::Velocity);
    EXPECT_EQ(s.objects[1].tree, "walk");
    EXPECT_EQ(s.objects[1].velocity, Eigen::Vector3d(1, 0, 0));
    EXPECT_EQ(s.objects[2].motion, MotionKind::Path);
    EXPECT_EQ(s.objects[2].pose.translation, Eigen::Vector3d(2, 0, 0)); // the path at t = 0
}

TEST(SceneParse, DefaultsAreThoseTheIssueGives) {
    const Scene s = parse_scene(R"({"spt_scene": 1, "objects": [{"name": "a", "model": "a.obj"}]})", "d.json", "");
    EXPECT_DOUBLE_EQ(s.dt, 0.01);
    EXPECT_EQ(s.steps, 100);
    EXPECT_EQ(s.gravity, Eigen::Vector3d(0, -9.81, 0));
    EXPECT_EQ(s.level, QueryLevel::Spheres);
    EXPECT_EQ(s.response.rule, BacktrackRule::Exact);
    EXPECT_EQ(s.response.restitution, 0);
    EXPECT_EQ(s.effects.bits(), 0u); // nothing is switched on silently
    EXPECT_EQ(s.objects[0].motion, MotionKind::Velocity);
    EXPECT_EQ(s.objects[0].scale, 1);
}

TEST(SceneParse, PathIsLinearInPositionAndSlerpInOrientation) {
    const Eigen::Quaterniond q1(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
    const std::vector<Keyframe> path = {{0, {2, 0, 0}, Eigen::Quaterniond::Identity()}, {1.5, {2, 0, 1}, q1}};
    const Pose mid = path_pose(path, 0.75);
    EXPECT_NEAR((mid.translation - Eigen::Vector3d(2, 0, 0.5)).norm(), 0, 1e-12);
    const Eigen::Quaterniond half(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitY()));
    EXPECT_NEAR(mid.rotation.angularDistance(half), 0, 1e-9);
    EXPECT_EQ(path_pose(path, -1).translation, Eigen::Vector3d(2, 0, 0)); // held before the first key
    EXPECT_EQ(path_pose(path, 9).translation, Eigen::Vector3d(2, 0, 1));  // and after the last
}

TEST(SceneParse, PathVelocityIsEachSegmentsSlopeAndTurnRateAndZeroWhereThePathHolds) {
    const Eigen::Quaterniond q1(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
    // The second segment turns back the long way round in value, the short way in motion.
    const Eigen::Quaterniond q2 = Eigen::Quaterniond(-q1.w(), -q1.x(), -q1.y(), -q1.z()) * Eigen::Quaterniond(Eigen::AngleAxisd(-M_PI / 4, Eigen::Vector3d::UnitY()));
    const std::vector<Keyframe> path = {{0, {2, 0, 0}, Eigen::Quaterniond::Identity()}, {1.5, {2, 0, 1}, q1}, {2.5, {2, 3, 1}, q2}};
    const auto [v0, w0] = path_velocity(path, 0.75);
    EXPECT_NEAR((v0 - Eigen::Vector3d(0, 0, 1 / 1.5)).norm(), 0, 1e-12);
    EXPECT_NEAR((w0 - Eigen::Vector3d(0, (M_PI / 2) / 1.5, 0)).norm(), 0, 1e-9);
    const auto [v1, w1] = path_velocity(path, 1.5); // at a key: the segment it starts
    EXPECT_NEAR((v1 - Eigen::Vector3d(0, 3, 0)).norm(), 0, 1e-12);
    EXPECT_NEAR((w1 - Eigen::Vector3d(0, -M_PI / 4, 0)).norm(), 0, 1e-9);
    // The velocity carries the pose along the path: a small step of it lands on path_pose.
    const double t = 0.4, h = 1e-6;
    const Pose a = path_pose(path, t), b = path_pose(path, t + h);
    const auto [v, w] = path_velocity(path, t);
    EXPECT_NEAR((a.translation + h * v - b.translation).norm(), 0, 1e-12);
    const Eigen::Quaterniond stepped = Eigen::Quaterniond(Eigen::AngleAxisd(w.norm() * h, w.normalized())) * a.rotation;
    EXPECT_NEAR(stepped.angularDistance(b.rotation), 0, 1e-9);
    for (double held : {-1.0, 2.5, 9.0}) {
        const auto [vh, wh] = path_velocity(path, held);
        EXPECT_EQ(vh, Eigen::Vector3d::Zero()) << held;
        EXPECT_EQ(wh, Eigen::Vector3d::Zero()) << held;
    }
}

TEST(SceneParse, InvalidJsonNamesTheFileLineAndPath) {
    const std::string m = refusal("{\"spt_scene\": 1,\n \"objects\": [{\"name\": \"a\",, }]}");
    EXPECT_NE(m.find("bad.json"), std::string::npos) << m;
    EXPECT_NE(m.find("line 2"), std::string::npos) << m;
    EXPECT_NE(m.find("/objects/0"), std::string::npos) << m;
}

TEST(SceneParse, NanIsRefusedAtItsPath) {
    const std::string m = refusal(R"({"spt_scene": 1, "dt": NaN, "objects": []})");
    EXPECT_NE(m.find("bad.json"), std::string::npos) << m;
    EXPECT_NE(m.find("/dt"), std::string::npos) << m;
    const std::string big = refusal(R"({"spt_scene": 1, "objects": [{"name": "a", "model": "a.obj", "position": [0, 1e999, 0]}]})");
    EXPECT_NE(big.find("/objects/0/position/1"), std::string::npos) << big;
}

TEST(SceneParse, NegativeOrZeroDtIsRefused) {
    EXPECT_NE(refusal(R"({"spt_scene": 1, "dt": -0.01, "objects": []})").find("bad.json: at /dt: must be positive"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"spt_scene": 1, "dt": 0, "objects": []})").find("/dt"), std::string::npos);
}

TEST(SceneParse, UnknownFieldsAreRefusedWherever) {
    EXPECT_NE(refusal(R"({"spt_scene": 1, "objects": [], "colour": 1})").find("at /colour: unknown field 'colour'"),
              std::string::npos);
    const std::string m = refusal(R"({"spt_scene": 1, "objects": [{"name": "a", "model": "a.obj", "colour": 2}]})");
    EXPECT_NE(m.find("at /objects/0/colour: unknown field 'colour'"), std::string::npos) << m;
    EXPECT_NE(refusal(R"({"spt_scene": 1, "objects": [], "response": {"friction": 1}})").find("/response/friction"),
              std::string::npos);
}

TEST(SceneParse, UnknownEffectAndMissingDependencyAreRefusedNamingBoth) {
    const std::string unknown = refusal(R"({"spt_scene": 1, "effects": ["motion", "flying"], "objects": []})");
    EXPECT_NE(unknown.find("unknown effect 'flying'"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("/effects"), std::string::npos) << unknown;
    const std::string missing = refusal(R"({"spt_scene": 1, "effects": ["contacts", "response"], "objects": []})");
    EXPECT_NE(missing.find("effect 'response' needs effect 'depth'"), std::string::npos) << missing;
    EXPECT_NE(refusal(R"({"spt_scene": 1, "effects": ["contacts", "ccd"], "objects": []})")
                  .find("effect 'ccd' needs effect 'motion'"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"spt_scene": 1, "effects": ["gravity"], "objects": []})").find("'gravity' needs effect 'motion'"),
              std::string::npos);
}

TEST(SceneParse, ContradictoryMotionsAreRefused) {
    EXPECT_NE(refusal(R"({"spt_scene": 1, "objects": [{"name": "a", "model": "a.obj", "static": true,
        "velocity": [1, 0, 0]}]})").find("/objects/0"), std::string::npos);
    EXPECT_NE(refusal(R"({"spt_scene": 1, "objects": [{"name": "a", "model": "a.obj",
        "path": [{"t": 1}, {"t": 0.5}]}]})").find("/objects/0/path/1/t"), std::string::npos);
    EXPECT_NE(refusal(R"({"spt_scene": 1, "objects": [{"name": "a", "model": "a.obj"}, {"name": "a", "model": "b.obj"}]})")
                  .find("/objects/1/name"),
              std::string::npos);
}

TEST(SceneParse, MissingModelIsRefusedWithItsPath) {
    const spt::test::SceneDir dir;
    const std::string path = dir.write("missing.json", R"({"spt_scene": 1, "objects": [
        {"name": "a", "model": "box.obj"}, {"name": "b", "model": "nowhere.obj"}]})");
    try {
        load_scene(path);
        FAIL() << "a missing model was accepted";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        EXPECT_NE(m.find("missing.json: at /objects/1/model"), std::string::npos) << m;
        EXPECT_NE(m.find("nowhere.obj"), std::string::npos) << m;
    }
}

// Import bounds a mesh as read (1e-15 across to 1e16 from the origin); a scale must keep it there.
TEST(SceneParse, AScaleThatTakesAMeshOutOfRangeIsRefusedWithItsPath) {
    const spt::test::SceneDir dir;
    for (const char* scale : {"1e-300", "1e-18", "1e20", "1e300"}) {
        const std::string path = dir.write("scaled.json", std::string(R"({"spt_scene": 1, "objects": [
            {"name": "a", "model": "box.obj"}, {"name": "b", "model": "ball.obj", "scale": )") + scale + "}]}");
        try {
            load_scene(path);
            ADD_FAILURE() << "scale " << scale << " was accepted";
        } catch (const Error& e) {
            const std::string m = e.what();
            EXPECT_EQ(e.kind(), ErrorKind::BadInput);
            EXPECT_NE(m.find("scaled.json: at /objects/1/model: 'scale'"), std::string::npos) << m;
            EXPECT_NE(m.find(std::atof(scale) < 1 ? "smaller than 1e-15 across" : "beyond 1e16"), std::string::npos) << m;
        }
    }
}

TEST(SceneParse, ModelsAreLoadedOnceAndTheirSphereHoldsEveryVertex) {
    const spt::test::SceneDir dir;
    const std::string path = dir.write("two.json", R"({"spt_scene": 1, "objects": [
        {"name": "a", "model": "box.obj"}, {"name": "b", "model": "box.obj", "position": [3, 0, 0]},
        {"name": "c", "model": "box.obj", "scale": 2}]})");
    const Scene s = load_scene(path);
    EXPECT_EQ(s.objects[0].model.get(), s.objects[1].model.get());
    EXPECT_NE(s.objects[0].model.get(), s.objects[2].model.get());
    EXPECT_NEAR(s.objects[2].model->diagonal(), 2 * s.objects[0].model->diagonal(), 1e-9);
    // Every corner of the unit cube lies inside the bounding sphere.
    for (int i = 0; i < 8; ++i) {
        const Eigen::Vector3d corner((i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5);
        EXPECT_LE((corner - s.objects[0].bound_center).norm(), s.objects[0].bound_radius);
    }
}

TEST(SceneParse, ACancelledLoadStopsAndCachesNothingSoTheNextLoadSucceeds) {
    // The viewer drops a scene still converting its meshes (closed, or its file reloaded).
    const spt::test::SceneDir dir;
    const std::string path = dir.write("one.json", R"({"spt_scene": 1, "objects": [{"name": "a", "model": "box.obj"}]})");
    std::atomic<bool> cancel{true};
    EXPECT_THROW(load_scene(path, &cancel), Cancelled);
    const Scene s = load_scene(path);
    ASSERT_TRUE(s.objects[0].model);
    EXPECT_GT(s.objects[0].model->tree().sphere_count(), 0u);
}

// The schema (docs/scene.schema.json) and the parser agree on every field and effect.
TEST(SceneSchema, ParserAcceptsEveryFieldTheSchemaListsAndTheSchemaListsEveryEffect) {
    std::ifstream in(std::string(SPT_SOURCE_DIR) + "/docs/scene.schema.json");
    const nlohmann::json schema = nlohmann::json::parse(in);
    std::vector<std::string> effects;
    for (const auto& e : schema["properties"]["effects"]["items"]["enum"]) effects.push_back(e.get<std::string>());
    ASSERT_EQ(effects.size(), size_t(kEffectCount));
    for (int i = 0; i < kEffectCount; ++i) EXPECT_EQ(effects[size_t(i)], effect_name(Effect(i)));
    // A value of the right type for every property of each level, taken from the schema's defaults.
    auto sample = [](const nlohmann::json& prop) -> nlohmann::json {
        if (prop.contains("default")) return prop["default"];
        if (prop.contains("const")) return prop["const"];
        if (prop.contains("enum")) return prop["enum"][0];
        return nullptr;
    };
    nlohmann::json scene = nlohmann::json::object();
    for (auto& [k, v] : schema["properties"].items())
        if (k != "objects" && k != "response" && k != "dynamics") scene[k] = sample(v);
    for (const char* block : {"response", "dynamics"}) {
        scene[block] = nlohmann::json::object();
        for (auto& [k, v] : schema["properties"][block]["properties"].items()) scene[block][k] = sample(v);
    }
    nlohmann::json object = {{"name", "o"}, {"model", "o.obj"}, {"tree", "t"}, {"mesh", "o.gltf"}};
    // Without a default: mass (it excludes density), friction, restitution and rolling friction (unset: the scene's).
    object["friction"] = 0.3, object["restitution"] = 0.1, object["rolling_friction"] = 0.01;
    for (auto& [k, v] : schema["$defs"]["object"]["properties"].items())
        if (!object.contains(k) && k != "path" && k != "mass") object[k] = sample(v);
    nlohmann::json key = nlohmann::json::object();
    for (auto& [k, v] : schema["$defs"]["keyframe"]["properties"].items()) key[k] = k == "t" ? nlohmann::json(0) : sample(v);
    nlohmann::json on_path = {{"name", "p"}, {"model", "p.obj"}, {"path", {key}}};
    scene["objects"] = {object, on_path};
    EXPECT_NO_THROW(parse_scene(scene.dump(), "schema.json", "")) << scene.dump();
    // And refuses a field the schema does not list, at every level.
    for (const char* where : {"", "/response", "/dynamics", "/objects/0", "/objects/1/path/0"}) {
        nlohmann::json bad = scene;
        bad[nlohmann::json::json_pointer(where)]["not_in_schema"] = 1;
        EXPECT_NE(refusal(bad.dump()).find(std::string(where) + "/not_in_schema"), std::string::npos) << where;
    }
}

} // namespace
