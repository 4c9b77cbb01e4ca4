// Stopping an import from outside: before assimp reads the file, and between the steps of
// preparing the mesh (welding, topology, orientation, normals).
#include "meshgen.hpp"
#include "mesh/cancellable_io.hpp"
#include "spt/error.hpp"
#include "spt/mesh.hpp"
#include "test_support.hpp"
#include <assimp/IOStream.hpp>
#include <gtest/gtest.h>
#include <memory>

using namespace spt;
using spt::test::TempDir;

TEST(ImportCancel, AFlagSetBeforeTheCallStopsItBeforeTheFileIsReadAndNamesTheFile) {
    TempDir dir("import-cancel");
    const std::string path = dir.file("box.stl");
    meshgen::write_stl(meshgen::box(1, 2, 3, 4), path);
    std::atomic<bool> cancel{true};
    ImportOptions o;
    o.cancel = &cancel;
    try {
        import_mesh(path, o);
        FAIL() << "the import ran to its end";
    } catch (const Cancelled& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("cancelled"), std::string::npos) << e.what();
    }
}

TEST(ImportCancel, AssimpsReadsEndOnceTheFlagIsSetAsAtTheEndOfATruncatedFile) {
    // assimp cannot be told to stop a loader; the files it reads can stop giving bytes.
    TempDir dir("import-cancel-io");
    const std::string path = dir.file("box.stl");
    meshgen::write_stl(meshgen::box(1, 2, 3, 4), path);
    std::atomic<bool> cancel{false};
    detail::CancellableIOSystem io(cancel);
    Assimp::IOStream* stream = io.Open(path.c_str(), "rb");
    ASSERT_NE(stream, nullptr);
    char buffer[64];
    EXPECT_EQ(stream->Read(buffer, 1, sizeof buffer), sizeof buffer);
    EXPECT_EQ(stream->Tell(), sizeof buffer);
    cancel = true;
    EXPECT_EQ(stream->Read(buffer, 1, sizeof buffer), 0u);
    EXPECT_GT(stream->FileSize(), 2 * sizeof buffer);
    io.Close(stream);
    EXPECT_EQ(io.Open(dir.file("missing.stl").c_str(), "rb"), nullptr);
}

TEST(ImportCancel, AFlagSetWhileALargeMeshIsPreparedStopsItBeforeItEnds) {
    // 300,000 vertices: preparing them takes far longer than the other thread needs to set the
    // flag, and before this check nothing looked at it until the conversion's first stage.
    const meshgen::RawMesh raw = meshgen::torus(1, 0.4, 600, 500);
    for (int threads : {1, 2}) {
        std::atomic<bool> cancel{false};
        ImportOptions o;
        o.cancel = &cancel;
        o.threads = threads;
        test::CancelFromAnotherThread canceller(cancel);
        canceller.start();
        EXPECT_THROW(prepare_mesh("torus", raw.positions, raw.triangles, o), Cancelled) << threads << " thread(s)";
    }
}

TEST(ImportCancel, AFlagLeftUnsetChangesNothing) {
    const meshgen::RawMesh raw = meshgen::torus(1, 0.4, 40, 20);
    std::atomic<bool> cancel{false};
    ImportOptions o;
    o.cancel = &cancel;
    const ImportedMesh watched = prepare_mesh("torus", raw.positions, raw.triangles, o);
    const ImportedMesh plain = prepare_mesh("torus", raw.positions, raw.triangles);
    EXPECT_EQ(watched.mesh.positions, plain.mesh.positions);
    EXPECT_EQ(watched.mesh.triangles, plain.mesh.triangles);
    EXPECT_EQ(watched.mesh.content_hash(), plain.mesh.content_hash());
}
