// accuracy_bench --replot: redraws PNGs from their CSVs with no display, and names the file and line of bad input.
#include "run_command.hpp"
#include <QImage>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using spt::test::q;
using spt::test::run_command;

namespace {

const char* kHeader = "mesh,kind,configuration,median_time_ns,agree_near_percent\n";

std::string temp_dir(const std::string& name) {
    const std::string d = std::string(SPT_BINARY_DIR) + "/test-output/replot/" + name;
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// Runs the bench as a cron job or CI step would: the X11 plugin named, no X server.
spt::test::CommandResult bench(const std::string& args) {
    return run_command("env -u DISPLAY -u WAYLAND_DISPLAY QT_QPA_PLATFORM=xcb " + q(ACCURACY_BENCH) + " " + args);
}

const std::string kGood = std::string(kHeader) +
                          "demo,fcl,\"FCL 0.7 (OBBRSS, boolean) — ground truth\",15040,100\n"
                          "demo,spheres,\"spheres, tight, cull off, vertices, leaf 8\",521,100\n"
                          "demo,bounds,\"bounds, tight, cull off, vertices, leaf 8\",491,64.17\n"
                          "demo,brute_force,\"brute force, \"\"all\"\" pairs\",151510000,100\n";

} // namespace

TEST(replot, redraws_every_png_from_its_csv_without_a_display) {
    const std::string d = temp_dir("good");
    write(d + "/accuracy-vs-time-demo.csv", kGood);
    write(d + "/accuracy-vs-time-other.csv", std::string(kHeader) + "other,exact,\"exact\",2650,100\n");
    write(d + "/unrelated.csv", "not a plot\n");
    const auto r = bench("--replot --out " + q(d + "/accuracy-vs-time.md"));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    for (const char* mesh : {"demo", "other"}) {
        const QImage png(QString::fromStdString(d + "/accuracy-vs-time-" + mesh + ".png"));
        ASSERT_FALSE(png.isNull()) << mesh << "\n" << r.output;
        EXPECT_EQ(png.size(), QSize(2000, 1280));
    }
    EXPECT_FALSE(std::filesystem::exists(d + "/accuracy-vs-time.md")) << "--replot measures and writes no tables";
    EXPECT_FALSE(std::filesystem::exists(d + "/unrelated.png"));
}

TEST(replot, mesh_option_redraws_that_mesh_only) {
    const std::string d = temp_dir("one");
    write(d + "/accuracy-vs-time-demo.csv", kGood);
    write(d + "/accuracy-vs-time-other.csv", std::string(kHeader) + "other,exact,\"exact\",2650,100\n");
    const auto r = bench("--replot --mesh other --out " + q(d + "/accuracy-vs-time.md"));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(d + "/accuracy-vs-time-other.png"));
    EXPECT_FALSE(std::filesystem::exists(d + "/accuracy-vs-time-demo.png"));
}

TEST(replot, bad_csv_is_named_with_its_line_and_exits_2) {
    const struct {
        const char* name;
        std::string text;
        const char* says;
    } cases[] = {
        {"header", "mesh,kind,time\n", "line 1: header"},
        {"empty", "", "empty file"},
        {"no-points", kHeader, "no points"},
        {"kind", std::string(kHeader) + "demo,fcl,\"a\",1,100\ndemo,physx,\"b\",2,50\n", "line 3: unknown kind 'physx'"},
        {"time", std::string(kHeader) + "demo,fcl,\"a\",fast,100\n", "line 2: median_time_ns 'fast'"},
        {"nan", std::string(kHeader) + "demo,fcl,\"a\",nan,100\n", "line 2: median_time_ns 'nan'"},
        {"percent", std::string(kHeader) + "demo,fcl,\"a\",10,140\n", "line 2: agree_near_percent '140'"},
        {"fields", std::string(kHeader) + "demo,fcl,a,b,10,100\n", "line 2: expected 5 fields, found 6"},
        {"quotes", std::string(kHeader) + "demo,fcl,\"a,10,100\n", "line 2: unbalanced quotes"},
        {"meshes", std::string(kHeader) + "demo,fcl,a,10,100\nzzz,fcl,a,10,100\n", "line 3: mesh 'zzz' differs"},
    };
    for (const auto& c : cases) {
        const std::string d = temp_dir(std::string("bad-") + c.name);
        const std::string csv = d + "/accuracy-vs-time-demo.csv";
        write(csv, c.text);
        const auto r = bench("--replot --out " + q(d + "/accuracy-vs-time.md"));
        EXPECT_EQ(r.exit_code, 2) << c.name << "\n" << r.output;
        EXPECT_FALSE(r.crashed) << c.name;
        EXPECT_NE(r.output.find(csv), std::string::npos) << c.name << "\n" << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << c.name << "\n" << r.output;
        EXPECT_FALSE(std::filesystem::exists(d + "/accuracy-vs-time-demo.png")) << c.name;
    }
}

TEST(replot, nothing_to_redraw_exits_2) {
    const std::string d = temp_dir("none");
    const auto r = bench("--replot --out " + q(d + "/accuracy-vs-time.md"));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("no plot CSV"), std::string::npos) << r.output;
    const auto missing = bench("--replot --out " + q(d + "/no/such/dir/accuracy-vs-time.md"));
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
}

TEST(replot, unwritable_png_exits_3_and_still_redraws_the_others) {
    const std::string d = temp_dir("unwritable");
    write(d + "/accuracy-vs-time-demo.csv", kGood);
    write(d + "/accuracy-vs-time-other.csv", std::string(kHeader) + "other,exact,\"exact\",2650,100\n");
    std::filesystem::create_directories(d + "/accuracy-vs-time-demo.png"); // a folder where the PNG goes
    const auto r = bench("--replot --out " + q(d + "/accuracy-vs-time.md"));
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("accuracy-vs-time-demo.png"), std::string::npos) << r.output;
    EXPECT_TRUE(std::filesystem::exists(d + "/accuracy-vs-time-other.png"));
}

TEST(replot, bad_flags_exit_1_with_usage) {
    for (const char* args : {"--bogus", "--orientations", "--orientations ten", "--directions 0", "--seed -1"}) {
        const auto r = bench(args);
        EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("usage"), std::string::npos) << args << "\n" << r.output;
    }
}
