// Google Benchmark: depth and response of deep overlaps (issue 37, item 5). Two 480-triangle
// balls (default conversion) overlapping by half their radius, and 1,000 such balls at random
// positions and velocities (a fixed seed), effects motion,contacts,depth,response. Each
// iteration builds the scene's simulation and runs its first steps (two balls: one; 1,000
// balls: 20); the time reported is their ns_depth + ns_response (manual time, for the 1,000
// balls the sum of 20 steps), the counters are a step's.
#include "spt/simulation.hpp"
#include "meshgen.hpp"
#include <benchmark/benchmark.h>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <unistd.h>

namespace {

using namespace spt;
namespace fs = std::filesystem;

constexpr double kRadius = 0.5;

// The ball's OBJ in a folder of this process, written once.
const std::string& ball_file() {
    static const std::string path = [] {
        const fs::path dir = fs::temp_directory_path() / ("spt-deep-bench-" + std::to_string(getpid()));
        fs::create_directories(dir);
        const std::string p = (dir / "ball.obj").string();
        meshgen::write_obj(meshgen::uv_sphere(kRadius, 16, 16), p);
        return p;
    }();
    return path;
}

struct Ball {
    Eigen::Vector3d position, velocity;
    Eigen::Vector4d orientation{1, 0, 0, 0}; // w x y z
};

Scene scene_of(const std::vector<Ball>& balls) {
    std::ostringstream j;
    j.precision(17);
    j << R"({"spt_scene": 1, "dt": 0.01, "effects": ["motion", "contacts", "depth", "response"], "objects": [)";
    for (size_t i = 0; i < balls.size(); ++i) {
        const Ball& b = balls[i];
        j << (i ? "," : "") << R"({"name": "b)" << i << R"(", "model": "ball.obj", "position": [)" << b.position.x()
          << ", " << b.position.y() << ", " << b.position.z() << R"(], "velocity": [)" << b.velocity.x() << ", "
          << b.velocity.y() << ", " << b.velocity.z() << R"(], "orientation": [)" << b.orientation[0] << ", "
          << b.orientation[1] << ", " << b.orientation[2] << ", " << b.orientation[3] << "]}";
    }
    j << "]}";
    Scene s = parse_scene(j.str(), "bench", fs::path(ball_file()).parent_path().string());
    load_models(s);
    return s;
}

// Two balls whose centres are 1.5 radii apart. `together`: the same velocity (no relative
// motion: the response leaves along the contact normal); else approaching each other (the
// backtrack along the motion passes the step's motion, then leaves along the normal).
Scene two_balls(bool together) {
    const Eigen::Vector3d v(1, 0.5, 0);
    return scene_of({{Eigen::Vector3d::Zero(), v}, {Eigen::Vector3d(1.5 * kRadius, 0, 0), together ? v : -v}});
}

// The same two balls moving together, their centres 1.5 radii apart along a random line and B
// turned at random (a fixed seed): lines that pass through no pole or vertex in particular.
std::vector<Scene> two_balls_on_random_lines(int count) {
    std::mt19937 rng(53);
    std::normal_distribution<double> g;
    std::vector<Scene> scenes;
    for (int k = 0; k < count; ++k) {
        const Eigen::Vector3d dir = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
        const Eigen::Vector4d q = Eigen::Vector4d(g(rng), g(rng), g(rng), g(rng)).normalized();
        const Eigen::Vector3d v(1, 0.5, 0);
        scenes.push_back(scene_of({{Eigen::Vector3d::Zero(), v}, {1.5 * kRadius * dir, v, q}}));
    }
    return scenes;
}

// 1,000 balls at random places in a cube of side 34, none overlapping at the start, velocities
// up to 5 units/s a component: contacts come from the motion, a dozen or so a step.
Scene thousand_balls() {
    std::mt19937 rng(37);
    std::uniform_real_distribution<double> p(0, 34), v(-5, 5);
    std::vector<Ball> balls;
    while (balls.size() < 1000) {
        const Eigen::Vector3d c(p(rng), p(rng), p(rng));
        bool clear = true;
        for (const Ball& b : balls) clear = clear && (b.position - c).norm() >= 2 * kRadius;
        if (clear) balls.push_back({c, Eigen::Vector3d(v(rng), v(rng), v(rng))});
    }
    return scene_of(balls);
}

// Runs `steps` steps of each scene from its start; the time is their depth + response, the mean
// over the scenes, and the counters are a step's.
void steps_from_start(benchmark::State& state, const std::vector<Scene>& scenes, int threads, int steps) {
    StepCounters sum;
    for (auto _ : state) {
        int64_t ns = 0;
        for (const Scene& scene : scenes) {
            Simulation sim(scene, scene.effects, threads);
            for (int i = 0; i < steps; ++i) {
                const StepCounters& c = sim.step().counters;
                ns += c.ns_depth + c.ns_response;
                sum.colliding_pairs += c.colliding_pairs, sum.node_pairs += c.node_pairs;
                sum.sphere_tests += c.sphere_tests, sum.ns_depth += c.ns_depth, sum.ns_response += c.ns_response;
                sum.ns_narrow += c.ns_narrow;
            }
        }
        state.SetIterationTime(double(ns) * 1e-9 / double(scenes.size()));
    }
    const double per_step = 1.0 / double(state.iterations()) / steps / double(scenes.size());
    state.counters["colliding_pairs"] = double(sum.colliding_pairs) * per_step;
    state.counters["node_pairs"] = double(sum.node_pairs) * per_step;
    state.counters["sphere_tests"] = double(sum.sphere_tests) * per_step;
    state.counters["depth_us"] = double(sum.ns_depth) * 1e-3 * per_step;
    state.counters["response_us"] = double(sum.ns_response) * 1e-3 * per_step;
    state.counters["narrow_us"] = double(sum.ns_narrow) * 1e-3 * per_step;
}

void two_balls_together(benchmark::State& state) {
    static const std::vector<Scene> s{two_balls(true)};
    steps_from_start(state, s, 1, 1);
}
void two_balls_approaching(benchmark::State& state) {
    static const std::vector<Scene> s{two_balls(false)};
    steps_from_start(state, s, 1, 1);
}
// Eight such lines; the time and counters are a step's, the mean over the eight scenes.
void two_balls_together_random_lines(benchmark::State& state) {
    static const std::vector<Scene> s = two_balls_on_random_lines(8);
    steps_from_start(state, s, 1, 1);
}
void thousand_balls_2_threads(benchmark::State& state) {
    static const std::vector<Scene> s{thousand_balls()};
    steps_from_start(state, s, 2, 20);
}
BENCHMARK(two_balls_together)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(two_balls_approaching)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(two_balls_together_random_lines)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(thousand_balls_2_threads)->UseManualTime()->Unit(benchmark::kMicrosecond);

} // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
