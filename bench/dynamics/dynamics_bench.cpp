// dynamics_bench: effect dynamics (spt's sampling-sphere contact manifolds in Bullet's world and
// solver) against the same scene as a plain Bullet world with GImpact (gimpact_world.hpp), issue
// 39: step time of the 1,000-object pile in interleaved rounds, and the behaviour targets of the
// small scenes side by side. Figures and command: docs/scenes.md, "Dynamics against Bullet's GImpact".
// Opt-in: built with the benchmarks, never run by ctest. Markdown on stdout, progress on stderr.
#include "exit_code.hpp"
#include "gimpact_world.hpp"
#include "spt/error.hpp"
#include "spt/simulation.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace bench {
namespace {

using spt::Scene;

// spt's world, read through the same interface as Bullet's.
class SptEngine final : public Engine {
public:
    SptEngine(const Scene& s, int threads) : sim_(s, s.effects, threads) {}
    void step() override { last_ = &sim_.step(); }
    spt::Pose pose(size_t i) const override { return sim_.poses()[i]; }
    Eigen::Vector3d velocity(size_t i) const override { return sim_.object_velocity(i).first; }
    double energy() const override { return sim_.mechanical_energy(); }
    size_t touching() const override { return last_ ? last_->counters.colliding_pairs : 0; }
    int64_t collision_ns() const override { return last_ ? last_->counters.ns_broad + last_->counters.ns_narrow : 0; }

private:
    spt::Simulation sim_;
    const spt::StepResult* last_ = nullptr;
};

// The engines compared, in the order they take turns.
struct Contender {
    std::string name;
    int threads = 0;        // 0: Bullet with GImpact
    GImpactOptions gimpact; // its margin and solver
};

std::unique_ptr<Engine> start(const Contender& c, const Scene& s, const std::vector<std::shared_ptr<const spt::TriangleMesh>>& meshes) {
    if (c.threads == 0) return std::make_unique<GImpactWorld>(s, meshes, c.gimpact);
    return std::make_unique<SptEngine>(s, c.threads);
}

// One engine's run of a scene: per step, wall ms of the whole step and of collision detection,
// pairs touching after it; and the largest rise of mechanical energy from one step to the next.
struct Trace {
    std::vector<double> step_ms, collide_ms, touching;
    double energy = 0, worst_rise = 0;
};

void timed_step(Engine& e, Trace& t) {
    if (t.step_ms.empty()) t.energy = e.energy();
    const auto t0 = std::chrono::steady_clock::now();
    e.step();
    t.step_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    t.collide_ms.push_back(double(e.collision_ns()) / 1e6);
    t.touching.push_back(double(e.touching()));
    const double now = e.energy(); // outside the timing
    t.worst_rise = std::max(t.worst_rise, (now - t.energy) / std::abs(t.energy));
    t.energy = now;
}

// The q-quantile of v (nearest rank; 0.5 is the median of an odd count).
double quantile(std::vector<double> v, double q) {
    if (v.empty()) return std::nan("");
    std::sort(v.begin(), v.end());
    return v[size_t(std::max(0.0, std::ceil(q * double(v.size())) - 1))];
}

// Steps first..last (1-based, inclusive) of each of `runs`, pooled.
std::vector<double> window(const std::vector<std::vector<double>>& runs, int first, int last) {
    std::vector<double> out;
    for (const auto& r : runs)
        for (int s = first; s <= last && s <= int(r.size()); ++s) out.push_back(r[size_t(s - 1)]);
    return out;
}

std::string num(double v, int digits) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}

// ---------------------------------------------------------------------------------------------
// Behaviour: the targets, measured as tests/dynamics/dynamics_scenes_test.cpp measures them.

using Measure = std::function<std::vector<std::string>(const Scene&, Engine&, Trace&)>;

struct SmallScene {
    const char* file;
    std::vector<std::pair<const char*, const char*>> rows; // what is measured, its target
    Measure measure;
};

// The first rebound's apex over the floor's top (y = 0), as a fraction of e^2 times the drop.
std::vector<std::string> bounce(const Scene& s, Engine& e, Trace& t) {
    const double radius = 0.5, e2 = s.dynamics.restitution * s.dynamics.restitution;
    const double drop = s.objects[1].pose.translation.y() - radius;
    bool bounced = false, past = false;
    double apex = 0;
    for (int i = 0; i < s.steps; ++i) {
        timed_step(e, t);
        const double vy = e.velocity(1).y(), height = e.pose(1).translation.y() - radius;
        if (past) continue;
        bounced = bounced || vy > 0;
        if (bounced && vy > 0) apex = std::max(apex, height);
        past = bounced && vy < 0 && apex > 0;
    }
    return {num(apex / (e2 * drop), 3) + " (apex " + num(apex, 3) + " of " + num(e2 * drop, 3) + ")"};
}

// Over 2 s: how far the cube with friction 0.6 moved (% of its 0.5 side), and the other's
// acceleration down the slope between 0.5 and 2 s against g (sin 20 - 0.2 cos 20).
std::vector<std::string> slope(const Scene& s, Engine& e, Trace& t) {
    const double theta = 20 * M_PI / 180, size = 0.5;
    const Eigen::Vector3d down(-std::cos(theta), -std::sin(theta), 0);
    const Eigen::Vector3d held0 = e.pose(1).translation;
    double v_half = 0;
    for (int i = 1; i <= 200; ++i) {
        timed_step(e, t);
        if (i == 50) v_half = e.velocity(2).dot(down);
    }
    const double a = (e.velocity(2).dot(down) - v_half) / 1.5;
    const double expected = -s.gravity.y() * (std::sin(theta) - s.objects[2].friction * std::cos(theta));
    return {num(100 * (e.pose(1).translation - held0).norm() / size, 2) + "%",
            num(a / expected, 3) + " (" + num(a, 3) + " of " + num(expected, 3) + " units/s²)"};
}

// After 5 s: how far the top of the five unit cubes moved (% of its side) and turned.
std::vector<std::string> stack(const Scene&, Engine& e, Trace& t) {
    const spt::Pose top0 = e.pose(5);
    for (int i = 0; i < 500; ++i) timed_step(e, t);
    const spt::Pose top = e.pose(5);
    return {num(100 * (top.translation - top0.translation).norm(), 2) + "%, turned " +
            num(top.rotation.angularDistance(top0.rotation) * 180 / M_PI, 2) + "°"};
}

// After 3 s: balls outside the box's inside (1.5 each side of the centre) or below its floor.
std::vector<std::string> balls(const Scene& s, Engine& e, Trace& t) {
    for (int i = 0; i < 300; ++i) timed_step(e, t);
    const double inside = 1.5, radius = 0.1;
    int out = 0, n = 0;
    for (size_t i = 0; i < s.objects.size(); ++i) {
        if (s.objects[i].name.rfind("ball", 0) != 0) continue;
        ++n;
        const Eigen::Vector3d p = e.pose(i).translation;
        out += std::abs(p.x()) >= inside - radius + 0.01 || std::abs(p.z()) >= inside - radius + 0.01 || p.y() <= radius - 0.01;
    }
    return {std::to_string(out) + " of " + std::to_string(n)};
}

// ---------------------------------------------------------------------------------------------

struct Options {
    std::string scenes = SPT_SOURCE_DIR "/resources/scenes";
    int rounds = 5, steps = 150, heap_first = 100, heap_last = 150, small_rounds = 3, threads = 2;
    bool pile = true, small = true;
    GImpactOptions gimpact;
};

std::string host_note() {
    std::ifstream cpu("/proc/cpuinfo"), load("/proc/loadavg");
    std::string line, model = "unknown CPU", l1, l5, l15;
    while (std::getline(cpu, line))
        if (line.rfind("model name", 0) == 0) { model = line.substr(line.find(':') + 2); break; }
    load >> l1 >> l5 >> l15;
    char when[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    return std::string(when) + ", " + model + ", load average " + l1 + " " + l5 + " " + l15;
}

// Each round runs every contender once, the first one rotating from round to round.
template <class Run>
void rounds(const std::vector<Contender>& who, int n, const Run& run) {
    for (int r = 0; r < n; ++r)
        for (size_t k = 0; k < who.size(); ++k) run(r, (size_t(r) + k) % who.size());
}

void pile(const Options& o, const std::vector<Contender>& who) {
    const Scene s = spt::load_scene(o.scenes + "/pile_dynamics.json");
    const auto meshes = object_meshes(s);
    std::vector<std::vector<std::vector<double>>> step(who.size()), collide(who.size()), touching(who.size());
    std::vector<std::vector<int>> sunk(who.size());
    rounds(who, o.rounds, [&](int r, size_t k) {
        const auto t0 = std::chrono::steady_clock::now();
        auto e = start(who[k], s, meshes);
        Trace t;
        for (int i = 0; i < o.steps; ++i) timed_step(*e, t);
        int below = 0; // pebbles whose centre is below the floor's top (y = 0): fallen through
        for (size_t i = 1; i < s.objects.size(); ++i) below += e->pose(i).translation.y() < 0;
        step[k].push_back(t.step_ms), collide[k].push_back(t.collide_ms), touching[k].push_back(t.touching);
        sunk[k].push_back(below);
        std::fprintf(stderr, "pile round %d: %s, %d steps in %.1f s\n", r + 1, who[k].name.c_str(), o.steps,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    });
    const int a = o.heap_first, b = std::min(o.heap_last, o.steps);
    std::cout << "\n**The pile** (`pile_dynamics.json`, " << s.objects.size() - 1 << " pebbles): " << o.rounds
              << " rounds of " << o.steps << " steps, the heap's steps " << a << "-" << b << " pooled over the rounds.\n\n"
              << "| engine | step, median ms | step, p90 ms | round medians ms | collision detection, median ms "
                 "| pairs touching, median | pebbles below the floor's top after step " << o.steps << " |\n"
              << "|---|---:|---:|---|---:|---:|---|\n";
    std::vector<double> medians;
    for (size_t k = 0; k < who.size(); ++k) {
        std::string per_round;
        for (const auto& r : step[k]) per_round += (per_round.empty() ? "" : ", ") + num(quantile(window({r}, a, b), 0.5), 1);
        std::string below;
        for (int n : sunk[k]) below += (below.empty() ? "" : ", ") + std::to_string(n);
        medians.push_back(quantile(window(step[k], a, b), 0.5));
        std::cout << "| " << who[k].name << " | " << num(medians.back(), 2) << " | " << num(quantile(window(step[k], a, b), 0.9), 2)
                  << " | " << per_round << " | " << num(quantile(window(collide[k], a, b), 0.5), 2) << " | "
                  << num(quantile(window(touching[k], a, b), 0.5), 0) << " | " << below << " |\n";
    }
    std::cout << "\nMedian step of GImpact over spt's:";
    for (size_t g = 0; g < who.size(); ++g)
        for (size_t k = 0; k < who.size(); ++k)
            if (who[g].threads == 0 && who[k].threads > 0)
                std::cout << " " << who[g].name << " / " << who[k].name << " " << num(medians[g] / medians[k], 1) << "×;";
    std::cout << "\n";
}

void small(const Options& o, const std::vector<Contender>& who) {
    const std::vector<SmallScene> scenes = {
        {"bounce.json", {{"ball, e = 0.8: first rebound apex / e²h", "0.9-1.1"}}, bounce},
        {"slope.json", {{"cube on 20°, μ 0.6: moved in 2 s, % of its side", "< 1%"},
                        {"cube on 20°, μ 0.2: acceleration / g(sin θ − μ cos θ)", "0.9-1.1"}}, slope},
        {"stack.json", {{"5 unit cubes: top box after 5 s, moved % of its side", "< 2%"}}, stack},
        {"balls_in_box.json", {{"300 balls after 3 s: outside the box or below its floor", "0"}}, balls},
    };
    std::ostringstream behaviour, timing;
    behaviour << "\n**Behaviour** (the tests' measures, `tests/dynamics/dynamics_scenes_test.cpp`; largest rise of kinetic + "
                 "potential energy from one step to the next in brackets, target ≤ 1% with restitution 0):\n\n| scene | measure | target |";
    timing << "\n**Step times of the small scenes** (mean over every step of " << o.small_rounds << " interleaved rounds: bodies "
              "asleep cost next to nothing, so a median would show the sleep; pairs touching, median):\n\n"
           << "| scene | objects |";
    for (const Contender& c : who) behaviour << " " << c.name << " |", timing << " " << c.name << ": ms a step (pairs touching) |";
    behaviour << "\n|---|---|---|", timing << "\n|---|---:|";
    for (size_t k = 0; k < who.size(); ++k) behaviour << "---|", timing << "---:|";
    behaviour << "\n", timing << "\n";
    for (const SmallScene& sc : scenes) {
        const Scene s = spt::load_scene(o.scenes + "/" + sc.file);
        const auto meshes = object_meshes(s);
        std::vector<std::vector<std::string>> got(who.size());
        std::vector<std::vector<double>> ms(who.size()), pairs(who.size());
        std::vector<double> rise(who.size());
        rounds(who, o.small_rounds, [&](int r, size_t k) {
            auto e = start(who[k], s, meshes);
            Trace t;
            const std::vector<std::string> values = sc.measure(s, *e, t);
            if (r == 0) got[k] = values, rise[k] = t.worst_rise;
            else if (values != got[k]) std::fprintf(stderr, "%s: %s measured differently in round %d\n", sc.file, who[k].name.c_str(), r + 1);
            ms[k].insert(ms[k].end(), t.step_ms.begin(), t.step_ms.end());
            pairs[k].insert(pairs[k].end(), t.touching.begin(), t.touching.end());
        });
        std::fprintf(stderr, "%s measured\n", sc.file);
        for (size_t row = 0; row < sc.rows.size(); ++row) {
            behaviour << "| `" << sc.file << "` | " << sc.rows[row].first << " | " << sc.rows[row].second << " |";
            for (size_t k = 0; k < who.size(); ++k)
                behaviour << " " << got[k][row] << (row + 1 == sc.rows.size() ? " [" + num(100 * rise[k], 2) + "%]" : "") << " |";
            behaviour << "\n";
        }
        timing << "| `" << sc.file << "` | " << s.objects.size() << " |";
        for (size_t k = 0; k < who.size(); ++k)
            timing << " " << num(std::accumulate(ms[k].begin(), ms[k].end(), 0.0) / double(ms[k].size()), 3) << " ("
                   << num(quantile(pairs[k], 0.5), 0) << ") |";
        timing << "\n";
    }
    std::cout << behaviour.str() << timing.str();
}

int usage() {
    std::fprintf(stderr, "usage: dynamics_bench [--only pile|small] [--rounds R] [--steps N] [--heap FIRST:LAST] [--small-rounds R]\n"
                         "                      [--threads N] [--scenes DIR] [--margin M] [--bullet-solver on|off]\n"
                         "  --margin: GImpact's triangle margin (default Bullet's, 0.01); --bullet-solver on: Bullet's default\n"
                         "  solver settings for the GImpact world instead of spt's (iterations stay the scene's)\n");
    return 1;
}

} // namespace
} // namespace bench

int main(int argc, char** argv) {
    bench::Options o;
    std::string command = "build/bench/dynamics_bench";
    for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) return bench::usage();
        const std::string v = argv[++i];
        char* end = nullptr;
        const long n = std::strtol(v.c_str(), &end, 10);
        const bool whole = *end == 0 && n >= 1 && n <= 100000;
        if (a == "--only" && (v == "pile" || v == "small")) o.pile = v == "pile", o.small = v == "small";
        else if (a == "--rounds" && whole) o.rounds = int(n);
        else if (a == "--steps" && whole) o.steps = int(n);
        else if (a == "--small-rounds" && whole) o.small_rounds = int(n);
        else if (a == "--threads" && whole) o.threads = int(n);
        else if (a == "--scenes") o.scenes = v;
        else if (a == "--margin" && (o.gimpact.margin = std::strtod(v.c_str(), &end)) >= 0 && *end == 0) {
        } else if (a == "--bullet-solver" && (v == "on" || v == "off")) o.gimpact.bullet_solver = v == "on";
        else if (a == "--heap" && std::sscanf(v.c_str(), "%d:%d", &o.heap_first, &o.heap_last) == 2 && o.heap_first >= 1 &&
                 o.heap_first <= o.heap_last) {
        } else return bench::usage();
    }
    std::vector<bench::Contender> who = {{"spt, " + std::to_string(o.threads) + " threads", o.threads, {}},
                                               {"spt, 1 thread", 1, {}},
                                               {"GImpact, floor BVH, 1 thread", 0, o.gimpact},
                                               {"GImpact, floor GImpact, 1 thread", 0, o.gimpact}};
    who[3].gimpact.static_gimpact = true;
    try {
        std::cout << "`" << command << "`: started " << bench::host_note() << ".\n";
        if (o.pile) bench::pile(o, who);
        if (o.small) bench::small(o, {who[0], who[2], who[3]});
        std::cout << "\nFinished " << bench::host_note() << ".\n";
    } catch (const spt::Error& e) {
        std::cerr << e.what() << "\n";
        return spt::cli::exit_code(e.kind());
    }
    return 0;
}
