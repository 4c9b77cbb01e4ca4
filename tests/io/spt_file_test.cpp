// The .spt codec: round trips, atomic saves, and every kind of corrupt file refused with an offset.
#include "meshgen.hpp"
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "spt/query.hpp"
#include "spt_reseal.hpp"
#include "test_support.hpp"
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <zlib.h>

using namespace spt;
using spt::test::TempDir;
using spt::test::reseal;

namespace {

// Small on purpose: the corruption tests decode the whole file once per byte.
SptDocument small_document(std::optional<double> tolerance = {}) {
    const ImportedMesh m = meshgen::prepare(meshgen::box(1, 1, 1, 2), "box.obj");
    ConvertOptions o;
    o.tolerance = tolerance;
    o.auto_tolerance = false;
    o.build.leaf_size = 4;
    SptDocument doc = make_document(m.mesh, o);
    // A second tree, made by hand like the editor would.
    SamplingTree hand("feet-first", uint32_t(doc.samples.size()));
    std::vector<uint32_t> low;
    for (uint32_t i = 0; i < doc.samples.size(); ++i)
        if (doc.samples.position(i).z() < 0) low.push_back(i);
    hand.assign_radii(doc.samples, {});
    hand.compute_bounds(doc.samples, BoundsMethod::Tight);
    EXPECT_TRUE(hand.split(1, low, doc.samples));
    doc.trees.push_back(std::move(hand));
    return doc;
}

void expect_same(const SptDocument& a, const SptDocument& b) {
    EXPECT_EQ(a.mesh.name, b.mesh.name);
    EXPECT_EQ(a.mesh.hash, b.mesh.hash);
    EXPECT_EQ(a.mesh.vertex_count, b.mesh.vertex_count);
    EXPECT_EQ(a.mesh.diagonal, b.mesh.diagonal);
    ASSERT_EQ(a.samples.size(), b.samples.size());
    for (size_t i = 0; i < a.samples.size(); ++i) {
        EXPECT_EQ(a.samples.points[i], b.samples.points[i]);
        EXPECT_EQ(a.samples.normals[i], b.samples.normals[i]);
        EXPECT_EQ(a.samples.sources[i], b.samples.sources[i]);
        EXPECT_EQ(a.samples.spacing[i], b.samples.spacing[i]);
    }
    ASSERT_EQ(a.trees.size(), b.trees.size());
    for (size_t t = 0; t < a.trees.size(); ++t) {
        EXPECT_EQ(a.trees[t].name(), b.trees[t].name());
        const auto na = a.trees[t].nodes(), nb = b.trees[t].nodes();
        ASSERT_EQ(na.size(), nb.size());
        for (size_t i = 0; i < na.size(); ++i) {
            EXPECT_EQ(na[i]->id, nb[i]->id);
            EXPECT_EQ(na[i]->center, nb[i]->center);
            EXPECT_EQ(na[i]->bv_radius, nb[i]->bv_radius);
            EXPECT_EQ(na[i]->ss_radius, nb[i]->ss_radius);
            EXPECT_EQ(na[i]->active, nb[i]->active);
            EXPECT_EQ(na[i]->samples, nb[i]->samples);
        }
    }
}

size_t sample_count_offset(const SptDocument& doc) { return 32 + 4 + doc.mesh.name.size() + 4 + 4 + 8 + 8; }

} // namespace

TEST(SptFile, RoundTripKeepsEverything) {
    const SptDocument doc = small_document(0.2);
    EXPECT_GT(doc.samples.size(), 26u); // face samples too
    expect_same(doc, decode_spt(encode_spt(doc), "mem"));
}

TEST(SptFile, TwoSidedSamplesOfAnOpenPartRoundTripAndStayCentredWithoutTheMesh) {
    // An open box (no top): its samples are two-sided, and a model made from the file alone
    // (no mesh, parts unknown) still centres their spheres on the surface and walls nothing in.
    auto raw = meshgen::box(1, 1, 1, 2);
    std::vector<spt::Triangle> t;
    for (const auto& tri : raw.triangles) {
        bool top = true;
        for (uint32_t v : tri) top = top && raw.positions[v].z() > 0.49;
        if (!top) t.push_back(tri);
    }
    const ImportedMesh m = prepare_mesh("cup.obj", raw.positions, std::move(t));
    const SptDocument doc = make_document(m.mesh);
    const SptDocument back = decode_spt(encode_spt(doc), "mem");
    expect_same(doc, back);
    for (size_t i = 0; i < back.samples.size(); ++i) ASSERT_TRUE(back.samples.is_two_sided(i)) << i;
    const CollisionModel model(back);
    const CompactTree& tree = model.tree();
    for (const CompactNode& n : tree.nodes())
        for (uint32_t k = n.first; n.is_active() && k < n.first + n.count; ++k)
            ASSERT_EQ(tree.sphere_center(n, k), back.samples.points[tree.sample_index()[k]]);
    // A small cube inside the cup: open parts enclose nothing, with or without the mesh.
    const SptDocument cube = make_document(meshgen::prepare(meshgen::box(0.2, 0.2, 0.2, 1), "cube.obj").mesh);
    QueryScratch s;
    EXPECT_FALSE(collide_relative(model, CollisionModel(cube), Pose{}, {}, s).collide);
}

TEST(SptFile, SaveIsAtomicAndLoadReadsItBack) {
    TempDir dir("save");
    const SptDocument doc = small_document();
    save_spt(doc, dir.file("a.spt"));
    expect_same(doc, load_spt(dir.file("a.spt")));
    for (const auto& e : std::filesystem::directory_iterator(dir.path()))
        EXPECT_EQ(e.path().filename(), "a.spt") << "temporary file left behind";
}

TEST(SptFile, IsSptFileTellsByTheFirstBytesAndNeverThrows) {
    TempDir dir("magic");
    save_spt(small_document(), dir.file("a.spt"));
    EXPECT_TRUE(is_spt_file(dir.file("a.spt")));
    std::ofstream(dir.file("mesh.obj")) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    EXPECT_FALSE(is_spt_file(dir.file("mesh.obj")));
    std::ofstream(dir.file("short")) << "SPT";
    EXPECT_FALSE(is_spt_file(dir.file("short")));
    // Damaged after the name: still an .spt file, for load_spt to name the damage.
    std::ofstream(dir.file("damaged.spt")) << "SPTREE??";
    EXPECT_TRUE(is_spt_file(dir.file("damaged.spt")));
    EXPECT_THROW(load_spt(dir.file("damaged.spt")), Error);
    EXPECT_FALSE(is_spt_file(dir.file("missing.spt")));
    EXPECT_FALSE(is_spt_file(dir.path()));
}

TEST(SptFile, FailedSaveLeavesTheOldFileIntact) {
    TempDir dir("atomic");
    const SptDocument doc = small_document();
    save_spt(doc, dir.file("a.spt"));
    // Block the temporary file's name with a directory: the save fails before the rename,
    // as a full disk or a crash would, and the old file must survive unchanged.
    std::filesystem::create_directory(dir.file("a.spt.tmp." + std::to_string(::getpid())));
    try {
        save_spt(small_document(0.2), dir.file("a.spt"));
        ADD_FAILURE() << "save should fail";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::CannotWrite);
        EXPECT_NE(std::string(e.what()).find("a.spt"), std::string::npos);
    }
    expect_same(doc, load_spt(dir.file("a.spt")));
}

TEST(SptFile, SaveIntoMissingDirectoryIsCannotWrite) {
    try {
        save_spt(small_document(), "/nonexistent-dir/x.spt");
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::CannotWrite);
        EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.spt"), std::string::npos);
    }
}

TEST(SptFile, EveryTruncationIsRejectedWithAnOffset) {
    const auto bytes = encode_spt(small_document());
    for (size_t len = 0; len < bytes.size(); ++len) {
        const std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + long(len));
        try {
            decode_spt(cut, "cut.spt");
            FAIL() << "length " << len << " accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::BadInput);
            EXPECT_NE(std::string(e.what()).find("cut.spt: byte "), std::string::npos) << e.what();
        }
    }
}

TEST(SptFile, EverySingleBitFlipIsRejected) {
    const auto bytes = encode_spt(small_document());
    for (size_t i = 0; i < bytes.size(); ++i)
        for (int bit = 0; bit < 8; ++bit) {
            auto flipped = bytes;
            flipped[i] ^= uint8_t(1u << bit);
            EXPECT_THROW(decode_spt(flipped, "flip.spt"), Error) << "byte " << i << " bit " << bit;
        }
}

TEST(SptFile, HostileCountsAreCaughtBeforeAllocating) {
    const SptDocument doc = small_document();
    auto bytes = encode_spt(doc);
    const size_t at = sample_count_offset(doc);
    const uint32_t huge = 0x7fffffff;
    std::memcpy(bytes.data() + at, &huge, 4);
    reseal(bytes);
    try {
        decode_spt(bytes, "hostile.spt");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("byte " + std::to_string(at + 4)), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    }
}

TEST(SptFile, HostileButWellSealedEditsAreRejected) {
    // Flip every byte after the header and reseal: the structural checks alone must hold.
    const auto bytes = encode_spt(small_document());
    size_t rejected = 0;
    for (size_t i = 32; i < bytes.size(); ++i) {
        auto edited = bytes;
        edited[i] ^= 0xA5;
        reseal(edited);
        try {
            decode_spt(edited, "sealed.spt");
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::BadInput);
            ++rejected;
        }
    }
    // Float payload edits can be valid data; structure edits must not be.
    EXPECT_GT(rejected, 0u);
}

TEST(SptFile, VersionAndMagicAreChecked) {
    auto bytes = encode_spt(small_document());
    auto wrong_version = bytes;
    wrong_version[8] = 9;
    const uint32_t head = uint32_t(crc32(0, wrong_version.data(), 28));
    std::memcpy(wrong_version.data() + 28, &head, 4);
    try {
        decode_spt(wrong_version, "v9.spt");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("version 9"), std::string::npos) << e.what();
    }
    std::vector<uint8_t> text(64, 'x');
    EXPECT_THROW(decode_spt(text, "text.spt"), Error);
}

TEST(SptFile, MeshFarFromItsOriginIsVersionTwoWithItsLocalOrigin) {
    auto raw = meshgen::box(1, 1, 1, 2);
    for (auto& p : raw.positions) p += Eigen::Vector3d(2.5e4, -1e5, 3.0);
    const SptDocument doc = make_document(meshgen::prepare(raw, "far.obj").mesh);
    EXPECT_FALSE(doc.samples.origin.isZero(0));
    EXPECT_LT((doc.samples.origin - Eigen::Vector3d(2.5e4, -1e5, 3.0)).norm(), 4.0);
    const auto bytes = encode_spt(doc);
    uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 8, 4);
    EXPECT_EQ(version, 2u);
    const SptDocument back = decode_spt(bytes, "far.spt");
    EXPECT_EQ(back.samples.origin, doc.samples.origin);
    expect_same(doc, back);
    EXPECT_EQ(encode_spt(back), bytes);
    // Sample points are local: small numbers, not 1e5.
    for (size_t i = 0; i < back.samples.size(); ++i) EXPECT_LT(back.samples.points[i].norm(), 4.0f);
}

TEST(SptFile, MeshAroundItsOriginStaysVersionOneByteForByte) {
    const SptDocument doc = small_document();
    EXPECT_TRUE(doc.samples.origin.isZero(0));
    const auto bytes = encode_spt(doc);
    uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 8, 4);
    EXPECT_EQ(version, 1u);
    EXPECT_EQ(encode_spt(decode_spt(bytes, "v1.spt")), bytes);
}

TEST(SptFile, NonFiniteOrZeroLocalOriginIsRejected) {
    auto raw = meshgen::box(1, 1, 1, 2);
    for (auto& p : raw.positions) p += Eigen::Vector3d(1e4, 0, 0);
    const SptDocument doc = make_document(meshgen::prepare(raw, "far.obj").mesh);
    const auto bytes = encode_spt(doc);
    const size_t origin_at = sample_count_offset(doc); // the origin sits where version 1 has the sample count
    for (double bad : {std::nan(""), double(INFINITY), 0.0}) {
        auto b = bytes;
        const double zero = 0;
        std::memcpy(b.data() + origin_at, bad == 0 ? &zero : &bad, 8);
        if (bad == 0) std::memcpy(b.data() + origin_at + 8, &zero, 8), std::memcpy(b.data() + origin_at + 16, &zero, 8);
        reseal(b);
        try {
            decode_spt(b, "origin.spt");
            FAIL() << "origin " << bad << " accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("local origin"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("origin.spt: byte " + std::to_string(origin_at)), std::string::npos)
                << e.what();
        }
    }
}

TEST(SptFile, MismatchedMeshIsDetected) {
    const ImportedMesh box = meshgen::prepare(meshgen::box(1, 1, 1, 2), "box.obj");
    const SptDocument doc = make_document(box.mesh);
    EXPECT_EQ(check_mesh_matches(doc.mesh, box.mesh), "");
    auto raw = meshgen::box(1, 1, 1, 2);
    raw.positions[0].z() -= 0.01;
    EXPECT_NE(check_mesh_matches(doc.mesh, meshgen::prepare(raw, "box.obj").mesh), "");
    EXPECT_NE(check_mesh_matches(doc.mesh, meshgen::prepare(meshgen::box(1, 1, 1, 3), "box.obj").mesh), "");
}

TEST(SptFile, FileSizeStaysUnderFortyBytesPerSample) {
    const ImportedMesh m = meshgen::prepare(meshgen::torus(1, 0.3, 200, 100), "torus");
    const SptDocument doc = make_document(m.mesh);
    EXPECT_LE(double(encode_spt(doc).size()) / double(doc.samples.size()), 40.0);
}
