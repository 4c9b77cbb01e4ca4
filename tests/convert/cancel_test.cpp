// Stopping a conversion from outside: the cancel flag and the stage names.
#include "meshgen.hpp"
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>

using namespace spt;

namespace {

TEST(ConvertCancel, FlagSetBeforeTheCallStopsItBeforeAnyWork) {
    const ImportedMesh m = meshgen::prepare(meshgen::torus(1, 0.4, 40, 20), "torus");
    std::atomic<bool> cancel{true};
    ConvertOptions o;
    o.cancel = &cancel;
    int stages = 0;
    o.on_stage = [&](const std::string&) { ++stages; };
    EXPECT_THROW(make_document(m.mesh, o), Cancelled);
    EXPECT_EQ(stages, 0);
}

TEST(ConvertCancel, FlagSetWhileSamplingFacesStopsItThereOnOneThreadOrMore) {
    // A CAD part whose large faces make the automatic tolerance sample them.
    const TriangleMesh mesh = import_mesh(test::project_meshes() + "/cad_part.stl").mesh;
    for (int threads : {1, 2}) {
        std::atomic<bool> cancel{false};
        ConvertOptions o;
        o.cancel = &cancel;
        o.threads = threads;
        std::vector<std::string> seen;
        o.on_stage = [&](const std::string& s) {
            seen.push_back(s);
            if (s == "sampling faces") cancel = true;
        };
        try {
            make_document(mesh, o);
            FAIL() << "the conversion ran to its end on " << threads << " thread(s)";
        } catch (const Cancelled& e) {
            EXPECT_NE(std::string(e.what()).find("cancelled"), std::string::npos) << e.what();
        }
        ASSERT_FALSE(seen.empty());
        EXPECT_EQ(seen.back(), "sampling faces") << "no stage may start after the flag is set";
    }
}

TEST(ConvertCancel, FlagSetAsTheTreeIsBuiltStopsTheBuilderBeforeItEnds) {
    // Vertex samples only: building the tree is the last stage, so only the builder itself
    // can see the flag (before it looked, the conversion ended with a document).
    const ImportedMesh m = meshgen::prepare(meshgen::torus(1, 0.4, 64, 32), "torus");
    for (int threads : {1, 2}) {
        std::atomic<bool> cancel{false};
        ConvertOptions o;
        o.cancel = &cancel;
        o.threads = threads;
        o.auto_tolerance = false;
        o.on_stage = [&](const std::string& s) {
            if (s == "building the tree") cancel = true;
        };
        EXPECT_THROW(make_document(m.mesh, o), Cancelled) << threads << " thread(s)";
    }
}

TEST(ConvertCancel, VertexSamplingLooksAtTheFlag) {
    const ImportedMesh m = meshgen::prepare(meshgen::torus(1, 0.4, 64, 32), "torus");
    const RadiusLimiter limiter(m.mesh, kDefaultProtrusion * m.mesh.diagonal());
    std::atomic<bool> cancel{true};
    for (int threads : {1, 2}) EXPECT_THROW(sample_vertices(m.mesh, limiter, {}, threads, &cancel), Cancelled);
    cancel = false;
    EXPECT_EQ(sample_vertices(m.mesh, limiter, {}, 2, &cancel).points, sample_vertices(m.mesh, limiter).points);
}

TEST(ConvertCancel, StagesOfAnUncancelledConversionAreNamedInOrder) {
    const TriangleMesh mesh = import_mesh(test::project_meshes() + "/cad_part.stl").mesh;
    ConvertOptions o;
    std::vector<std::string> seen;
    o.on_stage = [&](const std::string& s) { seen.push_back(s); };
    ConvertStats st;
    const SptDocument with = make_document(mesh, o, &st);
    ASSERT_GT(st.automatic_tolerance, 0) << "the part should need face samples";
    const std::vector<std::string> expected = {"sampling vertices", "building the tree", "sampling vertices",
                                               "sampling faces", "building the tree"};
    EXPECT_EQ(seen, expected);
    // Watching changes nothing.
    EXPECT_EQ(encode_spt(with), encode_spt(make_document(mesh)));
}

} // namespace
