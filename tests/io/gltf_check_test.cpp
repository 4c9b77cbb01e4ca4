// A glTF 2.0 file's indices checked before assimp follows them (core/src/io/gltf_check.cpp).
#include "spt/error.hpp"
#include "spt/mesh.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <fstream>

namespace {

using nlohmann::json;

json bar() {
    std::ifstream in(std::string(SPT_SOURCE_DIR) + "/tests/data/anim/bending_bar.gltf");
    return json::parse(in);
}

// import_mesh of `doc` written as a file refuses it, naming the file and `where`.
void expect_refused_at(const json& doc, const std::string& where) {
    spt::test::TempDir dir{"gltf-check"};
    const std::string path = dir.file("broken.gltf");
    std::ofstream(path) << doc.dump();
    try {
        spt::import_mesh(path);
        FAIL() << "accepted a file broken at " << where;
    } catch (const spt::Error& e) {
        EXPECT_EQ(e.kind(), spt::ErrorKind::BadInput);
        const std::string m = e.what();
        EXPECT_NE(m.find(path), std::string::npos) << m;
        EXPECT_NE(m.find(where), std::string::npos) << m;
    }
}

// Found by the animated_import fuzz target: assimp 5.2.5 dereferenced the missing node.
TEST(GltfCheck, AnAnimationChannelWithoutANodeIsRefusedBeforeAssimp) {
    json doc = bar();
    doc["animations"][0]["channels"][0]["target"].erase("node");
    expect_refused_at(doc, "/animations/0/channels/0/target");
}

TEST(GltfCheck, IndicesPastTheirArraysAreRefusedWithTheirPath) {
    {
        json doc = bar();
        doc["nodes"][1]["children"] = {99};
        expect_refused_at(doc, "/nodes/1/children/0");
    }
    {
        json doc = bar();
        doc["skins"][0]["joints"][0] = -1;
        expect_refused_at(doc, "/skins/0/joints/0");
    }
    {
        json doc = bar();
        doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 1000;
        expect_refused_at(doc, "/meshes/0/primitives/0/attributes/POSITION");
    }
    {
        json doc = bar();
        doc["animations"][1]["channels"][0]["sampler"] = 7;
        expect_refused_at(doc, "/animations/1/channels/0/sampler");
    }
    {
        json doc = bar();
        doc["bufferViews"][0].erase("buffer");
        expect_refused_at(doc, "/bufferViews/0");
    }
}

TEST(GltfCheck, AWholeFileIsReadAsBefore) {
    EXPECT_EQ(spt::import_mesh(std::string(SPT_SOURCE_DIR) + "/tests/data/anim/bending_bar.gltf").mesh.triangles.size(), 68u);
    EXPECT_EQ(spt::import_mesh(std::string(SPT_SOURCE_DIR) + "/tests/data/anim/bending_bar.glb").mesh.triangles.size(), 68u);
}

} // namespace
