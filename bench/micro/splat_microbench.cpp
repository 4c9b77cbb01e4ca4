// Google Benchmark micro-benchmark: the CPU sphere splat (render/src/sphere_splat.hpp) of one
// editor view (463 x 379) of the editor bench's redraw mesh: a torus of 50,000 vertices with a
// sphere a vertex, each tangent inside the surface at its vertex with a radius of 0.6 times the
// spacing of the vertices (2 to 4 pixels across), framed as the editor frames it.
#include "sphere_splat.hpp"
#include "mesh/shapes.hpp"
#include "spt/render/camera.hpp"
#include <benchmark/benchmark.h>
#include <thread>

namespace {

using namespace spt;
using namespace spt::render;

const std::vector<detail::SplatSphere>& spheres() {
    static const std::vector<detail::SplatSphere> s = [] {
        const TriangleMesh m = make_torus(1.0, 0.3, 250, 200);
        const float r = 0.6f * float(2 * 3.14159265 * 0.7 / 250);
        std::vector<detail::SplatSphere> out;
        for (size_t i = 0; i < m.positions.size(); ++i) {
            const Eigen::Vector3d& p = m.positions[i];
            // Inward normal of a torus about Y at p: towards the tube's centre circle.
            const Eigen::Vector3d ring = Eigen::Vector3d(p.x(), 0, p.z()).normalized();
            const Eigen::Vector3d inward = (ring - p).normalized();
            const Eigen::Vector3f c = (p + double(r) * inward).cast<float>();
            out.push_back({{c.x(), c.y(), c.z()}, r, {200, 120, 80, 255}});
        }
        return out;
    }();
    return s;
}

void splat(benchmark::State& state, View view) {
    const int threads = state.range(0) == 0 ? int(std::max(1u, std::thread::hardware_concurrency())) : int(state.range(0));
    Bounds b;
    for (const detail::SplatSphere& s : spheres()) b.add_sphere({s.center[0], s.center[1], s.center[2]}, s.radius);
    const Camera cam = fit_camera(view, b);
    const int w = 463, h = 379;
    detail::SphereSplat splat;
    size_t covered = 0;
    for (auto _ : state) {
        splat.begin(w, h, cam.projection_matrix(float(w) / float(h)), !cam.perspective());
        detail::SplatItem item;
        item.spheres = spheres().data();
        item.count = uint32_t(spheres().size());
        item.model_view = cam.view_matrix();
        splat.add(item);
        splat.run(threads);
        benchmark::DoNotOptimize(splat.depth().data());
    }
    for (float d : splat.depth()) covered += d <= 1;
    state.counters["spheres"] = double(spheres().size());
    state.counters["pixels_covered"] = double(covered);
    state.counters["threads"] = threads;
}

} // namespace

// Argument: threads (0: the machine's cores).
BENCHMARK_CAPTURE(splat, front, View::Front)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(splat, camera, View::Camera)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
