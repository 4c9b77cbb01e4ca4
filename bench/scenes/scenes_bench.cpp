// spt-bench-scenes: broad phase and whole-step times for scenes of 100 to 10,000 objects
// (docs/benchmarks.md). Usage: spt-bench-scenes [--quick]
#include "spt/simulation.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <random>
#include <ctime>

namespace {

using namespace spt;
// CPU time of this thread: on a shared machine, wall time measures the neighbours too.
struct Clock {
    using duration = std::chrono::nanoseconds;
    using time_point = std::chrono::time_point<Clock, duration>;
    static time_point now() {
        timespec t;
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return time_point(duration(int64_t(t.tv_sec) * 1000000000 + t.tv_nsec));
    }
};

double median(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

// n moving spheres of about the pile's sizes (radius 0.4 to 0.61) at the pile's density (one a unit cube).
std::vector<BroadSphere> moving_spheres(size_t n, std::mt19937& rng) {
    const double side = std::cbrt(double(n));
    std::uniform_real_distribution<double> p(0, side), r(0.4, 0.61);
    std::vector<BroadSphere> s(n);
    for (BroadSphere& b : s) b.center = {p(rng), p(rng), p(rng)}, b.radius = r(rng);
    return s;
}

void broad_phase_table(int frames) {
    std::printf("| objects | candidate pairs | grid (ms) | all pairs (ms) |\n|---:|---:|---:|---:|\n");
    std::mt19937 rng(13);
    for (size_t n : {100, 1000, 10000}) {
        std::vector<BroadSphere> s = moving_spheres(n, rng);
        std::normal_distribution<double> step(0, 0.02); // 2 cm a step: 2 m/s at dt = 0.01
        BroadPhase bp;
        std::vector<double> ms, brute;
        size_t pairs = 0;
        for (int f = 0; f < frames; ++f) {
            for (BroadSphere& b : s) b.center += Eigen::Vector3d(step(rng), step(rng), step(rng));
            const auto t0 = Clock::now();
            pairs = bp.find(s).size();
            ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
            if (f < 5) {
                const auto t1 = Clock::now();
                all_overlapping_pairs(s);
                brute.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t1).count());
            }
        }
        std::printf("| %zu | %zu | %.3f | %.2f |\n", n, pairs, median(ms), median(brute));
    }
}

// The pile's models on a jittered lattice of n objects above a floor, as resources/scenes/pile.json.
Scene lattice(const Scene& pile, size_t n) {
    Scene s = pile;
    s.objects.resize(1); // the floor
    const int side = int(std::ceil(std::sqrt(double(n) / 10.0)));
    s.objects[0].pose.translation = {0, -0.5, 0};
    std::mt19937 rng(1000);
    std::uniform_real_distribution<double> j(-0.05, 0.05), v(-0.5, 0.5);
    for (size_t i = 0; i < n; ++i) {
        SceneObject o = pile.objects[i % 3 == 0 ? 1 : 2]; // grit, pebble, pebble as in the pile
        o.name = "o" + std::to_string(i);
        o.pose.translation = {double(i % side) - side / 2.0 + j(rng), double(i / (size_t(side) * side)) + 0.5,
                              double(i / side % side) - side / 2.0 + j(rng)};
        o.velocity = {v(rng), v(rng), v(rng)};
        s.objects.push_back(o);
    }
    return s;
}

void step_table(const Scene& pile, int steps) {
    std::printf("| objects | effects | steps | candidate pairs | colliding pairs | step (ms) |\n"
                "|---:|---|---:|---:|---:|---:|\n");
    for (size_t n : {100, 1000, 10000})
        for (const char* fx : {"contacts,depth,response", "motion,gravity,contacts,depth,response"}) {
            Simulation sim(lattice(pile, n), parse_effect_list(fx, "bench"));
            std::vector<double> ms;
            uint64_t cand = 0, coll = 0;
            for (int i = 0; i < steps; ++i) {
                const auto t0 = Clock::now();
                const StepResult& r = sim.step();
                ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
                cand += r.counters.candidate_pairs, coll += r.counters.colliding_pairs;
            }
            std::printf("| %zu | %s | 1-%d | %.0f | %.1f | %.2f |\n", n, fx, steps, double(cand) / steps,
                        double(coll) / steps, median(ms));
        }
}

// The bundled pile itself as it falls and heaps up: step time at a few moments, on one thread
// (CPU time of the thread) and on two (wall time: the step's own time when the two cores are
// free, so quote it with the load average), and the medians over the heap (steps 100-150).
void pile_table(const Scene& pile, int steps) {
    std::printf("| step | colliding pairs | broad (wall ms) | narrow (wall ms) | depth (wall ms) | response (wall ms) "
                "| step, 1 thread (CPU ms) | step, 2 threads (wall ms) |\n"
                "|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    Simulation one(pile, pile.effects, 1), two(pile, pile.effects, 2);
    std::vector<double> heap_one, heap_two;
    for (int i = 1; i <= steps; ++i) {
        const auto t0 = Clock::now();
        const StepResult& r = one.step();
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        const auto w0 = std::chrono::steady_clock::now();
        const uint64_t hash = two.step().state_hash;
        const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w0).count();
        if (hash != r.state_hash) std::fprintf(stderr, "step %d: one and two threads differ\n", i);
        if (i >= 100 && i <= 150) heap_one.push_back(ms), heap_two.push_back(wall);
        const StepCounters& c = r.counters;
        if (i == 1 || i % 50 == 0)
            std::printf("| %d | %llu | %.3f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", i,
                        (unsigned long long)c.colliding_pairs, c.ns_broad * 1e-6, c.ns_narrow * 1e-6,
                        c.ns_depth * 1e-6, c.ns_response * 1e-6, ms, wall);
    }
    if (!heap_one.empty())
        std::printf("\nHeap, median of steps 100-150: %.2f ms on one thread (CPU), %.2f ms on two threads (wall).\n",
                    median(heap_one), median(heap_two));
}

} // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const Scene pile = load_scene(std::string(SPT_SOURCE_DIR) + "/resources/scenes/pile.json");
    std::printf("## Broad phase, moving spheres (median of %d steps)\n\n", quick ? 20 : 100);
    broad_phase_table(quick ? 20 : 100);
    std::printf("\n## Whole step from a lattice of the pile's objects (median of steps 1-%d)\n\n", quick ? 5 : 20);
    step_table(pile, quick ? 5 : 20);
    std::printf("\n## resources/scenes/pile.json with its effects (motion,gravity,contacts,depth,response)\n\n");
    pile_table(pile, quick ? 50 : 300);
    return 0;
}
