// Mesh import and preparation: welding, formats, transforms, orientation fixes, reports.
#include "meshgen.hpp"
#include "spt/error.hpp"
#include "spt/mesh.hpp"
#include "test_support.hpp"
#include <cmath>
#include <fstream>
#include <limits>
#include <gtest/gtest.h>

using namespace spt;
using spt::test::TempDir;

namespace {

double volume(const TriangleMesh& m) {
    double v = 0;
    for (const auto& t : m.triangles)
        v += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6;
    return v;
}

} // namespace

TEST(MeshImport, UnindexedStlIsWeldedByPosition) {
    TempDir dir("stl");
    meshgen::write_stl(meshgen::box(1, 2, 3, 1), dir.file("box.stl"));
    const ImportedMesh m = import_mesh(dir.file("box.stl"));
    EXPECT_EQ(m.report.file_vertices, 36u); // 12 triangles x 3 corners
    EXPECT_EQ(m.report.vertices, 8u);
    EXPECT_EQ(m.report.welded, 28u);
    EXPECT_EQ(m.mesh.welded_index.size(), 36u);
    EXPECT_TRUE(m.report.closed);
    EXPECT_EQ(m.report.components, 1u);
    EXPECT_NEAR(volume(m.mesh), 6.0, 1e-6);
}

TEST(MeshImport, EveryWrittenFormatGivesTheSameMesh) {
    TempDir dir("formats");
    const auto raw = meshgen::torus(1.0, 0.3, 24, 12);
    meshgen::write_obj(raw, dir.file("t.obj"));
    meshgen::write_stl(raw, dir.file("t.stl"));
    meshgen::write_ply(raw, dir.file("t.ply"));
    {
        std::ofstream off(dir.file("t.off"));
        off << "OFF\n" << raw.positions.size() << " " << raw.triangles.size() << " 0\n";
        for (const auto& p : raw.positions) off << p.x() << " " << p.y() << " " << p.z() << "\n";
        for (const auto& t : raw.triangles) off << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    }
    for (const char* name : {"t.obj", "t.stl", "t.ply", "t.off"}) {
        SCOPED_TRACE(name);
        const ImportedMesh m = import_mesh(dir.file(name));
        EXPECT_EQ(m.mesh.positions.size(), raw.positions.size());
        EXPECT_EQ(m.mesh.triangles.size(), raw.triangles.size());
        EXPECT_TRUE(m.report.closed);
        EXPECT_EQ(m.report.flipped_faces, 0u);
        EXPECT_GT(volume(m.mesh), 0);
    }
}

TEST(MeshImport, NodeTransformsOfEveryMeshAreApplied) {
    // A glTF scene with one triangle mesh used by two nodes at different translations.
    TempDir dir("gltf");
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const uint16_t idx[3] = {0, 1, 2};
    {
        std::ofstream bin(dir.file("tri.bin"), std::ios::binary);
        bin.write(reinterpret_cast<const char*>(tri), sizeof tri);
        bin.write(reinterpret_cast<const char*>(idx), sizeof idx);
    }
    std::ofstream(dir.file("two.gltf")) << R"({
 "asset": {"version": "2.0"},
 "scene": 0, "scenes": [{"nodes": [0, 1]}],
 "nodes": [{"mesh": 0, "translation": [10, 0, 0]}, {"mesh": 0, "translation": [0, 5, 0]}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
 "buffers": [{"uri": "tri.bin", "byteLength": 42}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
 "accessors": [
  {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
  {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]
})";
    const ImportedMesh m = import_mesh(dir.file("two.gltf"));
    ASSERT_EQ(m.mesh.triangles.size(), 2u);
    ASSERT_EQ(m.mesh.positions.size(), 6u);
    auto [lo, hi] = m.mesh.bounds();
    EXPECT_NEAR(lo.x(), 0, 1e-9);
    EXPECT_NEAR(hi.x(), 11, 1e-9);
    EXPECT_NEAR(hi.y(), 6, 1e-9);
    EXPECT_EQ(m.report.components, 2u);
    EXPECT_FALSE(m.report.closed);
}

TEST(MeshPrepare, BoxCornerNormalIsAngleWeighted) {
    // A corner touches three quarter-faces; angle weighting gives the diagonal whatever
    // the triangulation, where area or count weighting would not.
    const ImportedMesh m = meshgen::prepare(meshgen::box(2, 2, 2, 1), "box");
    for (size_t v = 0; v < m.mesh.positions.size(); ++v) {
        const Eigen::Vector3d expected = m.mesh.positions[v].normalized();
        EXPECT_LT((m.mesh.normals[v] - expected).norm(), 1e-12) << "vertex " << v;
    }
}

TEST(MeshPrepare, InconsistentWindingIsFixed) {
    auto raw = meshgen::box(1, 1, 1, 2);
    for (size_t f = 0; f < raw.triangles.size(); f += 3) std::swap(raw.triangles[f][1], raw.triangles[f][2]);
    const ImportedMesh m = meshgen::prepare(raw, "box");
    EXPECT_EQ(m.report.flipped_faces, (raw.triangles.size() + 2) / 3);
    EXPECT_EQ(m.report.inverted_components, 0u);
    EXPECT_NEAR(volume(m.mesh), 1.0, 1e-9);
    EXPECT_FALSE(m.report.fixes.empty());
}

TEST(MeshPrepare, AClosedPartWhoseWallsLieOnOneAnotherIsSampledAsAnOpenSheet) {
    // A flat closed shell (a sheet exported as a box 1e-7 thick, its top slid along it so that
    // no vertex welds to one below, as assimp's OBJ/regr01.obj's trims are) encloses no volume:
    // each face's winding would put its one-sided spheres outside the part on one wall or the
    // other. It is an open sheet: two-sided spheres within the allowance, no solid. A box 1e-4
    // thick beside it stays a closed solid.
    meshgen::RawMesh raw = meshgen::box(1, 0.5, 1, 2);
    for (Eigen::Vector3d& v : raw.positions) v.x() += v.z() > 0 ? 0.01 : 0, v.z() *= 1e-7;
    raw.append(meshgen::box(1, 0.5, 1e-4, 2), Eigen::Vector3d(0, 2, 0));
    const ImportedMesh m = meshgen::prepare(raw, "flat shell and thin box");
    EXPECT_TRUE(m.report.closed);
    EXPECT_EQ(m.report.flat_closed_parts, 1u);
    size_t open = 0, closed = 0;
    for (uint32_t f = 0; f < m.mesh.triangles.size(); ++f) {
        const bool on_flat = m.mesh.positions[m.mesh.triangles[f][0]].y() < 1;
        EXPECT_EQ(bool(m.mesh.on_open_part[f]), on_flat) << "face " << f;
        (m.mesh.on_open_part[f] ? open : closed) += 1;
    }
    EXPECT_GT(open, 0u);
    EXPECT_GT(closed, 0u);
    const SptDocument doc = make_document(m.mesh);
    const double allowance = kDefaultProtrusion * m.mesh.diagonal();
    for (size_t i = 0; i < doc.samples.size(); ++i) {
        const bool on_flat = doc.samples.position(i).y() < 1;
        EXPECT_EQ(doc.samples.is_two_sided(i), on_flat) << "sample " << i;
        EXPECT_LE(doc.samples.max_radius[i], allowance * 1.01) << "sample " << i;
    }
}

TEST(MeshPrepare, InsideOutClosedMeshIsTurnedAround) {
    auto raw = meshgen::icosphere(1.0, 2);
    for (auto& t : raw.triangles) std::swap(t[1], t[2]);
    const ImportedMesh m = meshgen::prepare(raw, "sphere");
    EXPECT_EQ(m.report.inverted_components, 1u);
    EXPECT_GT(volume(m.mesh), 0);
    for (size_t v = 0; v < m.mesh.positions.size(); ++v) EXPECT_GT(m.mesh.normals[v].dot(m.mesh.positions[v]), 0.9);
}

TEST(MeshPrepare, APartPokingThroughAnotherWithinItsBoxKeepsFacingOutAndAWhollyNestedOneIsACavity) {
    // A small ball through the inner wall of a torus's tube, its box inside the torus's box and
    // its first vertex inside the tube (an eye through a head's socket): it was taken for the
    // inner wall of a cavity and turned inside out, its normals (and so its sampling spheres)
    // pointing out of it.
    const double r = 0.1;
    auto ball_normals_facing_out = [&](const Eigen::Vector3d& centre, size_t* inverted) {
        meshgen::RawMesh m = meshgen::torus(1, 0.4, 48, 24);
        m.append(meshgen::icosphere(r, 2), centre);
        const ImportedMesh im = meshgen::prepare(m, "torus and ball");
        *inverted = im.report.inverted_components;
        int out = 0, ball = 0;
        for (size_t v = 0; v < im.mesh.positions.size(); ++v) {
            const Eigen::Vector3d d = im.mesh.positions[v] - centre;
            if (std::abs(d.norm() - r) > 1e-9) continue;
            ++ball;
            out += im.mesh.normals[v].dot(d) > 0;
        }
        EXPECT_GT(ball, 100);
        return double(out) / ball;
    };
    size_t inverted = 0;
    for (const Eigen::Vector3d& through : {Eigen::Vector3d(0.68, 0, 0.1), Eigen::Vector3d(0.68, -0.1, 0.1)}) {
        EXPECT_EQ(ball_normals_facing_out(through, &inverted), 1.0) << through.transpose();
        EXPECT_EQ(inverted, 0u) << through.transpose();
    }
    // Wholly inside the tube, it is the wall of a cavity there (docs/queries.md).
    EXPECT_EQ(ball_normals_facing_out(Eigen::Vector3d(1.0, 0, 0), &inverted), 0.0);
    EXPECT_EQ(inverted, 1u);
}

TEST(MeshPrepare, APartInsideAConeOfSliversIsFoundNestedWithoutListingEverySliverInEveryCell) {
    // A cone of 20,000 slivers from its apex, each of whose boxes spans the small box inside it:
    // the grid that finds meeting faces would list every sliver in every cell (4e8 entries)
    // without its budget.
    const int slivers = 20000;
    meshgen::RawMesh m;
    m.positions = {{0, 0, 1}, {0, 0, -1}};
    for (int k = 0; k < slivers; ++k) {
        const double a = 2 * M_PI * k / slivers;
        m.positions.push_back({std::cos(a), std::sin(a), -1});
    }
    for (int k = 0; k < slivers; ++k) {
        const uint32_t p = 2 + uint32_t(k), q = 2 + uint32_t((k + 1) % slivers);
        m.triangles.push_back({0, p, q});
        m.triangles.push_back({1, q, p});
    }
    m.append(meshgen::box(0.1, 0.1, 0.1, 1), {0, 0, -0.5});
    const ImportedMesh im = meshgen::prepare(m, "cone and box");
    EXPECT_TRUE(im.report.closed);
    EXPECT_EQ(im.report.inverted_components, 1u) << "the box wholly inside is the wall of a cavity";
}

TEST(MeshPrepare, OpenMeshLoadsWithWarning) {
    auto raw = meshgen::box(1, 1, 1, 1);
    raw.triangles.pop_back();
    const ImportedMesh m = meshgen::prepare(raw, "open");
    EXPECT_EQ(m.report.boundary_edges, 3u);
    EXPECT_FALSE(m.report.closed);
    EXPECT_FALSE(m.report.warnings.empty());
}

TEST(MeshPrepare, NonManifoldEdgeIsReported) {
    meshgen::RawMesh raw;
    raw.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    raw.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const ImportedMesh m = meshgen::prepare(raw, "fin");
    EXPECT_EQ(m.report.nonmanifold_edges, 1u);
}

TEST(MeshPrepare, DegenerateFacesAreIgnoredForNormals) {
    auto raw = meshgen::box(1, 1, 1, 1);
    raw.positions.push_back(raw.positions[0]);           // duplicate of vertex 0, welded onto it
    raw.triangles.push_back({0, 1, uint32_t(raw.positions.size() - 1)}); // collapses after welding
    raw.positions.push_back((raw.positions[0] + raw.positions[1]) / 2);   // on the edge 0-1
    raw.triangles.push_back({0, 1, uint32_t(raw.positions.size() - 1)}); // zero area
    const ImportedMesh m = meshgen::prepare(raw, "degenerate");
    EXPECT_EQ(m.report.degenerate_faces, 2u);
    for (size_t v = 0; v < m.mesh.positions.size(); ++v) EXPECT_TRUE(m.mesh.normals[v].allFinite());
}

TEST(MeshPrepare, VertexWithoutNormalIsReportedNotNaN) {
    auto raw = meshgen::box(1, 1, 1, 1);
    raw.positions.push_back({5, 5, 5}); // used by no face
    const ImportedMesh m = meshgen::prepare(raw, "stray");
    EXPECT_EQ(m.report.vertices_without_normal, 1u);
    EXPECT_FALSE(m.mesh.normal_valid.back());
    EXPECT_TRUE(m.mesh.normals.back().isZero());
}

TEST(MeshPrepare, NonFiniteCoordinateIsBadInput) {
    auto raw = meshgen::box(1, 1, 1, 1);
    raw.positions[3].y() = std::numeric_limits<double>::quiet_NaN();
    try {
        meshgen::prepare(raw, "nan.obj");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        EXPECT_NE(std::string(e.what()).find("nan.obj"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("vertex 3"), std::string::npos);
    }
}

TEST(MeshImport, ANaNOrInfinityInTheFileIsNamedWithItsVertexNotLostByTheReader) {
    // assimp's invalid-data step used to drop the whole mesh ("No meshes remaining").
    TempDir dir("nan-file");
    std::ofstream(dir.file("nan.obj")) << "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n";
    {
        std::ofstream ply(dir.file("inf.ply"), std::ios::binary);
        ply << "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
               "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
        const float v[9] = {0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::infinity(), 0};
        ply.write(reinterpret_cast<const char*>(v), sizeof v);
        const unsigned char n = 3;
        const int32_t f[3] = {0, 1, 2};
        ply.write(reinterpret_cast<const char*>(&n), 1);
        ply.write(reinterpret_cast<const char*>(f), sizeof f);
    }
    for (const char* name : {"nan.obj", "inf.ply"}) {
        try {
            import_mesh(dir.file(name));
            FAIL() << name << " was imported";
        } catch (const Error& e) {
            const std::string m = e.what();
            EXPECT_EQ(e.kind(), ErrorKind::BadInput);
            EXPECT_NE(m.find(name), std::string::npos) << m;
            EXPECT_NE(m.find("not finite"), std::string::npos) << m;
            EXPECT_NE(m.find(std::string(name) == "nan.obj" ? "vertex 1 " : "vertex 2 "), std::string::npos) << m;
        }
    }
}

TEST(MeshImport, ACoordinateBeyondTheRangeIsNamedWithItsVertexAndValue) {
    TempDir dir("huge-file");
    std::ofstream(dir.file("huge.obj")) << "v 0 0 0\nv 1e30 0 0\nv 0 1 0\nf 1 2 3\n";
    try {
        import_mesh(dir.file("huge.obj"));
        FAIL() << "a vertex at 1e30 was imported";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        EXPECT_NE(m.find("vertex 1 (counting from 0 as read) at (1e+30, 0, 0)"), std::string::npos) << m;
        EXPECT_NE(m.find("beyond 1e16"), std::string::npos) << m;
    }
}

TEST(MeshBounds, FarForFloatBeyondEightSizesFromTheOrigin) {
    TriangleMesh m = meshgen::prepare(meshgen::box(1, 1, 1, 1), "box").mesh; // 1 across, about the origin
    EXPECT_FALSE(m.far_for_float());
    for (Eigen::Vector3d& p : m.positions) p += Eigen::Vector3d(7.4, 0, 0); // farthest 7.9: within 8 sizes
    EXPECT_FALSE(m.far_for_float());
    for (Eigen::Vector3d& p : m.positions) p += Eigen::Vector3d(0, 0, -1e6);
    EXPECT_TRUE(m.far_for_float());
}

TEST(MeshImport, MissingFileNamesThePath) {
    try {
        import_mesh("/nonexistent/thing.obj");
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        EXPECT_NE(std::string(e.what()).find("/nonexistent/thing.obj"), std::string::npos);
    }
}

TEST(MeshImport, ContentHashTellsMeshesApart) {
    const auto a = meshgen::prepare(meshgen::box(1, 1, 1, 1), "a").mesh;
    auto moved = meshgen::box(1, 1, 1, 1);
    moved.positions[0].x() += 1e-3;
    const auto b = meshgen::prepare(moved, "b").mesh;
    EXPECT_EQ(a.content_hash(), meshgen::prepare(meshgen::box(1, 1, 1, 1), "c").mesh.content_hash());
    EXPECT_NE(a.content_hash(), b.content_hash());
}

TEST(MeshImport, OpenPartsAreMarkedPerTriangleAndClosedPartsAreNot) {
    // A closed cube and an open sheet in one mesh, joined by nothing.
    auto cube = meshgen::box(1, 1, 1, 1);
    std::vector<Eigen::Vector3d> p = cube.positions;
    std::vector<Triangle> t = cube.triangles;
    const uint32_t base = uint32_t(p.size());
    for (const auto& v : {Eigen::Vector3d(3, 0, 0), Eigen::Vector3d(4, 0, 0), Eigen::Vector3d(3, 1, 0)}) p.push_back(v);
    t.push_back({base, base + 1, base + 2});
    const ImportedMesh m = prepare_mesh("cube and sheet", std::move(p), std::move(t));
    ASSERT_EQ(m.mesh.on_open_part.size(), m.mesh.triangles.size());
    for (size_t f = 0; f < m.mesh.triangles.size(); ++f) {
        const bool sheet = m.mesh.positions[m.mesh.triangles[f][0]].x() > 2;
        EXPECT_EQ(m.mesh.on_open_part[f], sheet ? 1 : 0) << "face " << f;
    }
}

TEST(MeshImport, ClosedBodyTouchedByAFlapAlongANonManifoldEdgeStaysClosed) {
    // A cube with a flap glued on along one of its edges (three faces on that edge): the cube
    // is still a solid, the flap alone is open (the Wuson's body and flaps).
    auto cube = meshgen::box(1, 1, 1, 1);
    std::vector<Eigen::Vector3d> p = cube.positions;
    std::vector<Triangle> t = cube.triangles;
    const Triangle first = t[0];
    const Eigen::Vector3d out = 0.5 * (p[first[0]] + p[first[1]]) + 2.0 * p[first[0]].normalized();
    p.push_back(out);
    t.push_back({first[0], first[1], uint32_t(p.size() - 1)});
    const ImportedMesh m = prepare_mesh("cube with flap", std::move(p), std::move(t));
    EXPECT_EQ(m.report.nonmanifold_edges, 1u);
    ASSERT_EQ(m.mesh.on_open_part.size(), m.mesh.triangles.size());
    for (size_t f = 0; f < m.mesh.triangles.size(); ++f) {
        const bool flap = f + 1 == m.mesh.triangles.size();
        EXPECT_EQ(m.mesh.on_open_part[f], flap ? 1 : 0) << "face " << f;
    }
}

TEST(MeshImport, TwoClosedBodiesSharingAnEdgeAreBothClosed) {
    meshgen::RawMesh two = meshgen::box(1, 1, 1, 1);
    two.append(meshgen::box(1, 1, 1, 1), Eigen::Vector3d(1, 1, 0)); // the edge x = y = 0.5 is shared
    const ImportedMesh m = meshgen::prepare(two, "two cubes");
    EXPECT_EQ(m.report.nonmanifold_edges, 1u);
    for (size_t f = 0; f < m.mesh.triangles.size(); ++f) EXPECT_EQ(m.mesh.on_open_part[f], 0) << "face " << f;
    EXPECT_EQ(m.report.inverted_components, 0u);
}

TEST(MeshPrepare, SameMeshAndReportOnAnyThreadCountWhenFacesAreReWoundCopiedOrOpen) {
    // On two threads or more the normals are computed beside the topology and again where a
    // face was re-wound or copied: every case below must come out as on one thread.
    std::vector<std::pair<std::string, meshgen::RawMesh>> cases;
    cases.emplace_back("torus", meshgen::torus(1, 0.3, 40, 20));
    auto rewound = meshgen::box(1, 1, 1, 3);
    for (size_t f = 0; f < rewound.triangles.size(); f += 3) std::swap(rewound.triangles[f][1], rewound.triangles[f][2]);
    cases.emplace_back("rewound box", rewound);
    auto inside_out = meshgen::icosphere(1.0, 2);
    for (auto& t : inside_out.triangles) std::swap(t[1], t[2]);
    cases.emplace_back("inside-out sphere", inside_out);
    auto copies = meshgen::torus(1, 0.3, 24, 12);
    for (size_t f = 0; f < 40; f += 4) {
        auto t = copies.triangles[f];
        if (f % 8 == 0) std::swap(t[1], t[2]); // a copy wound the other way
        copies.triangles.push_back(t);
    }
    cases.emplace_back("copied faces", copies);
    auto open = meshgen::box(1, 1, 1, 2);
    open.triangles.pop_back();
    cases.emplace_back("open box", open);
    for (const auto& [name, raw] : cases) {
        SCOPED_TRACE(name);
        ImportOptions one;
        one.threads = 1;
        const ImportedMesh a = prepare_mesh(name, raw.positions, raw.triangles, one);
        for (int threads : {2, 3}) {
            ImportOptions many;
            many.threads = threads;
            const ImportedMesh b = prepare_mesh(name, raw.positions, raw.triangles, many);
            EXPECT_EQ(b.mesh.triangles, a.mesh.triangles);
            EXPECT_EQ(b.mesh.normals, a.mesh.normals); // bit for bit
            EXPECT_EQ(b.mesh.normal_valid, a.mesh.normal_valid);
            EXPECT_EQ(b.mesh.on_open_part, a.mesh.on_open_part);
            EXPECT_EQ(b.report.flipped_faces, a.report.flipped_faces);
            EXPECT_EQ(b.report.inverted_components, a.report.inverted_components);
            EXPECT_EQ(b.report.duplicate_faces, a.report.duplicate_faces);
            EXPECT_EQ(b.report.components, a.report.components);
            EXPECT_EQ(b.report.vertices_without_normal, a.report.vertices_without_normal);
            EXPECT_EQ(b.report.fixes, a.report.fixes);
            EXPECT_EQ(b.report.warnings, a.report.warnings);
        }
    }
}
