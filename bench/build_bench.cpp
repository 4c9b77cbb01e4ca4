// Tree building after import, for meshes of 10k, 100k and 1M vertices (tori), on one core or
// `--threads N`. Prints a Markdown table; docs/benchmarks.md quotes it with this command.
#include "meshgen.hpp"
#include "spt/compact_tree.hpp"
#include "spt/convert.hpp"
#include "sampling/surface_samples.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

template <class F> double best_seconds(int reps, F&& f) {
    double best = 1e30;
    for (int i = 0; i < reps; ++i) {
        const auto t0 = Clock::now();
        f();
        best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
    }
    return best;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<int> sides = {100, 316, 1000}; // nu = nv: 10k, ~100k, 1M vertices
    int threads = 1; // sampling and building; `--threads N` last on the line
    if (argc > 2 && std::strcmp(argv[argc - 2], "--threads") == 0) threads = std::max(1, std::atoi(argv[argc - 1])), argc -= 2;
    if (argc > 1 && std::strcmp(argv[1], "--quick") == 0) sides = {100, 316};
    if (argc > 2 && std::strcmp(argv[1], "--sample-only") == 0) {
        // One run of the sample stage on a torus of SIDE x SIDE vertices: a target for
        // callgrind (--toggle-collect='spt::sample_vertices*' and the limiter's constructor).
        const int side = std::max(3, std::atoi(argv[2]));
        const spt::ImportedMesh m = spt::meshgen::prepare(spt::meshgen::torus(1.0, 0.35, side, side), "torus");
        const double t = best_seconds(1, [&] {
            const spt::RadiusLimiter limiter(m.mesh, spt::kDefaultProtrusion * m.mesh.diagonal());
            spt::sample_vertices(m.mesh, limiter);
        });
        std::printf("sample, %zu vertices: %.3f s\n", m.mesh.positions.size(), t);
        return 0;
    }
    std::printf("Sampling and building on %d thread%s.\n\n", threads, threads == 1 ? "" : "s");
    std::printf("| vertices | samples | strategy | sample (s) | build tree (s) | query layout (s) | "
                "layout B/sample | .spt B/sample | depth | save: validate + encode (s) |\n");
    std::printf("|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int side : sides) {
        const auto raw = spt::meshgen::torus(1.0, 0.35, side, side);
        const spt::ImportedMesh m = spt::meshgen::prepare(raw, "torus");
        for (auto strategy : {spt::SplitStrategy::Volume, spt::SplitStrategy::Median}) {
            spt::SampleSet samples;
            const double t_sample = best_seconds(3, [&] {
                const spt::RadiusLimiter limiter(m.mesh, spt::kDefaultProtrusion * m.mesh.diagonal());
                samples = spt::sample_vertices(m.mesh, limiter, {}, threads);
            });
            spt::BuildOptions opt;
            opt.strategy = strategy;
            opt.threads = threads;
            spt::SamplingTree tree("t", 0u);
            const double t_build = best_seconds(3, [&] { tree = spt::build_tree("t", samples, opt); });
            spt::CompactTree compact;
            const double t_layout = best_seconds(3, [&] { compact = spt::CompactTree(tree, samples); });
            spt::SptDocument doc;
            doc.samples = samples;
            doc.trees.push_back(tree);
            size_t file_bytes = 0;
            // What save_spt does before writing: the document checked, then encoded.
            const double t_save = best_seconds(3, [&] {
                if (!doc.validate().empty()) std::abort();
                file_bytes = spt::encode_spt(doc).size();
            });
            const double n = double(samples.size());
            std::printf("| %zu | %zu | %s | %.3f | %.3f | %.3f | %.1f | %.1f | %d | %.3f |\n", m.mesh.positions.size(),
                        samples.size(), strategy == spt::SplitStrategy::Volume ? "volume" : "median", t_sample,
                        t_build, t_layout, double(compact.memory_bytes()) / n, double(file_bytes) / n, tree.depth(),
                        t_save);
            std::fflush(stdout);
        }
    }
    return 0;
}
