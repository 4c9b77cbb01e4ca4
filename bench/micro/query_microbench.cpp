// Google Benchmark micro-benchmarks: the tree traversal and the sphere-block test.
#include "spt/convert.hpp"
#include "spt/query.hpp"
#include "mesh/shapes.hpp"
#include "geometry/sphere_block.hpp"
#include <benchmark/benchmark.h>
#include <random>

namespace {

using namespace spt;

struct Fixture {
    TriangleMesh mesh = scale_to_unit_cube(make_torus(1.0, 0.35, 160, 72));
    SptDocument doc = make_document(mesh);
    CollisionModel model{doc, mesh};
    std::vector<Pose> poses;
    Fixture() {
        std::mt19937 rng(1);
        std::normal_distribution<double> n;
        for (int i = 0; i < 1024; ++i) {
            const Eigen::Vector3d u = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
            poses.push_back(Pose::from((0.2 + 2.2 * (i % 12) / 11.0) * u,
                                       Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized()));
        }
    }
};

const Fixture& fixture() {
    static Fixture f;
    return f;
}

void traversal(benchmark::State& state, QueryLevel level, QueryMode mode, bool cull) {
    const Fixture& f = fixture();
    QueryScratch s;
    QueryOptions o;
    o.level = level, o.mode = mode, o.normal_culling = cull;
    size_t i = 0;
    QueryCounters sum;
    for (auto _ : state) {
        const QueryResult r = collide_relative(f.model, f.model, f.poses[i++ & 1023], o, s);
        sum.node_pairs += r.counters.node_pairs;
        sum.sphere_tests += r.counters.sphere_tests;
        sum.triangle_tests += r.counters.triangle_tests;
        benchmark::DoNotOptimize(r.collide);
    }
    auto per_query = [](uint64_t v) { return benchmark::Counter(double(v), benchmark::Counter::kAvgIterations); };
    state.counters["node_pairs"] = per_query(sum.node_pairs);
    state.counters["sphere_tests"] = per_query(sum.sphere_tests);
    state.counters["triangle_tests"] = per_query(sum.triangle_tests);
}
BENCHMARK_CAPTURE(traversal, spheres_any, QueryLevel::Spheres, QueryMode::Any, false);
BENCHMARK_CAPTURE(traversal, spheres_any_culling, QueryLevel::Spheres, QueryMode::Any, true);
BENCHMARK_CAPTURE(traversal, spheres_deepest, QueryLevel::Spheres, QueryMode::Deepest, false);
BENCHMARK_CAPTURE(traversal, bounds_any, QueryLevel::Bounds, QueryMode::Any, false);
BENCHMARK_CAPTURE(traversal, exact_any, QueryLevel::Exact, QueryMode::Any, false);

// One leaf pair: 8 spheres of A against 8 of B (64 sphere tests).
void sphere_block(benchmark::State& state) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> u(-1, 1);
    alignas(32) float a[3][16], b[3][16], out[8 * 8];
    for (auto& col : a)
        for (float& v : col) v = u(rng);
    for (auto& col : b)
        for (float& v : col) v = u(rng);
    for (auto _ : state) {
        benchmark::DoNotOptimize(sphere_block_d2(a[0], a[1], a[2], 8, b[0], b[1], b[2], 8, out));
        benchmark::ClobberMemory();
    }
    state.counters["sphere_tests"] = benchmark::Counter(64, benchmark::Counter::kIsIterationInvariantRate);
    state.SetLabel(sphere_block_variant());
}
BENCHMARK(sphere_block);

} // namespace
