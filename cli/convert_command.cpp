// spt convert IN... [-o OUT.spt | --out-dir DIR] [options]
#include "exit_code.hpp"
#include "commands.hpp"
#include "number_checks.hpp"
#include "process_pool.hpp"
#include "spt/animation.hpp"
#include "spt/convert.hpp"
#include "spt/deforming_model.hpp"
#include "spt/motion_tree.hpp"
#include "spt/recipe.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>
#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

namespace spt::cli {
namespace {

namespace fs = std::filesystem;

struct ConvertArgs {
    std::vector<std::string> inputs;
    std::string output, out_dir, bounds = "tight", strategy = "volume", tree_name = "default", recipe;
    std::string motion, object; // --motion SCENE.json --object NAME: a tree built for that motion
    int motion_steps = 0;
    uint32_t leaf_size = 8;
    double radius = 0, radius_scale = 1.0, tolerance = 0, timeout = 600;
    double protrusion = 0; // --protrusion, model units (0: the default)
    double clip_step = 0;  // --clip-poses, seconds (0: radii limited at the bind pose alone)
    int jobs = 0, threads = 0; // threads: per file; 0 until run_convert settles it
    bool force = false, quiet = false, append = false, vertices_only = false, times = false;
};

std::string fmt(double v, int prec = 2) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(prec) << v;
    return s.str();
}

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Peak resident memory of this process so far; a worker converts one file, so it is that file's.
long peak_mib() {
    rusage u{};
    ::getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024;
}

// The trees of the recipe file over the new samples, with a line on each; `animated` (null
// unless some split was made at a clip's pose) poses the samples as the splits were made.
void replay_recipe_file(SptDocument& doc, const TriangleMesh& mesh, const BuildOptions& build, const SptDocument& recipes,
                        const std::string& recipe, const std::string& in, std::shared_ptr<const AnimatedMesh> animated) {
    const std::string folder = fs::path(recipe).parent_path().string();
    for (const TreeReplay& r : replay_trees(doc, mesh, recipes, build, std::move(animated), folder)) {
        if (r.motion_builds)
            std::cerr << "  recipe: tree '" << r.tree << "': " << r.motion_builds << " build"
                      << (r.motion_builds == 1 ? "" : "s") << " from motion redone\n";
        if (r.built_automatically) {
            std::cerr << "  recipe: tree '" << r.tree << "' of " << recipe << " has no recipe; built automatically\n";
            continue;
        }
        std::cerr << "  recipe: tree '" << r.tree << "': " << r.report.replayed << " of " << r.steps
                  << " splits replayed on " << in << "\n";
        for (const std::string& why : r.report.skipped) std::cerr << "  recipe: not replayed: " << why << "\n";
    }
}

// An animated mesh's clips: how far each stretches the surface and how deep the gaps between the
// new document's spheres get across it (docs/deforming.md, "Stretch").
void report_clips(const std::shared_ptr<const AnimatedMesh>& mesh, const SptDocument& doc, const std::string& tree,
                  int threads) {
    if (!mesh || mesh->clips.empty()) return;
    const DeformingModel model(doc, mesh, doc.tree(tree) ? tree : std::string(), false);
    for (const Clip& clip : mesh->clips) {
        const ClipStretch st = measure_stretch(*mesh, clip);
        const ClipCoverage cov = model.measure_coverage(clip, 30, threads);
        char line[512];
        std::snprintf(line, sizeof line,
                      "  clip '%s' (%.3g s): stretch up to %.3g at %.3g s%s%s%s; largest coverage gap %.3g (bind pose "
                      "%.3g), a gap grows by up to %.3g at %.3g s near (%.4g, %.4g, %.4g) (%d poses)\n",
                      clip.name.c_str(), clip.duration, st.largest, st.time, st.joint.empty() ? "" : " (joint '",
                      st.joint.c_str(), st.joint.empty() ? "" : "')", cov.largest_gap, cov.bind_gap, cov.largest_growth,
                      cov.growth_time, cov.growth_where.x(), cov.growth_where.y(), cov.growth_where.z(), cov.poses);
        std::cerr << line;
    }
}

// Converts one file; runs in a worker process. Prints one summary line and the report.
int convert_one(const std::string& in, const std::string& out, const ConvertArgs& a) {
    const auto t0 = std::chrono::steady_clock::now();
    // The worker converts one file and exits. Where the programs' heap is glibc's
    // (SPT_ALLOCATOR=system; mimalloc and jemalloc ignore this), it maps each large array afresh and
    // unmaps it when freed, so every array costs a page fault a page; kept on the heap, a freed
    // array's pages serve the next ones (at 1M vertices about 0.3 s less system time, for 20 MB
    // more peak memory).
    ::mallopt(M_MMAP_THRESHOLD, 1 << 30);
    ::mallopt(M_TRIM_THRESHOLD, 1 << 30);
    ImportOptions import_options;
    import_options.threads = a.threads;
    // A format that may hold clips is read with them, once: the clips are reported, and a recipe
    // whose splits were made at a clip's pose replays at that pose.
    std::optional<SptDocument> recipes;
    if (!a.recipe.empty()) recipes = load_spt(a.recipe);
    std::shared_ptr<const AnimatedMesh> animated;
    if (may_hold_animation(in) || (recipes && recipe_has_poses(*recipes)))
        animated = std::make_shared<AnimatedMesh>(import_animated_mesh(in, import_options));
    const ImportedMesh m = animated ? animated->imported : import_mesh(in, import_options);
    const double import_secs = seconds_since(t0);
    ConvertOptions opt;
    opt.tree_name = a.tree_name;
    opt.build.leaf_size = a.leaf_size;
    opt.build.strategy = a.strategy == "median" ? SplitStrategy::Median : SplitStrategy::Volume;
    opt.build.bounds = a.bounds == "paper" ? BoundsMethod::Paper : BoundsMethod::Tight;
    opt.build.radius.fixed = float(a.radius);
    opt.build.radius.scale = float(a.radius_scale);
    if (a.tolerance > 0) opt.tolerance = a.tolerance;
    if (a.protrusion > 0) opt.protrusion = a.protrusion;
    std::ostringstream clip_note; // printed with the report, below the summary line
    if (a.clip_step > 0) {
        if (animated && !animated->clips.empty()) {
            opt.poses = clip_poses(*animated, a.clip_step);
            clip_note << "  clip poses: radii limited at " << opt.poses.size() << " pose" << (opt.poses.size() == 1 ? "" : "s")
                      << " of " << animated->clips.size()
                      << " clip" << (animated->clips.size() == 1 ? "" : "s") << " as well as the bind pose\n";
        } else {
            clip_note << "  note: " << in << " has no clips; --clip-poses limits radii at the bind pose alone\n";
        }
    } else if (animated && !animated->clips.empty() && !a.append) {
        clip_note << "  note: radii limited at the bind pose; a clip that squeezes or bends a part can make a sphere "
                     "poke out by more than the allowance there (--clip-poses 0.0333 limits them along the clips too)\n";
    }
    opt.threads = a.threads;
    opt.build.threads = a.threads; // trees built here too (--append, trees of a recipe without one)
    opt.auto_tolerance = !a.vertices_only;
    ConvertStats st;
    SptDocument doc;
    if (a.append) {
        // Another tree over the samples already in the file (the paper keeps one per motion).
        doc = load_spt(out);
        append_tree(doc, m.mesh, a.tree_name, opt.build, a.force, out, &st);
    } else {
        doc = make_document(m.mesh, opt, &st);
    }
    if (recipes) replay_recipe_file(doc, m.mesh, opt.build, *recipes, a.recipe, in, animated);
    if (!a.motion.empty()) {
        // The tree is built for the scene's motion of the object; the file records the scene relative
        // to its own folder, so that --recipe finds it again.
        std::shared_ptr<const AnimatedMesh> with_mesh = animated;
        if (!with_mesh) {
            auto plain = std::make_shared<AnimatedMesh>();
            plain->imported = m;
            with_mesh = std::move(plain);
        }
        const fs::path folder = fs::absolute(fs::path(out)).parent_path();
        const std::string recorded = fs::relative(fs::absolute(a.motion), folder).generic_string();
        MotionBuildOptions mb;
        mb.build = opt.build;
        add_motion_tree(doc, with_mesh, a.motion, recorded.empty() ? a.motion : recorded, a.object, a.tree_name, mb,
                        a.motion_steps, !a.append || a.force);
    }
    report_clips(animated, doc, a.tree_name, a.threads);
    const auto t_save = std::chrono::steady_clock::now();
    save_spt(doc, out);
    const double save_secs = seconds_since(t_save);
    const SamplingTree& t = doc.trees.back();
    const double secs = seconds_since(t0);
    const auto& r = m.report;
    std::cerr << in << " -> " << out << ": " << r.vertices << " vertices, " << r.faces << " faces; " << doc.samples.size()
              << " samples (" << st.vertex_samples << " vertex, " << st.face_samples << " face); tree '" << t.name()
              << "': " << t.node_count() << " nodes, " << t.active_nodes().size() << " active, depth " << t.depth()
              << "; " << fmt(secs) << " s, peak memory " << peak_mib() << " MiB\n";
    std::cerr << "  import: " << r.file_vertices << " file vertices welded to " << r.vertices << "; " << r.faces
              << " faces (" << r.degenerate_faces << " degenerate, " << r.needle_faces << " needles, " << r.duplicate_faces
              << " duplicates); " << r.components << " component"
              << (r.components == 1 ? "" : "s") << ", " << (r.closed ? "closed" : "not closed") << "; "
              << r.boundary_edges << " boundary, " << r.nonmanifold_edges << " non-manifold edges\n";
    std::cerr << clip_note.str();
    if (a.times)
        std::cerr << "  time: import " << fmt(import_secs) << " s, sampling " << fmt(st.sample_seconds) << " s, tree "
                  << fmt(st.build_seconds) << " s, save " << fmt(save_secs) << " s (" << a.threads << " thread"
                  << (a.threads > 1 ? "s" : "") << ")\n";
    for (const auto& f : r.fixes) std::cerr << "  fixed: " << f << "\n";
    for (const auto& w : r.warnings) std::cerr << "  warning: " << w << "\n";
    const double diag = m.mesh.diagonal();
    if (opt.tolerance && !std::isfinite(st.worst_predicted_gap))
        std::cerr << "  warning: the tree gave some face samples smaller spheres than assumed; gaps may exceed "
                  << a.tolerance << "\n";
    if (st.automatic_tolerance > 0 && st.uncovered_open_faces > 0)
        std::cerr << "  note: vertex samples alone would leave " << st.uncovered_open_faces
                  << " faces of open parts partly outside every sphere; faces were sampled until the spheres hold "
                  << "them, closed parts to a tolerance of " << st.automatic_tolerance << " (" << fmt(100 * kAutoTolerance)
                  << "% of the diagonal) (--vertices-only to keep vertex samples only)\n";
    else if (st.automatic_tolerance > 0)
        std::cerr << "  note: vertex samples alone would leave the surface uncovered deeper than "
                  << st.automatic_tolerance << " (" << fmt(100 * kAutoTolerance) << "% of the diagonal); faces were "
                  << "sampled to that tolerance (--vertices-only to keep vertex samples only)\n";
    if (!opt.tolerance && st.automatic_tolerance == 0 && st.worst_predicted_gap > 0.01 * diag)
        std::cerr << "  warning: vertex samples leave the surface uncovered up to " << st.worst_predicted_gap << " ("
                  << fmt(100 * st.worst_predicted_gap / diag) << "% of the diagonal); --tolerance EPS adds face samples\n";
    // The worker exits once this file is done, and the exit returns all its pages at once: the
    // mesh and the document are left to it rather than freed an allocation at a time (the
    // 334k tree nodes of a 1M-vertex mesh alone are as many small blocks).
    (void)new ImportedMesh(std::move(m));
    (void)new SptDocument(std::move(doc));
    return 0;
}

// DIR/<stem>.spt, or DIR/<file name>.spt when `keep_extension` (two inputs share a stem).
std::string output_for(const std::string& in, const ConvertArgs& a, bool keep_extension) {
    if (!a.output.empty()) return a.output;
    const fs::path name = keep_extension ? fs::path(in).filename() : fs::path(in).stem();
    const fs::path dir = a.out_dir.empty() ? fs::path(in).parent_path() : fs::path(a.out_dir);
    return (dir / name).string() + ".spt";
}

void draw_progress(size_t done, size_t total, size_t failed) {
    const int width = 30;
    const int filled = total ? int(width * done / total) : width;
    std::cerr << "\r[" << std::string(size_t(filled), '#') << std::string(size_t(width - filled), '.') << "] " << done
              << "/" << total << " files, " << failed << " failed" << std::flush;
}

int run_convert(const ConvertArgs& a) {
    if (a.motion.empty() != a.object.empty())
        throw Error(ErrorKind::Usage, "--motion SCENE.json and --object NAME go together: the scene's motion of that object");
    if (!a.motion.empty() && !a.recipe.empty())
        throw Error(ErrorKind::Usage, "--motion builds a tree for a motion; --recipe replaces the trees: use one");
    if (!a.motion.empty() && a.inputs.size() != 1)
        throw Error(ErrorKind::Usage, "--motion builds for one object: give one input mesh");
    if (a.append && !a.recipe.empty())
        throw Error(ErrorKind::Usage, "--append adds one automatic tree; --recipe replaces the trees");
    if (a.append && a.tolerance > 0)
        throw Error(ErrorKind::Usage, "--append keeps the file's samples; --tolerance would change them");
    if (!a.output.empty() && a.inputs.size() != 1)
        throw Error(ErrorKind::Usage, "-o names one output file; with " + std::to_string(a.inputs.size()) +
                                          " inputs use --out-dir DIR");
    // Caught before any work: a directory given to -o fails only at the final rename.
    if (!a.output.empty() && (fs::is_directory(a.output) || a.output.back() == '/'))
        throw Error(ErrorKind::Usage, "-o names an output file, and " + a.output + " is a directory: use --out-dir " +
                                          a.output);
    if (!a.out_dir.empty()) {
        std::error_code ec;
        fs::create_directories(a.out_dir, ec);
        if (!fs::is_directory(a.out_dir))
            throw Error(ErrorKind::CannotWrite, a.out_dir + ": cannot create the output directory");
    }
    // Inputs whose outputs would collide (spider.obj and spider.fbx) keep their extension.
    std::map<std::string, int> uses;
    for (const auto& in : a.inputs) ++uses[fs::weakly_canonical(output_for(in, a, false)).string()];
    std::vector<std::string> outputs;
    std::map<std::string, std::string> claimed;
    for (const auto& in : a.inputs) {
        const bool clash = a.output.empty() && uses[fs::weakly_canonical(output_for(in, a, false)).string()] > 1;
        outputs.push_back(output_for(in, a, clash));
        const std::string key = fs::weakly_canonical(outputs.back()).string();
        if (claimed.count(key))
            throw Error(ErrorKind::Usage, in + " and " + claimed[key] + " would both be written to " + outputs.back());
        claimed[key] = in;
    }
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const int jobs = a.jobs > 0 ? a.jobs : cores;
    // A file converts on the cores the other files at once leave it (one file: all of them).
    ConvertArgs args = a;
    if (args.threads == 0) args.threads = std::max(1, cores / int(std::min<size_t>(size_t(jobs), a.inputs.size())));
    const bool tty = ::isatty(2) && !a.quiet;
    const auto t0 = std::chrono::steady_clock::now();
    size_t converted = 0, failed = 0;
    int worst = 0;
    // Each worker may use at most 3/4 of the memory, shared among the workers.
    const size_t phys = size_t(::sysconf(_SC_PHYS_PAGES)) * size_t(::sysconf(_SC_PAGE_SIZE));
    const size_t limit = std::max<size_t>(size_t(1) << 30, phys / 4 * 3 / size_t(jobs));
    std::vector<std::string> failures;
    auto work = [&](size_t i) -> int {
        const std::string& out = outputs[i];
        if (a.append && !fs::exists(out)) {
            std::cerr << a.inputs[i] << ": --append needs an existing " << out << "\n";
            return 2;
        }
        if (!a.force && !a.append && fs::exists(out)) {
            std::cerr << a.inputs[i] << ": " << out << " exists; use --force to overwrite\n";
            return 3;
        }
        try {
            return convert_one(a.inputs[i], out, args);
        } catch (const Error& e) {
            std::cerr << e.what() << "\n";
            return spt::cli::exit_code(e.kind());
        }
    };
    auto done = [&](size_t i, const JobOutcome& o) {
        if (o.exit_code == 0) ++converted;
        else ++failed, worst = std::max(worst, o.exit_code);
        std::string msg = o.messages;
        if (!o.abnormal.empty()) msg += a.inputs[i] + ": " + o.abnormal + "\n";
        if (o.exit_code != 0) {
            std::string first = msg.substr(0, msg.find('\n'));
            failures.push_back(first);
        }
        if (tty) std::cerr << "\r\033[K";
        if (!a.quiet || o.exit_code != 0) std::cerr << (o.exit_code ? "FAILED " : "") << msg;
        if (tty) draw_progress(converted + failed, a.inputs.size(), failed);
    };
    if (tty) draw_progress(0, a.inputs.size(), 0);
    run_in_processes(a.inputs.size(), jobs, a.timeout, limit, work, done);
    if (tty) std::cerr << "\n";
    const double secs = seconds_since(t0);
    std::cerr << "converted " << converted << ", failed " << failed << ", " << fmt(secs) << " s (" << jobs
              << " job" << (jobs > 1 ? "s" : "") << ")\n";
    return worst;
}

} // namespace

Action add_convert_command(CLI::App& app) {
    auto a = std::make_shared<ConvertArgs>();
    CLI::App* c = app.add_subcommand("convert", "Convert meshes to .spt sampling-tree files (in parallel)");
    c->add_option("inputs", a->inputs, "Mesh files (any format assimp reads)")->required();
    auto* o = c->add_option("-o,--output", a->output, "Output .spt file (one input only)");
    c->add_option("--out-dir", a->out_dir, "Directory for outputs (DIR/<name>.spt)")->excludes(o);
    c->add_option("--leaf-size", a->leaf_size, "Split until an active node holds at most N samples")
        ->check(CLI::Range(1u, 1u << 20));
    c->add_option("--radius", a->radius, "Sampling-sphere radius for every node, model units (default: from spacing)")
        ->check(finite_positive());
    c->add_option("--radius-scale", a->radius_scale, "Default radius = scale x median sample spacing of the node")
        ->check(finite_positive());
    c->add_option("--tolerance", a->tolerance, "Add face samples so no surface gap is deeper than EPS (model units)")
        ->check(finite_positive());
    c->add_option("--protrusion", a->protrusion,
                  "How far a sampling sphere may poke out of the surface, model units (default: an eighth of "
                  "--tolerance if given, else 0.25% of the diagonal)")
        ->check(finite_positive());
    auto* clip_step = c->add_option("--clip-poses", a->clip_step,
                                    "Limit the spheres' radii at poses STEP seconds apart along every clip too, not "
                                    "only at the bind pose, so that none pokes out by more than the allowance where "
                                    "a clip squeezes or bends the surface (animated meshes; docs/deforming.md)")
                          ->check(finite_positive());
    c->add_flag("--vertices-only", a->vertices_only,
                "Sample vertices only (the paper), even where that leaves holes; otherwise faces are sampled "
                "automatically when vertex gaps exceed 0.5% of the diagonal");
    c->add_option("--bounds", a->bounds, "Bounding spheres: tight (contain every sampling sphere) or paper")
        ->check(CLI::IsMember({"tight", "paper"}));
    c->add_option("--strategy", a->strategy, "Automatic split: volume (min. children's sphere volume) or median")
        ->check(CLI::IsMember({"volume", "median"}));
    c->add_option("--tree-name", a->tree_name, "Name of the tree in the file");
    c->add_option("--recipe", a->recipe,
                  "Redo the manual splits recorded in this .spt file (made from an earlier version of the mesh), "
                  "each at the clip and time it was made at; its trees replace the automatic one")
        ->check(CLI::ExistingFile);
    c->add_option("--motion", a->motion,
                  "Build the tree (--tree-name) for this scene's motion of --object: the scene is run and the "
                  "regions that come near a partner are split first (docs/editor.md, \"Authoring from motion\")")
        ->check(CLI::ExistingFile);
    c->add_option("--object", a->object, "The object of the --motion scene whose motion the tree is for");
    c->add_option("--motion-steps", a->motion_steps, "Steps of the --motion scene to record (default: the scene's)")
        ->check(CLI::Range(1, 100000000));
    c->add_option("-j,--jobs", a->jobs, "Files converted at once (default: all cores)")->check(CLI::Range(1, 1024));
    c->add_option("--threads", a->threads,
                  "Threads sampling each file (default: the cores the --jobs at once leave it; the output is the "
                  "same for any count)")
        ->check(CLI::Range(1, 1024));
    c->add_option("--timeout", a->timeout, "Give up on one file after this many seconds (0: never)")
        ->check(finite_in(0, std::numeric_limits<double>::max(), "of seconds, 0 or more"));
    c->add_flag("-f,--force", a->force, "Overwrite existing outputs (with --append: replace a same-named tree)");
    c->add_flag("--append", a->append,
                "Add a tree (--tree-name) over the samples of an existing OUT.spt made from the same mesh")
        ->excludes(clip_step);
    c->add_flag("-q,--quiet", a->quiet, "Print only failures and the summary");
    c->add_flag("--times", a->times,
                "Print each file's stage times: import, sampling (with radius limiting), tree, save");
    return [a] { return run_convert(*a); };
}

} // namespace spt::cli
