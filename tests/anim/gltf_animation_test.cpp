// glTF 2.0 animation samplers and skin weights read from the file itself (core/src/anim/
// gltf_file.cpp, gltf_animation.cpp), on the files tools/make_skinned_models.py writes into
// tests/data/anim/ and on corrupt copies of them.
#include "anim/gltf_animation.hpp"
#include "anim/rig_import.hpp"
#include "spt/animation.hpp"
#include "spt/error.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>

namespace spt {
namespace {

using json = nlohmann::json;

std::string data_file(const std::string& name) { return std::string(SPT_SOURCE_DIR) + "/tests/data/anim/" + name; }

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

const AnimatedMesh& gltf_bar() {
    static const AnimatedMesh m = import_animated_mesh(data_file("bending_bar.gltf"));
    return m;
}

uint32_t node_named(const Rig& rig, const std::string& name) {
    for (uint32_t i = 0; i < rig.nodes.size(); ++i)
        if (rig.nodes[i].name == name) return i;
    ADD_FAILURE() << "no node " << name;
    return 0;
}

// The tip's turn about z (degrees) in the clip named `clip` at `t`.
double tip_degrees(const AnimatedMesh& m, const std::string& clip, double t) {
    const Eigen::Affine3d tip = pose_nodes(m.rig, &m.clips[m.find_clip(clip)], t)[node_named(m.rig, "tip")];
    return std::atan2(tip.linear()(1, 0), tip.linear()(0, 0)) * 180 / M_PI;
}

// The message of the BadInput error `f` throws (a failure if it throws none or another kind).
template <class F>
std::string bad_input(F f) {
    try {
        f();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "no error";
    return "";
}

// Everything this reading of a glTF file does, as import_animated_mesh does it, on `path`, with
// the rig of the intact bar (so a corrupt copy's failure is this reader's, not assimp's).
void read_gltf_parts(const std::string& path) {
    detail::GltfFile file(path);
    detail::check_gltf_skin_weights(file);
    std::vector<Clip> clips;
    detail::apply_gltf_animation(file, gltf_bar().rig, {}, clips);
}

// `path` is refused by this reader, naming the file and saying `problem`.
void expect_reader_refuses(const std::string& path, const std::string& problem) {
    const std::string direct = bad_input([&] { read_gltf_parts(path); });
    EXPECT_NE(direct.find(path), std::string::npos) << direct;
    EXPECT_NE(direct.find(problem), std::string::npos) << direct;
}

// `path` is refused by this reader and by import_animated_mesh (where assimp may find the
// problem first), each naming the file.
void expect_refused(const std::string& path, const std::string& problem) {
    expect_reader_refuses(path, problem);
    const std::string whole = bad_input([&] { import_animated_mesh(path); });
    EXPECT_NE(whole.find(path), std::string::npos) << whole;
}

// A copy of bending_bar.gltf with its JSON changed by `edit`, written into `dir`.
std::string edited_bar(const test::TempDir& dir, const std::string& name, void (*edit)(json&)) {
    json j = json::parse(read_bytes(data_file("bending_bar.gltf")));
    edit(j);
    write_bytes(dir.file(name), j.dump(1));
    return dir.file(name);
}

TEST(GltfAnimation, StepHoldsTheEarlierKeyUntilTheNext) {
    const Clip& c = gltf_bar().clips[gltf_bar().find_clip("step")];
    ASSERT_EQ(c.nodes.size(), 1u);
    EXPECT_EQ(c.nodes[0].rotation.interpolation, Interpolation::Step);
    EXPECT_NEAR(tip_degrees(gltf_bar(), "step", 0.99), 0, 1e-9);
    EXPECT_NEAR(tip_degrees(gltf_bar(), "step", 1.0), 90, 1e-5);
    EXPECT_NEAR(tip_degrees(gltf_bar(), "step", 1.99), 90, 1e-5);
    EXPECT_NEAR(tip_degrees(gltf_bar(), "step", 2.0), 0, 1e-9);
    EXPECT_NEAR(tip_degrees(gltf_bar(), "linear", 0.99), 89.1, 1e-5); // the same keys, lerped
}

// The generator's comments give the spline's turn: 36.44, 60.23, 77.11 degrees at 0.25, 0.5,
// 0.75 s (and 60.23 at 1.5 s), where linear turns 22.5, 45 and 67.5.
TEST(GltfAnimation, CubicSplineGivesGltfsHermiteWithTheFilesTangents) {
    const Clip& c = gltf_bar().clips[gltf_bar().find_clip("cubic")];
    ASSERT_EQ(c.nodes.size(), 1u);
    const Track<Eigen::Vector4d>& r = c.nodes[0].rotation;
    EXPECT_EQ(r.interpolation, Interpolation::CubicSpline);
    ASSERT_EQ(r.in_tangents.size(), 3u);
    ASSERT_EQ(r.out_tangents.size(), 3u);
    EXPECT_NEAR(r.out_tangents[0].z(), M_PI / 2, 1e-6); // 180 degrees a second: dq/dt = (0, 0, pi/2, 0)
    EXPECT_NEAR(tip_degrees(gltf_bar(), "cubic", 0.25), 36.44, 0.005);
    EXPECT_NEAR(tip_degrees(gltf_bar(), "cubic", 0.5), 60.23, 0.005);
    EXPECT_NEAR(tip_degrees(gltf_bar(), "cubic", 0.75), 77.11, 0.005);
    EXPECT_NEAR(tip_degrees(gltf_bar(), "cubic", 1.5), 60.23, 0.005);
    EXPECT_NEAR(tip_degrees(gltf_bar(), "linear", 0.5), 45, 1e-5);
    EXPECT_NEAR(tip_degrees(gltf_bar(), "cubic", 1.0), 90, 1e-5);
}

TEST(GltfAnimation, ClipsKeepTheFilesNamesOrderDurationsAndJoints) {
    ASSERT_EQ(gltf_bar().clips.size(), 3u);
    const char* names[] = {"linear", "step", "cubic"};
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(gltf_bar().clips[i].name, names[i]);
        EXPECT_EQ(gltf_bar().clips[i].duration, 2.0);
        EXPECT_EQ(gltf_bar().clips[i].joints_animated, i == 0 ? 2u : 1u) << names[i]; // "linear" moves the root too
    }
}

template <class Value>
void expect_same_track(const Track<Value>& a, const Track<Value>& b) {
    EXPECT_EQ(a.interpolation, b.interpolation);
    EXPECT_EQ(a.times, b.times);
    EXPECT_EQ(a.values, b.values);
    EXPECT_EQ(a.in_tangents, b.in_tangents);
    EXPECT_EQ(a.out_tangents, b.out_tangents);
}

TEST(GltfAnimation, EmbeddedExternalAndGlbFormsGiveIdenticalClips) {
    for (const char* name : {"bending_bar_external.gltf", "bending_bar.glb"}) {
        const AnimatedMesh m = import_animated_mesh(data_file(name));
        ASSERT_EQ(m.clips.size(), gltf_bar().clips.size()) << name;
        for (size_t i = 0; i < m.clips.size(); ++i) {
            const Clip &a = m.clips[i], &b = gltf_bar().clips[i];
            EXPECT_EQ(a.name, b.name);
            EXPECT_EQ(a.duration, b.duration);
            EXPECT_EQ(a.joints_animated, b.joints_animated);
            ASSERT_EQ(a.nodes.size(), b.nodes.size());
            for (size_t k = 0; k < a.nodes.size(); ++k) {
                EXPECT_EQ(a.nodes[k].node, b.nodes[k].node);
                expect_same_track(a.nodes[k].translation, b.nodes[k].translation);
                expect_same_track(a.nodes[k].rotation, b.nodes[k].rotation);
                expect_same_track(a.nodes[k].scale, b.nodes[k].scale);
            }
        }
    }
}

// "inflate" turns target 0 (the +y face up by 0.5) on over the first second, then target 1
// (the +x face out by 0.25).
TEST(GltfAnimation, MorphWeightsFollowTheFilesSampler) {
    const AnimatedMesh m = import_animated_mesh(data_file("morph_cube.gltf"));
    ASSERT_EQ(m.clips.size(), 1u);
    ASSERT_EQ(m.clips[0].morphs.size(), 1u);
    EXPECT_EQ(m.clips[0].name, "inflate");
    EXPECT_EQ(m.clips[0].duration, 2.0);
    for (const auto& [t, w0, w1] : {std::tuple{0.5, 0.5, 0.0}, std::tuple{1.5, 1.0, 0.5}}) {
        std::vector<Eigen::Vector3d> p;
        pose_vertices(m, &m.clips[0], t, p);
        for (size_t v = 0; v < p.size(); ++v) {
            const Eigen::Vector3d& rest = m.rig.mesh_positions[v];
            const Eigen::Vector3d expected = rest + Eigen::Vector3d(rest.x() > 0 ? 0.25 * w1 : 0, rest.y() > 0 ? 0.5 * w0 : 0, 0);
            EXPECT_LT((p[v] - expected).norm(), 1e-12) << "t " << t << ", vertex " << v;
        }
    }
}

TEST(GltfAnimation, UnnamedNodesAndClipsAreFoundByAssimpsNames) {
    const test::TempDir dir{"gltf-unnamed"};
    const std::string path = edited_bar(dir, "unnamed.gltf", [](json& j) {
        for (json& n : j["nodes"]) n.erase("name");
        for (json& a : j["animations"]) a.erase("name");
    });
    const AnimatedMesh m = import_animated_mesh(path);
    ASSERT_EQ(m.clips.size(), 3u);
    EXPECT_EQ(m.clips[1].name, "clip 1");
    const Eigen::Affine3d tip = pose_nodes(m.rig, &m.clips[1], 1.0)[node_named(m.rig, "nodes[2]")];
    EXPECT_NEAR(std::atan2(tip.linear()(1, 0), tip.linear()(0, 0)), M_PI / 2, 1e-6);
    EXPECT_EQ(m.clips[1].nodes[0].rotation.interpolation, Interpolation::Step);
}

double largest_difference(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
    double d = 0;
    for (size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
    return d;
}

// The key times of the clip's track with the most keys.
const std::vector<double>& most_keys(const Clip& c) {
    const std::vector<double>* most = nullptr;
    auto consider = [&](const std::vector<double>& t) {
        if (!most || t.size() > most->size()) most = &t;
    };
    for (const NodeChannel& n : c.nodes) consider(n.translation.times), consider(n.rotation.times), consider(n.scale.times);
    for (const MorphChannel& m : c.morphs) consider(m.weights.times);
    return *most;
}

// For LINEAR samplers assimp's keys were right: the poses are the ones its clips give.
// AnimatedMorphCube's key times are thirtieths of a second, which assimp rounds to float
// milliseconds (33.3333358765 ms for 1/30 s): its poses are compared at the middle of each key
// span, where both readings are half way between the same two keys. Its last key has a weight
// of -1.5e-7, which assimp drops (as 0) and the file's sampler keeps.
TEST(GltfAnimation, LinearSamplersGiveTheSamePosesAsAssimpsKeys) {
    const std::string models = test::assimp_models() + "/glTF2/";
    for (const std::string& path : {models + "simple_skin/simple_skin.gltf",
                                    models + "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf",
                                    data_file("bending_bar.gltf")}) {
        const AnimatedMesh m = import_animated_mesh(path);
        AnimatedMesh assimp;
        assimp.imported = m.imported;
        std::vector<detail::MorphMesh> morphs;
        detail::read_assimp_rig(path, assimp, morphs);
        ASSERT_FALSE(m.clips.empty()) << path;
        ASSERT_EQ(m.clips.size(), assimp.clips.size()) << path;
        const Clip &mine = m.clips[0], &theirs = assimp.clips[0]; // LINEAR in each file
        EXPECT_EQ(mine.name, theirs.name);
        EXPECT_NEAR(mine.duration, theirs.duration, 1e-6);
        EXPECT_EQ(mine.joints_animated, theirs.joints_animated);
        const std::vector<double> &t0 = most_keys(mine), &t1 = most_keys(theirs);
        ASSERT_EQ(t0.size(), t1.size());
        std::vector<Eigen::Vector3d> a, b;
        const bool dropped = !mine.morphs.empty() && mine.morphs[0].weights.values.back()[1] < 0;
        EXPECT_EQ(dropped, path.find("AnimatedMorphCube") != std::string::npos);
        for (size_t k = 0; k + 1 < t0.size(); ++k) {
            pose_vertices(m, &mine, 0.5 * (t0[k] + t0[k + 1]), a);
            pose_vertices(assimp, &theirs, 0.5 * (t1[k] + t1[k + 1]), b);
            EXPECT_LT(largest_difference(a, b), dropped && k + 2 == t0.size() ? 2e-7 : 1e-9) << path << ", key " << k;
        }
        for (double t = -0.25; t <= mine.duration + 0.25; t += 0.125) {
            pose_vertices(m, &mine, t, a);
            pose_vertices(assimp, &theirs, t, b);
            EXPECT_LT(largest_difference(a, b), mine.morphs.empty() ? 1e-9 : 1e-6) << path << " at " << t;
        }
    }
}

TEST(GltfAnimation, NanWeightIsRefusedNamingTheVertex) {
    const std::string path = data_file("bad_weights.gltf");
    const std::string e = bad_input([&] { import_animated_mesh(path); });
    EXPECT_NE(e.find(path), std::string::npos) << e;
    EXPECT_NE(e.find("vertex 20 of mesh 'bar_mesh'"), std::string::npos) << e;
    EXPECT_NE(e.find("not a number"), std::string::npos) << e;
}

// Weights that assimp would drop without a word, each refused alone (vertex 20 of the bar).
TEST(GltfAnimation, NegativeInfiniteAndZeroSumWeightsAreRefused) {
    const test::TempDir dir{"gltf-weights"};
    const std::string bin = read_bytes(data_file("bending_bar_external.bin"));
    const size_t weights = 1008 + 20 * 16; // bufferView 3 (WEIGHTS_0, 4 floats a vertex), vertex 20
    const std::pair<std::array<float, 4>, const char*> cases[] = {
        {{-0.25f, 1.25f, 0, 0}, "negative"},
        {{INFINITY, 0.5f, 0, 0}, "infinite"},
        {{0, 0, 0, 0}, "sum to 0"},
    };
    write_bytes(dir.file("bar.gltf"), read_bytes(data_file("bending_bar_external.gltf")));
    for (const auto& [w, problem] : cases) {
        std::string b = bin;
        std::memcpy(b.data() + weights, w.data(), 16);
        write_bytes(dir.file("bending_bar_external.bin"), b);
        expect_refused(dir.file("bar.gltf"), "vertex 20 of mesh 'bar_mesh'");
        const std::string e = bad_input([&] { import_animated_mesh(dir.file("bar.gltf")); });
        EXPECT_NE(e.find("vertex 20 of mesh 'bar_mesh'"), std::string::npos) << e;
        EXPECT_NE(e.find(problem), std::string::npos) << e;
    }
}

TEST(GltfAnimation, KeyTimesOutOfOrderOrNotFiniteAreRefusedNamingClipNodeAndKey) {
    const test::TempDir dir{"gltf-times"};
    const std::string bin = read_bytes(data_file("bending_bar_external.bin"));
    const size_t step_times = 2216; // bufferView 9: the "step" clip's 3 key times
    write_bytes(dir.file("bar.gltf"), read_bytes(data_file("bending_bar_external.gltf")));
    for (const auto& [t, problem] : {std::pair{0.5f, "keys out of order (key 2"}, std::pair{NAN, "key 1 has a time that is not a number"}}) {
        std::string b = bin;
        std::memcpy(b.data() + step_times + (std::isnan(t) ? 4 : 8), &t, 4);
        write_bytes(dir.file("bending_bar_external.bin"), b);
        expect_refused(dir.file("bar.gltf"), "clip 'step', node 'tip' rotation: " + std::string(problem));
    }
}

// Every length a GLB file can be cut to, the header's and chunks' edges among them.
TEST(GltfAnimation, AGlbCutShortAnywhereIsBadInputNamingTheFile) {
    const test::TempDir dir{"gltf-cut"};
    const std::string glb = read_bytes(data_file("bending_bar.glb"));
    const std::string path = dir.file("cut.glb");
    for (size_t n = 0; n < glb.size(); n += (n < 40 || n + 40 > glb.size()) ? 1 : 97) {
        write_bytes(path, glb.substr(0, n));
        const std::string e = bad_input([&] { read_gltf_parts(path); });
        EXPECT_NE(e.find(path), std::string::npos) << n << ": " << e;
    }
    for (const size_t n : {size_t(0), size_t(12), size_t(20), glb.size() / 2, glb.size() - 1}) {
        write_bytes(path, glb.substr(0, n));
        const std::string e = bad_input([&] { import_animated_mesh(path); });
        EXPECT_NE(e.find(path), std::string::npos) << n << ": " << e;
    }
}

// Seeded single-byte changes anywhere in the GLB (its JSON's indices, counts and offsets, its
// binary chunk's floats): each copy is read or refused as BadInput, never anything worse.
TEST(GltfAnimation, AGlbWithAnyByteChangedIsReadOrRefused) {
    const test::TempDir dir{"gltf-mutate"};
    const std::string glb = read_bytes(data_file("bending_bar.glb"));
    const std::string path = dir.file("changed.glb");
    std::mt19937 random(38);
    int refused = 0;
    for (int i = 0; i < 400; ++i) {
        std::string b = glb;
        b[random() % b.size()] = char(random() % 256);
        write_bytes(path, b);
        try {
            read_gltf_parts(path);
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::BadInput) << e.what();
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
            ++refused;
        }
    }
    EXPECT_GT(refused, 0);
}

TEST(GltfAnimation, ABrokenDataUriIsBadInput) {
    const test::TempDir dir{"gltf-base64"};
    expect_refused(edited_bar(dir, "bad_char.gltf", [](json& j) {
        std::string uri = j["buffers"][0]["uri"];
        uri[uri.size() / 2] = '!';
        j["buffers"][0]["uri"] = uri;
    }), "not valid base64");
    expect_refused(edited_bar(dir, "short.gltf", [](json& j) {
        std::string uri = j["buffers"][0]["uri"];
        j["buffers"][0]["uri"] = uri.substr(0, uri.size() - 400);
    }), "is cut short: buffer 0 has");
}

TEST(GltfAnimation, AMissingExternalBufferIsBadInput) {
    const test::TempDir dir{"gltf-missing"};
    write_bytes(dir.file("bar.gltf"), read_bytes(data_file("bending_bar_external.gltf")));
    expect_refused(dir.file("bar.gltf"), "bending_bar_external.bin' cannot be read");
}

TEST(GltfAnimation, AnAccessorOrViewPastItsBufferIsBadInput) {
    const test::TempDir dir{"gltf-range"};
    // assimp 5.2.5 refuses these two as well but leaks on its way out (LeakSanitizer says so), so
    // they are given to this reader alone.
    expect_reader_refuses(edited_bar(dir, "count.gltf", [](json& j) { j["accessors"][12]["count"] = 10; }),
                          "accessor 12 (clip 'cubic', node 'tip' rotation key values) reaches past the end of bufferView 12");
    expect_reader_refuses(edited_bar(dir, "stride.gltf", [](json& j) { j["bufferViews"][3]["byteStride"] = 20; }),
                          "accessor 3 (mesh 'bar_mesh' WEIGHTS_0) reaches past the end of bufferView 3");
    expect_refused(edited_bar(dir, "offset.gltf", [](json& j) { j["accessors"][3]["byteOffset"] = uint64_t(1) << 63; }),
                   "accessor 3 (mesh 'bar_mesh' WEIGHTS_0) reaches past the end of bufferView 3");
    expect_refused(edited_bar(dir, "view.gltf", [](json& j) { j["bufferViews"][12]["byteLength"] = 1 << 20; }),
                   "bufferView 12 reaches past its buffer");
    expect_refused(edited_bar(dir, "index.gltf", [](json& j) { j["animations"][2]["samplers"][0]["output"] = 99; }),
                   "is 99, but the file has 13 accessors");
    expect_refused(edited_bar(dir, "negative.gltf", [](json& j) { j["accessors"][6]["count"] = -1; }), "not a non-negative integer");
}

TEST(GltfAnimation, ACubicSplineWithoutItsTangentsIsBadInput) {
    const test::TempDir dir{"gltf-cubic"};
    expect_refused(edited_bar(dir, "cubic.gltf", [](json& j) { j["animations"][1]["samplers"][0]["interpolation"] = "CUBICSPLINE"; }),
                   "clip 'step', node 'tip' rotation: 3 keys need 9 output values, the sampler has 3");
}

TEST(GltfAnimation, CorruptJsonIsBadInputNamingTheFile) {
    const test::TempDir dir{"gltf-json"};
    std::string text = read_bytes(data_file("bending_bar.gltf"));
    write_bytes(dir.file("cut.gltf"), text.substr(0, text.size() / 3));
    expect_refused(dir.file("cut.gltf"), "is not valid JSON");
    write_bytes(dir.file("deep.gltf"), std::string(100000, '['));
    expect_refused(dir.file("deep.gltf"), "is not valid JSON");
}

// A file made here: one accessor read as the given JSON says over the given bytes.
std::vector<double> read_made_accessor(const test::TempDir& dir, const json& accessor, const json& view, const std::string& bytes,
                                       int components) {
    static const char* const table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string b64; // n bytes of a group of 3 are n + 1 characters, then padding
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        uint32_t v = 0;
        for (size_t k = 0; k < 3; ++k) v = v << 8 | (k < n ? uint8_t(bytes[i + k]) : 0u);
        for (size_t k = 0; k < 4; ++k) b64 += k <= n ? table[(v >> (18 - 6 * k)) & 63] : '=';
    }
    json j = {{"asset", {{"version", "2.0"}}},
              {"buffers", {{{"byteLength", bytes.size()}, {"uri", "data:application/gltf-buffer;base64," + b64}}}},
              {"bufferViews", {view}},
              {"accessors", {accessor}}};
    write_bytes(dir.file("made.gltf"), j.dump());
    detail::GltfFile file(dir.file("made.gltf"));
    return file.read_accessor(json(0u), components, true, "test");
}

TEST(GltfAnimation, NormalizedIntegersAndStridesAreReadAsGltfSays) {
    const test::TempDir dir{"gltf-normalized"};
    const int16_t shorts[] = {32767, -32768, 0, -16384, 7, 7}; // two VEC2 elements 6 bytes apart
    std::string bytes(reinterpret_cast<const char*>(shorts), sizeof shorts);
    const json view = {{"buffer", 0}, {"byteLength", 12}, {"byteStride", 6}};
    const std::vector<double> v = read_made_accessor(
        dir, {{"bufferView", 0}, {"componentType", 5122}, {"normalized", true}, {"count", 2}, {"type", "VEC2"}}, view, bytes, 2);
    EXPECT_EQ(v, (std::vector<double>{1.0, -1.0, -16384.0 / 32767, 7.0 / 32767}));
    const std::vector<double> u = read_made_accessor(
        dir, {{"bufferView", 0}, {"componentType", 5121}, {"normalized", true}, {"count", 3}, {"type", "SCALAR"}},
        {{"buffer", 0}, {"byteLength", 3}}, std::string("\xff\x00\x33", 3), 1);
    EXPECT_EQ(u, (std::vector<double>{1.0, 0.0, 0.2}));
    const std::string e = bad_input([&] {
        read_made_accessor(dir, {{"bufferView", 0}, {"componentType", 5123}, {"count", 1}, {"type", "SCALAR"}}, view, bytes, 1);
    });
    EXPECT_NE(e.find("not float or a normalized integer"), std::string::npos) << e;
}

TEST(GltfAnimation, Base64DecodesWithAndWithoutPadding) {
    EXPECT_EQ(detail::decode_base64("aGVsbG8="), "hello");
    EXPECT_EQ(detail::decode_base64("aGVsbG8"), "hello");
    EXPECT_EQ(detail::decode_base64("aGVsbG8h"), "hello!");
    EXPECT_EQ(detail::decode_base64(""), "");
    EXPECT_FALSE(detail::decode_base64("aGVs*G8="));
    EXPECT_FALSE(detail::decode_base64("aGVsb"));
}

} // namespace
} // namespace spt
