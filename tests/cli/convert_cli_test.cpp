// `spt convert` run as a user would: real binary, real files.
#include "meshgen.hpp"
#include "run_command.hpp"
#include "spt/spt_file.hpp"
#include "test_support.hpp"
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace spt;
using namespace spt::test;
namespace fs = std::filesystem;

namespace {

std::vector<uint8_t> read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

} // namespace

TEST(ConvertCli, BundledMeshesConvertAndValidate) {
    TempDir out("bundled");
    const auto r = run_command(spt_binary() + " convert " + q(project_meshes()) + "/*.* --out-dir " + q(out.path()));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("converted 5, failed 0"), std::string::npos) << r.output;
    for (const char* name : {"figure", "torus", "box", "cad_part", "sphere"}) {
        const std::string spt = out.file(std::string(name) + ".spt");
        ASSERT_TRUE(fs::exists(spt)) << name;
        EXPECT_EQ(load_spt(spt).validate(), "");
    }
}

TEST(ConvertCli, AssimpTestModelsInManyFormatsConvert) {
    TempDir out("assimp");
    const std::string m = assimp_models();
    std::string files;
    for (const char* f : {"/PLY/Wuson.ply", "/OBJ/spider.obj", "/STL/Spider_binary.stl", "/STL/Spider_ascii.stl",
                          "/OFF/Cube.off", "/Collada/duck.dae", "/3DS/fels.3ds", "/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "/FBX/spider.fbx",
                          "/FBX/box.fbx"})
        if (fs::exists(m + f)) files += " " + q(m + f);
    ASSERT_FALSE(files.empty());
    // Reading is under test here, not sampling: vertex samples keep it quick.
    const auto r = run_command(spt_binary() + " convert" + files + " --vertices-only --out-dir " + q(out.path()) + " -j 2");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("failed 0"), std::string::npos) << r.output;
}

TEST(ConvertCli, EveryInvalidModelFailsCleanlyWithItsName) {
    TempDir out("invalid");
    for (const auto& e : fs::directory_iterator(assimp_models() + "/invalid")) {
        const std::string path = e.path().string();
        // Its header asks for 1.3e9 vertices. A worker's memory limit refuses them (bad_alloc,
        // exit 2), but under AddressSanitizer workers have no limit (process_pool.cpp), so the
        // reader would zero 16 GiB first: checked by the Release suite alone.
        if (kAddressSanitizer && e.path().filename() == "OutOfMemory.off") continue;
        const auto r = run_command(spt_binary() + " convert " + q(path) + " -o " + q(out.file("x.spt")) + " --force");
        EXPECT_FALSE(r.crashed) << path << "\n" << r.output;
        if (r.exit_code == 0) continue; // a few "invalid" files still hold a readable mesh
        EXPECT_EQ(r.exit_code, 2) << path << "\n" << r.output;
        EXPECT_NE(r.output.find(path), std::string::npos) << r.output;
    }
}

TEST(ConvertCli, OneBadFileDoesNotStopTheOthers) {
    TempDir out("batch");
    std::ofstream(out.file("broken.obj")) << "v 0 0 0\nv 1 0 0\nf 1 2 9\n";
    const auto r = run_command(spt_binary() + " convert " + q(project_meshes() + "/torus.obj") + " " +
                               q(out.file("broken.obj")) + " " + q(project_meshes() + "/box.ply") + " --out-dir " +
                               q(out.file("o")));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("converted 2, failed 1"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(out.file("o/torus.spt")));
    EXPECT_TRUE(fs::exists(out.file("o/box.spt")));
    EXPECT_FALSE(fs::exists(out.file("o/broken.spt")));
}

TEST(ConvertCli, NaNCoordinateIsBadInputNamingTheFile) {
    TempDir out("nan");
    std::ofstream(out.file("nan.obj")) << "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n";
    const auto r = run_command(spt_binary() + " convert " + q(out.file("nan.obj")) + " -o " + q(out.file("n.spt")));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("nan.obj"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out.file("n.spt")));
}

TEST(ConvertCli, ToleranceFarBelowTheMeshsDetailIsExitTwoNamingTheFile) {
    // Model units mistaken for a fraction of the diagonal: torus.obj would need about 1e12 samples.
    TempDir out("tiny-tolerance");
    const auto r = run_command(spt_binary() + " convert " + q(project_meshes() + "/torus.obj") +
                               " --tolerance 1e-6 -o " + q(out.file("t.spt")));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("torus.obj: a tolerance of 1e-06"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("give a larger --tolerance"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out.file("t.spt")));
}

TEST(ConvertCli, ParallelOutputIsByteIdenticalToSerial) {
    TempDir out("determinism");
    const std::string in = q(project_meshes()) + "/*.*";
    ASSERT_EQ(run_command(spt_binary() + " convert " + in + " -q -j 1 --out-dir " + q(out.file("a"))).exit_code, 0);
    ASSERT_EQ(run_command(spt_binary() + " convert " + in + " -q -j 2 --out-dir " + q(out.file("b"))).exit_code, 0);
    for (const auto& e : fs::directory_iterator(out.file("a")))
        EXPECT_EQ(read_bytes(e.path().string()), read_bytes(out.file("b/" + e.path().filename().string())))
            << e.path().filename();
}

TEST(ConvertCli, ThreadCountChangesNoByteAndTimesNameEveryStage) {
    TempDir out("threads");
    const std::string in = q(project_meshes() + "/cad_part.stl"); // vertex and face samples
    const auto one = run_command(spt_binary() + " convert " + in + " --threads 1 --times -o " + q(out.file("1.spt")));
    const auto three = run_command(spt_binary() + " convert " + in + " --threads 3 -o " + q(out.file("3.spt")));
    ASSERT_EQ(one.exit_code, 0) << one.output;
    ASSERT_EQ(three.exit_code, 0) << three.output;
    EXPECT_EQ(read_bytes(out.file("1.spt")), read_bytes(out.file("3.spt")));
    const size_t at = one.output.find("  time: import ");
    ASSERT_NE(at, std::string::npos) << one.output;
    const std::string line = one.output.substr(at, one.output.find('\n', at) - at);
    for (const char* stage : {" s, sampling ", " s, tree ", " s, save ", " s (1 thread)"})
        EXPECT_NE(line.find(stage), std::string::npos) << line;
    EXPECT_EQ(three.output.find("time:"), std::string::npos) << "times only when asked for";
    EXPECT_NE(run_command(spt_binary() + " convert " + in + " --threads 0 -o " + q(out.file("0.spt"))).exit_code, 0);
}

TEST(ConvertCli, OptionsReachTheFile) {
    TempDir out("options");
    const auto r = run_command(spt_binary() + " convert " + q(project_meshes() + "/cad_part.stl") + " -o " +
                               q(out.file("c.spt")) + " --leaf-size 4 --radius 0.05 --tolerance 0.02 --bounds paper " +
                               "--strategy median --tree-name walk");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const SptDocument doc = load_spt(out.file("c.spt"));
    ASSERT_NE(doc.tree("walk"), nullptr);
    for (const TreeNode* n : doc.tree("walk")->active_nodes()) {
        EXPECT_LE(n->samples.size(), 4u);
        EXPECT_FLOAT_EQ(n->ss_radius, 0.05f);
    }
    size_t face = 0;
    for (size_t i = 0; i < doc.samples.size(); ++i) face += doc.samples.is_face_sample(i);
    EXPECT_GT(face, 0u);
}

TEST(ConvertCli, SameNameInputsKeepTheirExtensions) {
    TempDir out("clash");
    const std::string m = assimp_models();
    const auto r = run_command(spt_binary() + " convert " + q(m + "/OBJ/spider.obj") + " " + q(m + "/FBX/spider.fbx") +
                               " --out-dir " + q(out.path()));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(fs::exists(out.file("spider.obj.spt")));
    EXPECT_TRUE(fs::exists(out.file("spider.fbx.spt")));
}

TEST(ConvertCli, AppendAddsANamedTreeOverTheSameSamples) {
    TempDir out("append");
    const std::string fig = q(project_meshes() + "/figure.obj"), spt = q(out.file("f.spt"));
    ASSERT_EQ(run_command(spt_binary() + " convert " + fig + " -o " + spt).exit_code, 0);
    auto r = run_command(spt_binary() + " convert " + fig + " -o " + spt + " --append --tree-name walk --leaf-size 2");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const SptDocument doc = load_spt(out.file("f.spt"));
    ASSERT_EQ(doc.trees.size(), 2u);
    ASSERT_NE(doc.tree("walk"), nullptr);
    for (const TreeNode* n : doc.tree("walk")->active_nodes()) EXPECT_LE(n->samples.size(), 2u);
    // Same name again: refused without --force, replaced with it.
    r = run_command(spt_binary() + " convert " + fig + " -o " + spt + " --append --tree-name walk");
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_EQ(run_command(spt_binary() + " convert " + fig + " -o " + spt + " --append --tree-name walk -f").exit_code, 0);
    EXPECT_EQ(load_spt(out.file("f.spt")).trees.size(), 2u);
    // A different mesh: refused, file untouched.
    r = run_command(spt_binary() + " convert " + q(project_meshes() + "/torus.obj") + " -o " + spt + " --append --tree-name x");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(load_spt(out.file("f.spt")).trees.size(), 2u);
}

TEST(ConvertCli, UsageErrorsExitOne) {
    TempDir out("usage");
    const std::string torus = q(project_meshes() + "/torus.obj");
    for (const std::string& args : std::vector<std::string>{std::string("convert"), "convert " + torus + " --bogus", "convert " + torus + " --leaf-size 0",
          "convert " + torus + " --bounds round", "convert " + torus + " --radius -1",
          "convert " + torus + " --tolerance nan", "convert " + torus + " --radius inf",
          "convert " + torus + " --timeout nan", "convert " + torus + " --timeout inf", "convert " + torus + " --timeout -1",
          "convert " + torus + " --append --tolerance 0.1 -o " + q(out.file("y.spt")), "convert " + torus + " --clip-poses 0",
          "convert " + torus + " --clip-poses nan", "convert " + torus + " --protrusion -1",
          "convert " + torus + " --append --clip-poses 0.1 -o " + q(out.file("y.spt")), "convert " + torus + " " + torus + " -o " + q(out.file("x.spt")),
          "convert " + torus + " -o " + q(out.path().string()), "convert " + torus + " -o " + q(out.file("new/")),
          std::string("frobnicate")}) {
        const auto r = run_command(spt_binary() + " " + args);
        EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.output;
    }
}

TEST(ConvertCli, UnwritableOutputExitsThree) {
    TempDir out("unwritable");
    const std::string torus = q(project_meshes() + "/torus.obj");
    auto r = run_command(spt_binary() + " convert " + torus + " -o /nonexistent-dir/t.spt");
    EXPECT_EQ(r.exit_code, 3) << r.output;
    ASSERT_EQ(run_command(spt_binary() + " convert " + torus + " -o " + q(out.file("t.spt"))).exit_code, 0);
    const auto before = read_bytes(out.file("t.spt"));
    r = run_command(spt_binary() + " convert " + q(project_meshes() + "/box.ply") + " -o " + q(out.file("t.spt")));
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("--force"), std::string::npos) << r.output;
    EXPECT_EQ(read_bytes(out.file("t.spt")), before) << "an existing file was overwritten without --force";
}

TEST(ConvertCli, HelpListsEveryOption) {
    const auto r = run_command(spt_binary() + " convert --help");
    EXPECT_EQ(r.exit_code, 0);
    for (const char* opt :
         {"--out-dir", "--leaf-size", "--radius", "--tolerance", "--protrusion", "--clip-poses", "--bounds", "--jobs",
          "--threads", "--times", "--force"})
        EXPECT_NE(r.output.find(opt), std::string::npos) << opt;
}

namespace {

// An animated mesh's conversion reports each clip's stretch and coverage.
TEST(ConvertClips, EachClipOfAnAnimatedMeshIsReportedWithItsStretchAndGaps) {
    spt::test::TempDir dir{"convert-clips"};
    const auto r = spt::test::run_command(spt::test::spt_binary() + " convert " +
                                          spt::test::q(std::string(SPT_SOURCE_DIR) + "/tests/data/anim/bending_bar.gltf") +
                                          " -o " + spt::test::q(dir.file("bar.spt")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* clip : {"clip 'linear'", "clip 'step'", "clip 'cubic'"})
        EXPECT_NE(r.output.find(clip), std::string::npos) << clip << "\n" << r.output;
    EXPECT_NE(r.output.find("stretch up to"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("largest coverage gap"), std::string::npos) << r.output;
    // A static mesh has no such line.
    const auto s = spt::test::run_command(spt::test::spt_binary() + " convert " +
                                          spt::test::q(spt::test::project_meshes() + "/box.ply") + " -o " +
                                          spt::test::q(dir.file("box.spt")));
    ASSERT_EQ(s.exit_code, 0) << s.output;
    EXPECT_EQ(s.output.find("clip '"), std::string::npos) << s.output;
}

// --clip-poses limits the radii at the clips' poses too: the bar's spheres where it bends get
// smaller, none larger; a mesh without clips is converted as without it, with a note.
TEST(ConvertClips, ClipPosesLimitTheRadiiAtTheClipsPosesToo) {
    spt::test::TempDir dir{"convert-clip-poses"};
    const std::string bar = spt::test::q(std::string(SPT_SOURCE_DIR) + "/tests/data/anim/bending_bar.gltf");
    const auto convert = [&](const std::string& args, const std::string& name) {
        const auto r = spt::test::run_command(spt::test::spt_binary() + " convert " + bar + " --vertices-only -o " +
                                              spt::test::q(dir.file(name)) + args);
        EXPECT_EQ(r.exit_code, 0) << r.output;
        return std::make_pair(r.output, load_spt(dir.file(name)));
    };
    const auto [plain_out, plain] = convert("", "plain.spt");
    const auto [posed_out, posed] = convert(" --clip-poses 0.05", "posed.spt");
    EXPECT_EQ(plain_out.find("clip poses:"), std::string::npos) << plain_out;
    EXPECT_NE(plain_out.find("radii limited at the bind pose; "), std::string::npos) << plain_out;
    EXPECT_NE(posed_out.find("clip poses: radii limited at"), std::string::npos) << posed_out;
    EXPECT_EQ(posed_out.find("radii limited at the bind pose; "), std::string::npos) << posed_out;
    ASSERT_EQ(plain.samples.size(), posed.samples.size()); // vertices only: the same samples
    size_t smaller = 0;
    for (size_t i = 0; i < plain.samples.size(); ++i) {
        EXPECT_LE(posed.samples.max_radius[i], plain.samples.max_radius[i]) << "sample " << i;
        smaller += posed.samples.max_radius[i] < plain.samples.max_radius[i];
    }
    EXPECT_GT(smaller, 0u);
    // A smaller allowance gives smaller radii where a sphere would poke out.
    const auto [tight_out, tight] = convert(" --protrusion 0.0005", "tight.spt");
    size_t tighter = 0;
    for (size_t i = 0; i < plain.samples.size(); ++i) tighter += tight.samples.max_radius[i] < plain.samples.max_radius[i];
    EXPECT_GT(tighter, 0u) << tight_out;
    const auto s = spt::test::run_command(spt::test::spt_binary() + " convert " +
                                          spt::test::q(spt::test::project_meshes() + "/box.ply") + " --clip-poses 0.1 -o " +
                                          spt::test::q(dir.file("box.spt")));
    ASSERT_EQ(s.exit_code, 0) << s.output;
    EXPECT_NE(s.output.find("has no clips; --clip-poses limits radii at the bind pose alone"), std::string::npos) << s.output;
}

} // namespace
