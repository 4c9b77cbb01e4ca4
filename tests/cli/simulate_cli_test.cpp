// The `spt simulate` command-line contract, run against the real binary.
#include "../scene/scene_fixture.hpp"
#include "run_command.hpp"
#include "spt/pose.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <fstream>
#include <sstream>

namespace {

using spt::test::q;
using spt::test::run_command;
using spt::test::spt_binary;

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::stringstream s(line);
        std::string cell;
        while (std::getline(s, cell, ',')) cells.push_back(cell);
        if (!line.empty() && line.back() == ',') cells.push_back("");
        rows.push_back(cells);
    }
    return rows;
}

const char* kSteps = "step,time,candidate_pairs,colliding_pairs,node_pairs,sphere_tests,triangle_tests,depth_queries,"
                     "ccd_queries,responses,ns_broad,ns_narrow,ns_depth,ns_ccd,ns_response,ns_deform,ns_dynamics,state_hash";
const char* kContacts = "step,a,b,depth,px,py,pz,nx,ny,nz,toi";

// b moves into a, which sits turned and moved away from the origin.
const char* kPair = R"({"spt_scene": 1, "steps": 7, "effects": ["motion", "contacts", "depth"], "objects": [
    {"name": "a", "model": "box.obj", "static": true, "position": [0.2, -0.1, 0.3], "orientation": [0.9, 0.1, 0.3, 0.2]},
    {"name": "b", "model": "ball.obj", "position": [1.0, 0.0, 0.3], "velocity": [-2, 0, 0]}]})";

class CliSimulate : public ::testing::Test {
protected:
    spt::test::SceneDir dir;
    std::string run(const std::string& args, int* code) {
        const auto r = run_command(spt_binary() + " simulate " + args);
        *code = r.exit_code;
        EXPECT_FALSE(r.crashed) << r.output;
        return r.output;
    }
};

TEST_F(CliSimulate, HeadersAreExactlyTheIssuesAndOneRowPerStep) {
    const std::string scene = dir.write("pair.json", kPair);
    int code;
    const std::string out = run(q(scene) + " -o " + q(dir.file("steps.csv")) + " --contacts " + q(dir.file("c.csv")), &code);
    ASSERT_EQ(code, 0) << out;
    const auto steps = read_csv(dir.file("steps.csv"));
    ASSERT_EQ(steps.size(), 8u); // header + the scene's 7 steps
    std::ifstream in(dir.file("steps.csv"));
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header, kSteps);
    std::ifstream cin(dir.file("c.csv"));
    std::getline(cin, header);
    EXPECT_EQ(header, kContacts);
    for (size_t i = 1; i < steps.size(); ++i) {
        ASSERT_EQ(steps[i].size(), 18u);
        EXPECT_EQ(steps[i][0], std::to_string(i));
        EXPECT_EQ(steps[i][17].size(), 16u);
        EXPECT_EQ(steps[i][17].find_first_not_of("0123456789abcdef"), std::string::npos);
    }
    const auto contacts = read_csv(dir.file("c.csv"));
    ASSERT_GT(contacts.size(), 1u);
    for (size_t i = 1; i < contacts.size(); ++i) {
        ASSERT_EQ(contacts[i].size(), 11u);
        EXPECT_EQ(contacts[i][1], "a");
        EXPECT_FALSE(contacts[i][3].empty()); // depth on
        EXPECT_TRUE(contacts[i][10].empty()); // ccd off: no toi
    }
    // --steps replaces the scene's count; stdout without -o.
    const std::string three = run(q(scene) + " --steps 3", &code);
    EXPECT_EQ(code, 0);
    EXPECT_EQ(std::count(three.begin(), three.end(), '\n'), 4);
}

TEST_F(CliSimulate, PosesOutHasARowPerObjectPerStepFromTheInitialState) {
    // a static and turned, b moving at (-2, 0, 0), c on a path: 1 unit along y and a quarter turn
    // about z over its first second.
    const std::string scene = dir.write("three.json", R"({"spt_scene": 1, "dt": 0.25, "steps": 6,
        "effects": ["motion", "contacts"], "objects": [
        {"name": "a", "model": "box.obj", "static": true, "position": [0.2, -0.1, 0.3], "orientation": [0.9, 0.1, 0.3, 0.2]},
        {"name": "b", "model": "ball.obj", "position": [5.0, 0.0, 0.0], "velocity": [-2, 0, 0]},
        {"name": "c", "model": "ball.obj", "path": [{"t": 0, "position": [0, 3, 0]},
                                                     {"t": 1, "position": [0, 4, 0], "orientation": [0.7071067811865476, 0, 0, 0.7071067811865476]}]}]})");
    int code;
    const std::string out = run(q(scene) + " -o " + q(dir.file("steps.csv")) + " --poses-out " + q(dir.file("poses.csv")), &code);
    ASSERT_EQ(code, 0) << out;
    std::ifstream in(dir.file("poses.csv"));
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header, "step,time,object,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz");
    const auto rows = read_csv(dir.file("poses.csv"));
    ASSERT_EQ(rows.size(), 1u + 7 * 3); // steps 0 to 6, three objects each, in object order
    auto at = [&](int step, int object, int column) { return std::stod(rows[size_t(1 + 3 * step + object)][size_t(column)]); };
    for (int step = 0; step <= 6; ++step) {
        for (int o = 0; o < 3; ++o) {
            const auto& r = rows[size_t(1 + 3 * step + o)];
            ASSERT_EQ(r.size(), 16u);
            EXPECT_EQ(r[0], std::to_string(step));
            EXPECT_EQ(r[2], std::string(1, char('a' + o)));
            EXPECT_DOUBLE_EQ(std::stod(r[1]), 0.25 * step);
        }
        // a stays where it was put, unit orientation, still.
        EXPECT_DOUBLE_EQ(at(step, 0, 3), 0.2);
        for (int k = 10; k < 16; ++k) EXPECT_EQ(at(step, 0, k), 0.0);
        // b moves by its velocity.
        EXPECT_NEAR(at(step, 1, 3), 5.0 - 2.0 * 0.25 * step, 1e-12);
        EXPECT_EQ(at(step, 1, 10), -2.0);
        // c: the path's slope until t = 1, then held.
        const bool moving = 0.25 * step < 1;
        EXPECT_NEAR(at(step, 2, 4), 3.0 + std::min(1.0, 0.25 * step), 1e-12);
        EXPECT_NEAR(at(step, 2, 11), moving ? 1.0 : 0.0, 1e-12);
        EXPECT_NEAR(at(step, 2, 15), moving ? M_PI / 2 : 0.0, 1e-9); // a quarter turn about z in 1 s
    }
}

TEST_F(CliSimulate, StagesThatAreOffCountAndCostNothing) {
    const std::string scene = dir.write("pair.json", kPair);
    int code;
    run(q(scene) + " --effects motion -o " + q(dir.file("m.csv")), &code);
    ASSERT_EQ(code, 0);
    for (const auto& row : read_csv(dir.file("m.csv"))) {
        if (row[0] == "step") continue;
        for (size_t col = 2; col <= 14; ++col) EXPECT_EQ(row[col], "0") << "column " << col;
    }
    run(q(scene) + " --effects motion,contacts,depth,pairs,response,ccd,exact -o " + q(dir.file("all.csv")), &code);
    ASSERT_EQ(code, 0);
    const auto rows = read_csv(dir.file("all.csv"));
    bool seen[16] = {};
    for (size_t i = 1; i < rows.size(); ++i)
        for (size_t col = 2; col <= 14; ++col) seen[col] |= rows[i][col] != "0";
    for (size_t col = 2; col <= 14; ++col) EXPECT_TRUE(seen[col]) << "column " << col << " stayed 0";
}

TEST_F(CliSimulate, UnknownAndMissingDependencyEffectsAreExitTwoNamingBoth) {
    const std::string scene = dir.write("pair.json", kPair);
    int code;
    std::string out = run(q(scene) + " --effects motion,flying", &code);
    EXPECT_EQ(code, 2);
    EXPECT_NE(out.find("unknown effect 'flying'"), std::string::npos) << out;
    out = run(q(scene) + " --effects motion,contacts,response", &code);
    EXPECT_EQ(code, 2);
    EXPECT_NE(out.find("effect 'response' needs effect 'depth'"), std::string::npos) << out;
    const std::string bad = dir.write("bad.json", R"({"spt_scene": 1, "effects": ["ccd"], "objects": []})");
    out = run(q(bad), &code);
    EXPECT_EQ(code, 2);
    EXPECT_NE(out.find("bad.json: at /effects"), std::string::npos) << out;
}

TEST_F(CliSimulate, BadScenesAndOptionsGetTheirExitCodes) {
    int code;
    std::string out = run(q(dir.write("neg.json", R"({"spt_scene": 1, "dt": -1, "objects": []})")), &code);
    EXPECT_EQ(code, 2);
    EXPECT_NE(out.find("neg.json: at /dt"), std::string::npos) << out;
    out = run(q(dir.write("nan.json", "{\"spt_scene\": 1,\n\"gravity\": [0, NaN, 0], \"objects\": []}")), &code);
    EXPECT_EQ(code, 2);
    EXPECT_NE(out.find("/gravity/1"), std::string::npos) << out;
    out = run(q(dir.file("absent.json")), &code);
    EXPECT_EQ(code, 2);
    out = run(q(dir.write("pair.json", kPair)) + " --frobnicate", &code);
    EXPECT_EQ(code, 1);
    out = run(q(dir.file("pair.json")) + " --threads 0", &code);
    EXPECT_EQ(code, 1);
    out = run(q(dir.file("pair.json")) + " -o " + q(dir.file("no/such/dir/x.csv")), &code);
    EXPECT_EQ(code, 3);
    out = run(q(dir.file("pair.json")) + " -o " + q(dir.file("s.csv")) + " --poses-out " + q(dir.file("no/such/dir/p.csv")), &code);
    EXPECT_EQ(code, 3);
    EXPECT_NE(out.find("p.csv"), std::string::npos) << out;
    const std::string comma = dir.write("comma.json", R"({"spt_scene": 1, "objects": [{"name": "a,b", "model": "box.obj"}]})");
    out = run(q(comma) + " -o " + q(dir.file("s.csv")) + " --poses-out " + q(dir.file("p.csv")), &code);
    EXPECT_EQ(code, 2);
    EXPECT_NE(out.find("'a,b'"), std::string::npos) << out;
    out = run("--help", &code);
    EXPECT_EQ(code, 0);
    EXPECT_NE(out.find("--effects"), std::string::npos);
}

std::vector<std::string> hash_column(const std::string& csv) {
    std::vector<std::string> h;
    for (const auto& row : read_csv(csv))
        if (row[0] != "step") h.push_back(row[17]);
    return h;
}

TEST_F(CliSimulate, StateHashesAreTheSameOnEveryRunAndForEveryThreadCount) {
    std::string objects = R"({"name": "floor", "model": "plate.obj", "static": true, "position": [0, -1.5, 0]})";
    for (int i = 0; i < 12; ++i)
        objects += ",{\"name\": \"o" + std::to_string(i) + "\", \"model\": \"ball.spt\", \"position\": [" +
                   std::to_string(1.05 * (i % 4) - 1.5) + ", " + std::to_string(0.3 * (i % 3)) + ", " +
                   std::to_string(1.05 * (i / 4) - 1) + "], \"velocity\": [" + std::to_string((i % 5) - 2) + ", 0, " +
                   std::to_string((i % 3) - 1) + "], \"angular_velocity\": [1, 0, 0]}";
    const std::string scene = dir.write("many.json", R"({"spt_scene": 1, "steps": 40, "response": {"restitution": 0.5},
        "effects": ["motion", "gravity", "contacts", "depth", "response", "ccd"], "objects": [)" + objects + "]}");
    int code;
    run(q(scene) + " -o " + q(dir.file("t1.csv")), &code);
    ASSERT_EQ(code, 0);
    run(q(scene) + " -o " + q(dir.file("t1b.csv")), &code);
    run(q(scene) + " --threads 2 -o " + q(dir.file("t2.csv")), &code);
    run(q(scene) + " --threads 3 -o " + q(dir.file("t3.csv")), &code);
    const auto one = hash_column(dir.file("t1.csv"));
    ASSERT_EQ(one.size(), 40u);
    EXPECT_NE(one.front(), one.back());
    EXPECT_EQ(hash_column(dir.file("t1b.csv")), one);
    EXPECT_EQ(hash_column(dir.file("t2.csv")), one);
    EXPECT_EQ(hash_column(dir.file("t3.csv")), one);
    uint64_t colliding = 0;
    for (const auto& row : read_csv(dir.file("t1.csv")))
        if (row[0] != "step") colliding += std::stoull(row[3]);
    EXPECT_GT(colliding, 0u);
}

TEST_F(CliSimulate, CollidingPairAnswersAsSptQueryAtTheSameRelativePose) {
    // No motion: the poses of step 1 are the scene's, so B's pose in A's frame is known here.
    const std::string scene = dir.write("still.json", R"({"spt_scene": 1, "objects": [
        {"name": "a", "model": "box.obj", "position": [0.2, -0.1, 0.3], "orientation": [0.9, 0.1, 0.3, 0.2]},
        {"name": "b", "model": "ball.obj", "position": [0.75, 0.3, 0.5], "orientation": [0.5, 0.5, -0.5, 0.5]}]})");
    int code;
    run(q(scene) + " --steps 1 --effects contacts,depth -o " + q(dir.file("s.csv")) + " --contacts " + q(dir.file("c.csv")), &code);
    ASSERT_EQ(code, 0);
    const auto contacts = read_csv(dir.file("c.csv"));
    ASSERT_EQ(contacts.size(), 2u);
    const spt::Pose pa = spt::Pose::from({0.2, -0.1, 0.3}, Eigen::Quaterniond(0.9, 0.1, 0.3, 0.2));
    const spt::Pose pb = spt::Pose::from({0.75, 0.3, 0.5}, Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5));
    const spt::Pose rel = spt::relative_pose(pa, pb);
    char line[512];
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", rel.translation.x(),
                  rel.translation.y(), rel.translation.z(), rel.rotation.w(), rel.rotation.x(), rel.rotation.y(),
                  rel.rotation.z());
    std::ofstream(dir.file("poses.txt")) << line;
    const auto r = run_command(spt_binary() + " query " + q(dir.file("box.obj")) + " " + q(dir.file("ball.obj")) +
                               " --poses " + q(dir.file("poses.txt")) + " --mode deepest --repeat 1 -o " +
                               q(dir.file("q.csv")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto query = read_csv(dir.file("q.csv"));
    ASSERT_EQ(query.size(), 2u);
    EXPECT_EQ(query[1][1], "1"); // collide
    // The ball lies deep in the box (surfaces crossed by more than half a sampling reach): the
    // scene's depth is a deep pair's, within the deep-overlap allowance of the deepest (2% of the
    // two largest sampling radii, each at most 0.5 here; docs/scenes.md), never deeper.
    const double deepest = std::stod(query[1][2]), depth = std::stod(contacts[1][3]);
    EXPECT_LE(depth, deepest + 1e-6 * deepest);
    EXPECT_GE(depth, deepest - 0.02 * (0.5 + 0.5));
}

} // namespace

namespace {

// A unit box dropped onto a plate under dynamics.
const char* kDrop = R"({"spt_scene": 1, "steps": 60, "effects": ["motion", "gravity", "contacts", "dynamics"], "objects": [
    {"name": "plate", "model": "plate.obj", "static": true},
    {"name": "box", "model": "box.obj", "position": [0, 0.8, 0]}]})";

TEST_F(CliSimulate, DynamicsTimesItsSolverAndTheBoxComesToRestOnThePlate) {
    const std::string scene = dir.write("drop.json", kDrop);
    int code;
    const std::string out = run(q(scene) + " -o " + q(dir.file("steps.csv")) + " --poses-out " + q(dir.file("poses.csv")), &code);
    ASSERT_EQ(code, 0) << out;
    const auto steps = read_csv(dir.file("steps.csv"));
    ASSERT_EQ(steps.size(), 61u);
    EXPECT_EQ(steps.back()[3], "1");          // colliding_pairs: the box rests on the plate
    EXPECT_GT(std::stoll(steps.back()[16]), 0); // ns_dynamics
    EXPECT_EQ(steps.back()[14], "0");          // ns_response: the paper's rule does not run
    const auto poses = read_csv(dir.file("poses.csv"));
    const auto& last = poses.back(); // the box after the last step: its bottom on the plate's top (y = 0.01)
    ASSERT_EQ(last[2], "box");
    EXPECT_NEAR(std::stod(last[4]), 0.51, 0.01);
}

TEST_F(CliSimulate, DynamicsWithResponseOrAMasslessPebbleIsExitTwoNamingThem) {
    const std::string scene = dir.write("drop.json", kDrop);
    int code;
    std::string out = run(q(scene) + " --effects motion,contacts,depth,response,dynamics", &code);
    EXPECT_EQ(code, 2);
    EXPECT_NE(out.find("effects 'response' and 'dynamics' cannot run together"), std::string::npos) << out;
    const std::string pebble = dir.write("pebble.json", R"({"spt_scene": 1, "effects": ["motion", "contacts", "dynamics"],
        "objects": [{"name": "pebble", "model": "ball.spt", "velocity": [1, 0, 0]}]})");
    out = run(q(pebble), &code);
    EXPECT_EQ(code, 2);
    EXPECT_NE(out.find("object 'pebble'"), std::string::npos) << out;
    EXPECT_NE(out.find("'mass'"), std::string::npos) << out;
}

} // namespace
