// Google Benchmark micro-benchmark: rectangle selection in core (through, visible only, and the
// software depth map of visible only) on the editor bench's mesh and view size (a
// 1,000,000-vertex torus with a sample a vertex, root current; a 463 x 379 orthographic view).
#include "spt/recipe.hpp"
#include "spt/selection.hpp"
#include "mesh/shapes.hpp"
#include <benchmark/benchmark.h>

namespace {

using namespace spt;

const TriangleMesh& torus() {
    static const TriangleMesh m = make_torus(1.0, 0.35, 1000, 1000);
    return m;
}

// A front view fitting 3 units of height, depth scaled into the clip range.
ViewProjection front_view() {
    ViewProjection v;
    v.width = 463, v.height = 379;
    v.projection(0, 0) = 2.0f / 3.0f * 379.0f / 463.0f;
    v.projection(1, 1) = 2.0f / 3.0f;
    v.projection(2, 2) = -0.2f;
    return v;
}

void depth_map(benchmark::State& state, bool window) {
    const ViewProjection v = front_view();
    const PixelRect quarter{115, 95, 347, 284}; // a rectangle a quarter of the view
    size_t pixels = 0;
    for (auto _ : state) {
        const DepthMap d = window ? render_depth(torus(), v, quarter) : render_depth(torus(), v);
        benchmark::DoNotOptimize(d.depth.data());
        pixels = d.depth.size();
    }
    state.counters["pixels"] = double(pixels);
}

// A sample a vertex, one unsplit tree: the editor bench's document.
struct VertexSamples {
    SampleSet samples;
    SamplingTree tree{"default", 0};
};
const VertexSamples& vertex_samples() {
    static const VertexSamples v = [] {
        VertexSamples out;
        const TriangleMesh& m = torus();
        for (size_t i = 0; i < m.positions.size(); ++i)
            out.samples.add(m.positions[i].cast<float>(), m.normals[i].cast<float>(), uint32_t(i), 0.003f);
        out.tree = unsplit_tree("default", out.samples);
        return out;
    }();
    return v;
}

void selection(benchmark::State& state, bool visible) {
    const VertexSamples& v = vertex_samples();
    const RecipeStroke stroke{front_view(), PixelRect{115, 95, 347, 284}, SelectionMode::Replace, visible};
    size_t hits = 0;
    for (auto _ : state) {
        const std::vector<uint32_t> s = apply_stroke(v.samples, v.tree, root_id(), {}, stroke, &torus());
        benchmark::DoNotOptimize(s.data());
        hits = s.size();
    }
    state.counters["hits"] = double(hits);
}

BENCHMARK_CAPTURE(selection, through_a_quarter, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(selection, visible_only_a_quarter, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(depth_map, window_of_a_quarter, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(depth_map, whole_view, false)->Unit(benchmark::kMillisecond);

} // namespace
