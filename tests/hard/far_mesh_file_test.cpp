// Far from the origin, through files: a mesh exported in world units 10^4 to 10^6 from its
// file's origin. Assimp reads coordinates into float (1/16 of a unit at 10^6), which merged
// and moved the vertices of a part a few units across before anything of ours saw them;
// OBJ and PLY keep the file's own digits (mesh/recentre.hpp).
#include "mesh/recentre.hpp"
#include "mesh/shapes.hpp"
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "spt/mesh.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace spt {
namespace {

using test::TempDir;

const Eigen::Vector3d kExported = Eigen::Vector3d(1, -0.6, 0.3).normalized();

enum class Format { Obj, PlyAscii, PlyDoubleLittle, PlyDoubleBig, PlyFloat };

const char* format_name(Format f) {
    switch (f) {
    case Format::Obj: return "obj";
    case Format::PlyAscii: return "ascii ply";
    case Format::PlyDoubleLittle: return "binary little-endian double ply";
    case Format::PlyDoubleBig: return "binary big-endian double ply";
    case Format::PlyFloat: return "binary float ply";
    }
    return "";
}

void put(std::ofstream& out, const void* p, size_t n, bool big) {
    char b[8];
    std::memcpy(b, p, n);
    if (big) std::reverse(b, b + n);
    out.write(b, std::streamsize(n));
}

// Writes `mesh` moved by `offset` as an exporter would, with every digit a double has. The PLY
// files put a property before x and keep z, x, y out of order, so a reader must use the header.
std::string write(const TriangleMesh& mesh, const Eigen::Vector3d& offset, Format format, const TempDir& dir) {
    const std::string path = dir.file(std::string("part") + (format == Format::Obj ? ".obj" : ".ply"));
    std::ofstream out(path, std::ios::binary);
    char line[160];
    if (format == Format::Obj) {
        out << "# exported in world units\nmtllib part.mtl\no part\nusemtl steel\n";
        for (const Eigen::Vector3d& q : mesh.positions) {
            const Eigen::Vector3d p = q + offset;
            std::snprintf(line, sizeof line, "v %.17g %.17g %.17g 0.5 0.5 0.5\n", p.x(), p.y(), p.z()); // with a colour
            out << line;
        }
        out << "vn 0 0 1\n";
        for (const Triangle& t : mesh.triangles) out << "f " << t[0] + 1 << "//1 " << t[1] + 1 << "//1 " << t[2] + 1 << "//1\n";
        std::ofstream(dir.file("part.mtl")) << "newmtl steel\nKd 0.6 0.6 0.6\n";
        return path;
    }
    const bool ascii = format == Format::PlyAscii, big = format == Format::PlyDoubleBig;
    const char* type = format == Format::PlyFloat ? "float" : "double";
    out << "ply\nformat " << (ascii ? "ascii" : big ? "binary_big_endian" : "binary_little_endian") << " 1.0\n"
        << "comment exported in world units\nelement vertex " << mesh.positions.size() << "\n"
        << "property float confidence\nproperty " << type << " z\nproperty " << type << " x\nproperty " << type << " y\n"
        << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const Eigen::Vector3d& q : mesh.positions) {
        const Eigen::Vector3d p = q + offset;
        if (ascii) {
            std::snprintf(line, sizeof line, "1 %.17g %.17g %.17g\n", p.z(), p.x(), p.y());
            out << line;
            continue;
        }
        const float confidence = 1;
        put(out, &confidence, 4, big);
        for (int k : {2, 0, 1}) {
            if (format == Format::PlyFloat) {
                const float v = float(p[k]);
                put(out, &v, 4, big);
            } else {
                put(out, &p[k], 8, big);
            }
        }
    }
    for (const Triangle& t : mesh.triangles) {
        if (ascii) {
            out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
            continue;
        }
        const unsigned char n = 3;
        out.write(reinterpret_cast<const char*>(&n), 1);
        for (int k = 0; k < 3; ++k) {
            const int32_t i = int32_t(t[size_t(k)]);
            put(out, &i, 4, big);
        }
    }
    return path;
}

TEST(FarMeshFile, OneExportedAMillionUnitsOutImportsAsPreciselyAsAtTheOrigin) {
    const TriangleMesh part = make_torus(1.0, 0.35, 40, 20); // 2.7 units across
    const double diag = part.diagonal();
    for (Format format : {Format::Obj, Format::PlyAscii, Format::PlyDoubleLittle, Format::PlyDoubleBig}) {
        TempDir near_dir("far-file-near"), far_dir("far-file-far");
        const ImportedMesh near = import_mesh(write(part, Eigen::Vector3d::Zero(), format, near_dir));
        for (double distance : {1e4, 1e5, 1e6}) {
            const Eigen::Vector3d offset = distance * kExported;
            const ImportedMesh far = import_mesh(write(part, offset, format, far_dir));
            ASSERT_EQ(far.mesh.positions.size(), near.mesh.positions.size())
                << format_name(format) << " at " << distance << ": vertices merged by rounding";
            ASSERT_EQ(far.mesh.triangles, near.mesh.triangles) << format_name(format) << " at " << distance;
            double worst = 0;
            for (size_t v = 0; v < near.mesh.positions.size(); ++v)
                worst = std::max(worst, (far.mesh.positions[v] - offset - near.mesh.positions[v]).norm());
            // Float relative to the part keeps about 2^-24 of its size; float at 10^6, 1/16 of a unit.
            EXPECT_LE(worst, 1e-6 * diag) << format_name(format) << " at " << distance;
        }
    }
}

TEST(FarMeshFile, ItsSampledModelIsTheModelAtTheOriginMoved) {
    const TriangleMesh part = make_torus(1.0, 0.35, 40, 20);
    TempDir near_dir("far-model-near"), far_dir("far-model-far");
    const SptDocument near = load_or_convert(write(part, Eigen::Vector3d::Zero(), Format::Obj, near_dir));
    const SptDocument far = load_or_convert(write(part, 1e6 * kExported, Format::Obj, far_dir));
    // The same samples as the part at the origin, as the far model made in code gets them
    // (FarFromOrigin.MeshExportedInWorldUnitsConvertsToAnEquivalentModel): the local origin is
    // rounded another way out there, so float sample coordinates round another way too.
    const double n0 = double(near.samples.size());
    EXPECT_NEAR(double(far.samples.size()), n0, 0.01 * n0);
    EXPECT_EQ(far.mesh.vertex_count, near.mesh.vertex_count);
    EXPECT_LE((far.samples.origin - 1e6 * kExported).norm(), 2 * part.diagonal()) << "the local origin sits with the part";
}

TEST(FarMeshFile, FloatCoordinatesInTheFileItselfAreReadAsTheyAreAndNothingElseIsRewritten) {
    const TriangleMesh part = make_torus(1.0, 0.35, 40, 20);
    TempDir dir("far-file-float");
    // A float file holds no more than assimp reads: it imports (its vertices as rounded) without a rewrite.
    const std::string path = write(part, 1e4 * kExported, Format::PlyFloat, dir);
    EXPECT_FALSE(detail::recentre_positions(path, nullptr).has_value());
    EXPECT_NO_THROW(import_mesh(path));
    // Near the origin nothing is rewritten: files read exactly as before.
    EXPECT_FALSE(detail::recentre_positions(write(part, Eigen::Vector3d(3, 0, 0), Format::Obj, dir), nullptr));
    EXPECT_TRUE(detail::recentre_positions(write(part, Eigen::Vector3d(30, 0, 0), Format::Obj, dir), nullptr));
}

TEST(FarMeshFile, AFileThisReaderDoesNotFollowIsLeftToAssimp) {
    TempDir dir("far-file-odd");
    const std::string obj = dir.file("odd.obj");
    // A continued line, a number that is not one: not rewritten, so assimp's own reading decides.
    std::ofstream(obj) << "v 1000000 0 \\\n 0\nv 1000001 0 0\nv 1000000 1 0\nf 1 2 3\n";
    EXPECT_FALSE(detail::recentre_positions(obj, nullptr).has_value());
    std::ofstream(obj) << "v 1000000 0 zero\nv 1000001 0 0\nv 1000000 1 0\nf 1 2 3\n";
    EXPECT_FALSE(detail::recentre_positions(obj, nullptr).has_value());
    const std::string ply = dir.file("odd.ply");
    // The vertex element after another one, and a record with a value too many.
    std::ofstream(ply) << "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nelement vertex 3\n"
                          "property double x\nproperty double y\nproperty double z\nend_header\n3 0 1 2\n"
                          "1000000 0 0\n1000001 0 0\n1000000 1 0\n";
    EXPECT_FALSE(detail::recentre_positions(ply, nullptr).has_value());
    std::ofstream(ply) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                          "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "1000000 0 0 7\n1000001 0 0\n1000000 1 0\n3 0 1 2\n";
    EXPECT_FALSE(detail::recentre_positions(ply, nullptr).has_value());
    // A binary file shorter than its header says.
    std::ofstream(ply, std::ios::binary) << "ply\nformat binary_little_endian 1.0\nelement vertex 1000\n"
                                            "property double x\nproperty double y\nproperty double z\nend_header\n0123";
    EXPECT_FALSE(detail::recentre_positions(ply, nullptr).has_value());
    EXPECT_THROW(import_mesh(ply), Error);
}

TEST(FarMeshFile, TheBoxTestSaysFarWhereFloatSpacingPassesTwoToTheMinusTwentyOfTheSize) {
    const Eigen::Vector3d unit(1, 1, 1);
    EXPECT_FALSE(detail::far_for_float(-unit, unit));
    EXPECT_FALSE(detail::far_for_float(Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(12, 2, 2))); // 12 is within 8 sides of 2
    EXPECT_TRUE(detail::far_for_float(Eigen::Vector3d(1e6, 0, 0), Eigen::Vector3d(1e6 + 3, 3, 3)));
    EXPECT_TRUE(detail::far_for_float(Eigen::Vector3d(1e6, 0, 0), Eigen::Vector3d(1e6, 0, 0))); // collapsed by rounding
    EXPECT_FALSE(detail::far_for_float(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()));
    EXPECT_FALSE(detail::far_for_float(Eigen::Vector3d::Constant(NAN), unit));
}

} // namespace
} // namespace spt
