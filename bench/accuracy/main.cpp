// accuracy_bench: what accuracy costs in time. Every accuracy option of the
// sampling-tree query against FCL, Bullet and brute force, on the same poses,
// in one process; writes docs/accuracy-vs-time.md and, per mesh, a PNG plot and the CSV of its points
// (`--replot` redraws the PNGs from those CSVs without measuring).
#include "peers.hpp"
#include "plot.hpp"
#include "plot_files.hpp"
#include "protocol.hpp"
#include "spt/convert.hpp"
#include "spt/query.hpp"
#include "spt/response.hpp"
#include "mesh/shapes.hpp"
#include "geometry/sphere_block.hpp"
#include "query/brute_force.hpp"
#include "spt/plot/headless_gui.hpp"
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace {

using namespace spt;
using bench::PointKind;
using Clock = std::chrono::steady_clock;

struct Config {
    QueryLevel level;
    BoundsMethod bounds;
    bool culling;
    double eps; // fraction of the diagonal; 0: vertices only
    uint32_t leaf;
    bool radius_eps; // sampling-sphere radius fixed to eps (bounds protrusion at sharp edges)
};

struct Row {
    Row(std::string n, PointKind k) : name(std::move(n)), kind(k) {}
    std::string name;
    PointKind kind;
    double agree_near = 0, agree_random = 0;
    double agree_off[3] = {0, 0, 0};
    int fn = 0, fp = 0, near_n = 0;
    std::vector<double> bt, paper_bt;
    double t_med = 0, t_p99 = 0, build_s = 0, bytes_per_sample = 0, mem_mb = 0;
    std::string note;
};

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))];
}

std::string fmt(double v, int prec) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", prec, v);
    return b;
}
std::string fmt_ns(double ns) {
    if (ns >= 1e6) return fmt(ns / 1e6, 2) + " ms";
    if (ns >= 1e3) return fmt(ns / 1e3, 2) + " µs";
    return fmt(ns, 0) + " ns";
}

// Times `query` on every random pose and scores agreement on both sets.
template <class Query>
void measure(Row& row, const bench::PoseSets& sets, Query&& query) {
    std::vector<double> times;
    times.reserve(sets.random.size());
    int agree = 0;
    for (size_t i = 0; i < sets.random.size(); ++i) {
        const auto t0 = Clock::now();
        const bool c = query(sets.random[i]);
        times.push_back(double(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count()));
        agree += c == sets.random_truth[i];
    }
    row.t_med = percentile(times, 0.5), row.t_p99 = percentile(times, 0.99);
    row.agree_random = 100.0 * agree / double(std::max<size_t>(1, sets.random.size()));
    int ok = 0, ok_off[3] = {0, 0, 0}, n_off[3] = {0, 0, 0};
    for (const auto& c : sets.near) {
        const bool got = query(c.pose);
        ok += got == c.truth, ok_off[c.offset] += got == c.truth, ++n_off[c.offset];
        row.fn += c.truth && !got, row.fp += !c.truth && got;
    }
    row.near_n = int(sets.near.size());
    row.agree_near = 100.0 * ok / double(std::max<size_t>(1, sets.near.size()));
    for (int o = 0; o < 3; ++o) row.agree_off[o] = 100.0 * ok_off[o] / double(std::max(1, n_off[o]));
}

struct Built {
    SptDocument doc;
    CollisionModel model;
    double seconds = 0;
};

std::string config_name(const Config& c, double diag) {
    std::string s = std::string(query_level_name(c.level)) + ", " + (c.bounds == BoundsMethod::Paper ? "paper" : "tight") +
                    ", cull " + (c.culling ? "on" : "off") + ", ";
    s += c.eps > 0 ? "ε " + fmt(c.eps * 100, 1) + "%" : std::string("vertices");
    if (c.radius_eps) s += " r=ε";
    return s + ", leaf " + std::to_string(c.leaf);
}

struct MeshResult {
    std::string name, file;
    size_t triangles = 0;
    double diag = 0;
    std::vector<Row> rows;
    Row* fcl = nullptr;
    bench::PoseSets sets;
    double truth_seconds = 0;
    bool plot_written = true;
};

MeshResult run_mesh(const std::string& name, const TriangleMesh& raw, int orientations, int directions, unsigned seed,
                    bool quick, const std::string& png_path) {
    MeshResult out;
    const TriangleMesh mesh = scale_to_unit_cube(raw);
    out.name = name, out.triangles = mesh.triangles.size(), out.diag = mesh.diagonal();
    const double diag = out.diag;
    std::cerr << name << ": " << mesh.triangles.size() << " triangles, diagonal " << diag << "\n";
    const bench::FclPeer fcl(mesh);
    const bench::BulletPeer bullet(mesh);
    auto t0 = Clock::now();
    out.sets = bench::make_pose_sets(fcl, diag, orientations, directions, seed);
    out.truth_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    const auto& sets = out.sets;
    std::cerr << "  poses: " << sets.random.size() << " random, " << sets.near.size() << " near contact ("
              << out.truth_seconds << " s of FCL ground truth)\n";

    Row fr{"FCL 0.7 (OBBRSS, boolean) — ground truth", PointKind::Fcl};
    measure(fr, sets, [&](const Pose& p) { return fcl.collide(p); });
    for (const auto& c : sets.near)
        if (c.truth) fr.bt.push_back(0);
    out.rows.push_back(fr);
    Row br{"Bullet 3.24 (btGImpactMeshShape)", PointKind::Bullet};
    measure(br, sets, [&](const Pose& p) { return bullet.collide(p); });
    out.rows.push_back(br);

    QueryScratch scratch;
    std::vector<Row> rows;
    const Built* default_model = nullptr;
    std::vector<std::unique_ptr<Built>> keep;
    for (BoundsMethod bounds : {BoundsMethod::Tight, BoundsMethod::Paper})
        for (auto [eps, radius_eps] : {std::pair{0.0, false}, {0.01, false}, {0.003, false}, {0.01, true}, {0.003, true}})
            for (uint32_t leaf : {4u, 8u, 16u}) {
                if (quick && (bounds != BoundsMethod::Tight || leaf != 8)) continue; // the rows the targets read
                auto b = std::make_unique<Built>();
                ConvertOptions co;
                co.build.leaf_size = leaf;
                co.build.bounds = bounds;
                if (eps > 0) co.tolerance = eps * diag;
                if (radius_eps) co.build.radius.fixed = float(eps * diag);
                const auto tb = Clock::now();
                b->doc = make_document(mesh, co);
                b->model = CollisionModel(b->doc, mesh);
                b->seconds = std::chrono::duration<double>(Clock::now() - tb).count();
                const CollisionModel& m = b->model;
                for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact})
                    for (bool cull : {false, true}) {
                        const Config cfg{level, bounds, cull, eps, leaf, radius_eps};
                        Row r{config_name(cfg, diag), level == QueryLevel::Bounds ? PointKind::Bounds
                                                      : level == QueryLevel::Spheres ? PointKind::Spheres
                                                                                     : PointKind::Exact};
                        QueryOptions o;
                        o.level = level, o.normal_culling = cull;
                        measure(r, sets, [&](const Pose& p) { return collide_relative(m, m, p, o, scratch).collide; });
                        for (const auto& c : sets.near) {
                            if (!c.truth || !collide_relative(m, m, c.pose, o, scratch).collide) continue;
                            const double ours = backtrack_relative(m, m, c.pose, c.motion, o, BacktrackRule::Exact, scratch).distance;
                            r.bt.push_back(std::abs(ours - c.truth_backtrack) / diag);
                            if (level == QueryLevel::Spheres) {
                                const double paper = backtrack_relative(m, m, c.pose, c.motion, o, BacktrackRule::Paper, scratch).distance;
                                r.paper_bt.push_back(std::abs(paper - c.truth_backtrack) / diag);
                            }
                        }
                        r.build_s = b->seconds;
                        r.bytes_per_sample = double(m.tree().memory_bytes()) / double(b->doc.samples.size());
                        r.mem_mb = double(level == QueryLevel::Exact ? m.memory_bytes() : m.tree().memory_bytes()) / 1e6;
                        r.note = std::to_string(b->doc.samples.size()) + " samples";
                        rows.push_back(std::move(r));
                    }
                if (bounds == BoundsMethod::Tight && eps == 0 && leaf == 8) default_model = b.get();
                std::cerr << "  built and measured bounds " << (bounds == BoundsMethod::Paper ? "paper" : "tight")
                          << " eps " << eps << (radius_eps ? " r=eps" : "") << " leaf " << leaf << ", "
                          << b->doc.samples.size() << " samples\n";
                keep.push_back(std::move(b));
            }
    // Brute force over all sphere pairs of the default model, on a spread subset of poses
    // (not with --quick: quadratic in the samples, hours on a million; the subset shrinks
    // with the model, see below).
    if (!quick) {
        const CollisionModel& m = default_model->model;
        QueryOptions o;
        bench::PoseSets sub;
        // At most 48 random and 60 near poses, fewer for a model whose n^2 sphere tests a pose
        // would take the run past about 2e10 tests (a two-sided model doubles n): 4 + 4 at least.
        const double n = double(m.tree().sphere_count());
        const double share = std::clamp(2e10 / (n * n) / 108.0, 4.0 / 48.0, 1.0);
        const size_t want_r = size_t(48 * share), want_n = size_t(std::max(4.0, 60 * share));
        const size_t stride_r = std::max<size_t>(1, sets.random.size() / std::max<size_t>(1, want_r));
        for (size_t i = 0; i < sets.random.size(); i += stride_r)
            sub.random.push_back(sets.random[i]), sub.random_truth.push_back(sets.random_truth[i]);
        const size_t stride_n = std::max<size_t>(1, sets.near.size() / want_n);
        for (size_t i = 0; i < sets.near.size(); i += stride_n) sub.near.push_back(sets.near[i]);
        Row bf{"brute force, all sphere pairs (default model)", PointKind::BruteForce};
        measure(bf, sub, [&](const Pose& p) { return collide_brute_force(m, m, p, o, scratch).collide; });
        bf.note = "on " + std::to_string(sub.random.size()) + " random and " + std::to_string(sub.near.size()) +
                  " near poses";
        bf.mem_mb = double(m.tree().memory_bytes()) / 1e6;
        out.rows.push_back(bf);
    }
    for (auto& r : rows) out.rows.push_back(std::move(r));
    bench::PlotData plot{name, {}};
    for (const auto& r : out.rows) plot.points.push_back({r.name, r.t_med, r.agree_near, r.kind});
    out.plot_written = bench::write_plot_files(png_path, plot);
    return out;
}

const Row* find_row(const MeshResult& m, const std::string& name) {
    for (const auto& r : m.rows)
        if (r.name == name) return &r;
    return nullptr;
}

std::string yes(bool ok) { return ok ? "**met**" : "**not met**"; }

void write_targets(std::ostream& md, const MeshResult& m) {
    const Row* fcl = &m.rows[0];
    const Row* def = find_row(m, "spheres, tight, cull off, vertices, leaf 8");
    const Row* e1 = find_row(m, "spheres, tight, cull off, ε 1.0%, leaf 8");
    const Row* e03 = find_row(m, "spheres, tight, cull off, ε 0.3%, leaf 8");
    const Row* ex = find_row(m, "exact, tight, cull off, vertices, leaf 8");
    const Row* r1 = find_row(m, "spheres, tight, cull off, ε 1.0% r=ε, leaf 8");
    const Row* r03 = find_row(m, "spheres, tight, cull off, ε 0.3% r=ε, leaf 8");
    md << "| target | measured | |\n|---|---|---|\n";
    md << "| `spheres` default agrees ≥ 99% at ±1% of the diagonal | " << fmt(def->agree_off[1], 2) << "% | "
       << yes(def->agree_off[1] >= 99) << " |\n";
    md << "| `spheres` with ε = 1% agrees ≥ 99% at ±1% | " << fmt(e1->agree_off[1], 2) << "% | " << yes(e1->agree_off[1] >= 99) << " |\n";
    md << "| `spheres` with ε = 0.3% agrees ≥ 99% at ±0.3% | " << fmt(e03->agree_off[0], 2) << "% | "
       << yes(e03->agree_off[0] >= 99) << " |\n";
    md << "| (radius = ε) `spheres` with ε = 1%, r = ε agrees ≥ 99% at ±1% | " << fmt(r1->agree_off[1], 2) << "% | "
       << yes(r1->agree_off[1] >= 99) << " |\n";
    md << "| (radius = ε) `spheres` with ε = 0.3%, r = ε agrees ≥ 99% at ±0.3% | " << fmt(r03->agree_off[0], 2) << "% | "
       << yes(r03->agree_off[0] >= 99) << " |\n";
    const double ratio = fcl->t_med / std::max(1.0, def->t_med);
    md << "| `spheres` default median time ≥ 10× lower than FCL's | " << fmt_ns(def->t_med) << " vs " << fmt_ns(fcl->t_med)
       << " (" << fmt(ratio, 1) << "×) | " << yes(ratio >= 10) << " |\n";
    const double bt_med = percentile(def->bt, 0.5), bt_max = percentile(def->bt, 1.0);
    md << "| `spheres` default backtrack within 2% of the diagonal of exact | median " << fmt(bt_med * 100, 2) << "%, max "
       << fmt(bt_max * 100, 2) << "% | " << yes(bt_max <= 0.02) << (bt_med <= 0.02 && bt_max > 0.02 ? " (median met)" : "")
       << " |\n";
    bool all100 = true;
    for (double a : ex->agree_off) all100 = all100 && a >= 100;
    md << "| `exact` agrees 100% at every offset | " << fmt(ex->agree_off[0], 2) << "% / " << fmt(ex->agree_off[1], 2)
       << "% / " << fmt(ex->agree_off[2], 2) << "% | " << yes(all100) << " |\n";
    md << "| `exact` no slower than FCL (median) | " << fmt_ns(ex->t_med) << " vs " << fmt_ns(fcl->t_med) << " | "
       << yes(ex->t_med <= fcl->t_med) << " |\n\n";
}

void write_table(std::ostream& md, const MeshResult& m) {
    md << "| configuration | agree near (%) | ±0.3% | ±1% | ±3% | FN | FP | random agree (%) | backtrack err med / max "
          "(% diag) | paper-rule err med / max | median time | p99 time | build (s) | layout B/sample | memory (MB) | note |\n";
    md << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : m.rows) {
        const bool peer = r.kind == PointKind::Fcl || r.kind == PointKind::Bullet || r.kind == PointKind::BruteForce;
        md << "| " << (peer ? "**" + r.name + "**" : r.name) << " | " << fmt(r.agree_near, 2) << " | "
           << fmt(r.agree_off[0], 1) << " | " << fmt(r.agree_off[1], 1) << " | " << fmt(r.agree_off[2], 1) << " | " << r.fn
           << " | " << r.fp << " | " << fmt(r.agree_random, 2) << " | ";
        if (!r.bt.empty() && r.kind != PointKind::Fcl)
            md << fmt(percentile(r.bt, 0.5) * 100, 2) << " / " << fmt(percentile(r.bt, 1.0) * 100, 2);
        md << " | ";
        if (!r.paper_bt.empty()) md << fmt(percentile(r.paper_bt, 0.5) * 100, 2) << " / " << fmt(percentile(r.paper_bt, 1.0) * 100, 2);
        md << " | " << fmt_ns(r.t_med) << " | " << fmt_ns(r.t_p99) << " | " << (r.build_s > 0 ? fmt(r.build_s, 2) : "")
           << " | " << (r.bytes_per_sample > 0 ? fmt(r.bytes_per_sample, 1) : "") << " | "
           << (r.mem_mb > 0 ? fmt(r.mem_mb, 2) : "") << " | " << r.note << " |\n";
    }
    md << "\n";
}

} // namespace

int main(int argc, char** argv) {
    std::string out = "docs/accuracy-vs-time.md", only;
    int orientations = 500, directions = 150;
    unsigned seed = 1;
    bool quick = false, replot_only = false;
    const char* usage =
        "usage: accuracy_bench [--out FILE.md] [--orientations N] [--directions N] [--seed S] "
        "[--mesh torus|bracket|wuson|engine] [--quick] [--replot]\n"
        "  --quick: tight bounds and leaf 8 only (the configurations the targets read), no brute force\n"
        "  --replot: measure nothing; redraw each PNG next to FILE.md (FILE-<mesh>.png) from the CSV beside it\n"
        "exit codes: 0 ok, 1 usage, 2 bad input (a plot CSV), 3 cannot write\n";
    auto whole = [&](const std::string& flag, const std::string& v, long long lo, long long hi) {
        char* end = nullptr;
        errno = 0;
        const long long n = std::strtoll(v.c_str(), &end, 10);
        if (v.empty() || *end != '\0' || errno != 0 || n < lo || n > hi) {
            std::cerr << flag << " needs a whole number from " << lo << " to " << hi << ", not '" << v << "'\n" << usage;
            std::exit(1);
        }
        return n;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::cerr << a << " needs a value\n" << usage;
                std::exit(1);
            }
            return argv[++i];
        };
        if (a == "--out") out = next();
        else if (a == "--orientations") orientations = int(whole(a, next(), 1, 1000000));
        else if (a == "--directions") directions = int(whole(a, next(), 1, 1000000));
        else if (a == "--seed") seed = unsigned(whole(a, next(), 0, 4294967295LL));
        else if (a == "--mesh") only = next();
        else if (a == "--quick") quick = true;
        else if (a == "--replot") replot_only = true;
        else {
            std::cerr << usage;
            return 1;
        }
    }
    namespace fs = std::filesystem;
    const fs::path out_path(out);
    const fs::path dir = out_path.parent_path().empty() ? fs::path(".") : out_path.parent_path();
    // The plots draw text, which needs a QGuiApplication even with no window (see headless_gui.hpp).
    const spt::plot::HeadlessGui gui;
    if (replot_only) return bench::replot(dir, out_path.stem().string(), only);
    std::error_code mkdir_error;
    fs::create_directories(dir, mkdir_error);
    if (mkdir_error) {
        std::cerr << "error: cannot create " << dir.string() << ": " << mkdir_error.message() << "\n";
        return 3;
    }
    std::vector<std::pair<std::string, TriangleMesh>> meshes;
    if (only.empty() || only == "torus") meshes.emplace_back("torus", make_torus(1.0, 0.35, 160, 72));
    if (only.empty() || only == "bracket") meshes.emplace_back("bracket", make_bracket());
    const std::string wuson = "/usr/share/assimp/models/PLY/Wuson.ply";
    if ((only.empty() || only == "wuson") && fs::exists(wuson)) meshes.emplace_back("wuson", import_mesh(wuson).mesh);
    // A real CAD assembly of 110k triangles, open, 77 parts: on request only (its models take minutes to build).
    const std::string engine = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    if (only == "engine" && fs::exists(engine)) meshes.emplace_back("engine", import_mesh(engine).mesh);
    if (meshes.empty()) {
        std::cerr << "no mesh named '" << only << "' (or its file is missing)\n";
        return 1;
    }

    std::vector<MeshResult> results;
    const auto t0 = Clock::now();
    for (const auto& [name, mesh] : meshes) {
        const std::string png = out_path.stem().string() + "-" + name + ".png";
        results.push_back(run_mesh(name, mesh, orientations, directions, seed, quick, (dir / png).string()));
        results.back().file = png;
    }
    const double total = std::chrono::duration<double>(Clock::now() - t0).count();

    std::ostringstream md;
    md << "# Accuracy vs time\n\n"
       << "Generated by `accuracy_bench";
    for (int i = 1; i < argc; ++i) md << " " << argv[i];
    md << "` (target `bench`: `cmake --build build --target bench`) in " << fmt(total, 0) << " s on "
       << std::thread::hardware_concurrency() << " hardware threads (shared), sphere kernel `" << sphere_block_variant()
       << "`. Do not edit by hand.\n\n"
       << "**Protocol.** Two copies of each mesh scaled into [-1, 1]³; A at the identity, B posed in A's frame. "
       << "(a) *random*: B's centre at distances 0.2, 0.4, …, 2.4 in a random direction, " << orientations
       << " seeded random orientations at each distance; this set times every query (one `any` query a pose, steady clock "
          "around the call) and gives *random agree*. (b) *near contact*: "
       << directions << " random approach directions and orientations; the exact first contact along the approach is found "
          "with FCL (steps of 0.5% of the diagonal, then bisection to 1e-7), then B is moved in and out by 0.3%, 1% and 3% of "
          "the diagonal (columns ±0.3%, ±1%, ±3%). Ground truth for *collide* is FCL's boolean mesh-mesh test on the same "
          "pose (surfaces intersect); for *backtrack*, FCL stepping (1% of the diagonal) and bisection along −motion. "
          "*FN*/*FP*: false negatives/positives on the near-contact set. Backtrack error is |ours − FCL| / diagonal over "
          "near-contact poses where both collide; *paper-rule* is the paper's \"move back by the deepest depth\". "
          "Memory: the query layout (`CompactTree`) for `bounds`/`spheres`, plus triangle data for `exact`. "
          "Brute force tests every sphere pair of the default model on a subset of poses (its answers equal the "
          "`spheres, tight, vertices, leaf 8` row by construction; absent from `--quick` runs).\n\n"
       << "**Plots.** Each mesh's PNG plots *agree near* against the median time on the random poses (log scale), "
          "with the Pareto front (configurations more accurate than every faster one); the points are in the CSV beside "
          "the PNG, and `accuracy_bench --replot` (target `replot`) redraws the PNGs from those CSVs without measuring.\n\n";
    for (const auto& m : results) {
        md << "## " << m.name << " (" << m.triangles << " triangles, diagonal " << fmt(m.diag, 3) << ")\n\n";
        md << "Poses: " << m.sets.random.size() << " random, " << m.sets.near.size() << " near contact.\n\n";
        md << "### Targets\n\n";
        write_targets(md, m);
        md << "![accuracy vs time, " << m.name << "](" << m.file << ")\n\n### All configurations\n\n";
        write_table(md, m);
    }
    std::ofstream f(out_path);
    f << md.str();
    f.close();
    if (!f) {
        std::cerr << "error: cannot write " << out << "\n";
        return 3;
    }
    std::cerr << "wrote " << out << "\n";
    for (const auto& m : results)
        if (!m.plot_written) return 3; // the tables are written; the plot that failed said why
    return 0;
}
