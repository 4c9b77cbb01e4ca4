// spt render INPUT [--tree FILE.spt] [--view V] [--size WxH] [--frame N | --frames A:B]
//            [--clip NAME --time T] [--backend B] [--overlay LIST]
//            [--color-by level|node|contacts --scene SCENE.json --object NAME [--motion-steps N]] -o OUT.png
#include "commands.hpp"
#include "number_checks.hpp"
#include "spt/compact_tree.hpp"
#include "spt/convert.hpp"
#include "spt/deforming_model.hpp"
#include "spt/error.hpp"
#include "spt/motion.hpp"
#include "spt/render/offscreen.hpp"
#include "spt/render/renderer.hpp"
#include "spt/render/scene_drawing.hpp"
#include "spt/render/tree_overlay.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <set>
#include <sys/resource.h>

namespace spt::cli {
namespace {

using namespace spt::render;

struct RenderArgs {
    std::string input, tree_path, tree_name, view = "camera", size = "512x512", frames, backend = "osmesa";
    std::string output, shading = "smooth", color_by = "node", clip;
    std::string scene, object; // --color-by contacts: the motion recorded
    int motion_steps = 0;
    double time = 0;
    bool time_given = false;
    std::vector<std::string> overlays;
    int frame = -1;
    uint64_t node = 1;
    int bounds_depth = 1;
    double mesh_opacity = -1;
    bool timings = false;
};

// Wall time of each step, printed with --timings (docs/benchmarks.md uses them).
class StepTimer {
public:
    explicit StepTimer(bool on) : on_(on), last_(Clock::now()) {}
    void step(const char* name) {
        const auto now = Clock::now();
        if (on_) std::cerr << "  " << name << ": " << std::chrono::duration<double>(now - last_).count() * 1000.0 << " ms\n";
        last_ = now;
    }

private:
    using Clock = std::chrono::steady_clock;
    bool on_;
    Clock::time_point last_;
};

const std::vector<std::string> kOverlays = {"spheres",  "bounds",  "node",     "wire",  "points", "grid",
                                            "axes",     "none",    "contacts", "normals", "manifold", "pairs",
                                            "ghost",    "trails",  "broad"};
const std::set<std::string> kSceneOnly = {"contacts", "normals", "manifold", "pairs", "ghost", "trails", "broad"};

std::pair<int, int> parse_size(const std::string& s) {
    const size_t x = s.find('x');
    auto number = [&](const std::string& t) {
        if (t.empty() || t.size() > 6 || t.find_first_not_of("0123456789") != std::string::npos) return -1;
        return std::stoi(t);
    };
    const int w = x == std::string::npos ? -1 : number(s.substr(0, x));
    const int h = x == std::string::npos ? -1 : number(s.substr(x + 1));
    if (w < 1 || h < 1 || w > 16384 || h > 16384)
        throw Error(ErrorKind::Usage, "--size " + s + ": expected WxH, each 1 to 16384 pixels (e.g. 512x512)");
    return {w, h};
}

std::vector<int> parse_frames(const RenderArgs& a) {
    if (a.frame >= 0) return {a.frame};
    if (a.frames.empty()) return {0};
    const size_t colon = a.frames.find(':');
    auto number = [](const std::string& t) -> long {
        if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos) return -1;
        return std::stol(t);
    };
    const long first = colon == std::string::npos ? -1 : number(a.frames.substr(0, colon));
    const long last = colon == std::string::npos ? -1 : number(a.frames.substr(colon + 1));
    if (first < 0 || last < first)
        throw Error(ErrorKind::Usage, "--frames " + a.frames + ": expected A:B with 0 <= A <= B");
    if (last - first >= 100000) throw Error(ErrorKind::Usage, "--frames " + a.frames + ": at most 100000 frames");
    std::vector<int> frames;
    for (long f = first; f <= last; ++f) frames.push_back(int(f));
    return frames;
}

std::string output_name(const std::string& pattern, int frame) {
    std::string out = pattern;
    const std::string key = "{frame}";
    for (size_t at = out.find(key); at != std::string::npos; at = out.find(key, at))
        out.replace(at, key.size(), std::to_string(frame)), at += std::to_string(frame).size();
    return out;
}

// Writes frame f's picture to the pattern's file, making its directory first ('-o out/{frame}.png'
// in a fresh folder works as it reads).
void write_frame(const Image& image, const std::string& pattern, int frame) {
    const std::string path = output_name(pattern, frame);
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    std::error_code ec;
    // An existing folder is not an error (false, ec clear); a file in its place is.
    if (!dir.empty() && !std::filesystem::create_directories(dir, ec) && ec)
        throw Error(ErrorKind::CannotWrite, path + ": cannot write: cannot make its directory " + dir.string() + ": " +
                                                ec.message());
    write_png(image, path);
}

View parse_view(const std::string& v) {
    if (v == "top") return View::Top;
    if (v == "front") return View::Front;
    if (v == "side") return View::Side;
    return View::Camera;
}

bool is_scene_file(const std::string& path) {
    return path.size() > 5 && path.compare(path.size() - 5, 5, ".json") == 0;
}

// Frame k is the state after step k (0: the initial state); only what an overlay needs is computed.
int run_scene_render(const RenderArgs& a, int width, int height, const std::vector<int>& frames) {
    std::set<std::string> names(a.overlays.begin(), a.overlays.end());
    if (a.overlays.empty()) names = {"grid", "axes"};
    for (const std::string& n : names)
        if (n == "node" || n == "wire" || n == "points")
            throw Error(ErrorKind::Usage, "--overlay " + n + " is for a mesh or .spt INPUT, not a scene");
    SceneOverlays o;
    for (const std::string& n : names)
        if (bool* flag = scene_overlay_flag(o, n)) *flag = true;
    const Scene scene = load_scene(a.input);
    // An overlay with nothing to draw is refused rather than silently left out of every frame.
    if (const std::string problem = scene_overlays_problem(scene.effects, o); !problem.empty())
        throw Error(ErrorKind::Usage, a.input + ": " + problem);
    Simulation sim(scene, effects_for_overlays(scene.effects, o), hardware_threads());
    auto context = make_offscreen_context(a.backend, width, height);
    auto renderer = std::make_unique<Renderer>(context->loader());
    SceneDrawing drawing(*renderer, sim.scene());
    std::vector<std::vector<Eigen::Vector3f>> trails(scene.objects.size());
    auto record = [&] {
        if (o.trails)
            for (size_t i = 0; i < trails.size(); ++i) trails[i].push_back(sim.poses()[i].translation.cast<float>());
    };
    record();
    // The camera is fitted once, to the initial state, so that frames line up.
    const Camera camera = fit_camera(parse_view(a.view), drawing.initial_bounds(*renderer));
    const StepResult* step = nullptr;
    for (int f : frames) {
        while (sim.steps_done() < f) step = &sim.step(), record();
        drawing.show_time(*renderer, double(sim.steps_done()) * scene.dt, sim.effects().has(Effect::Deform));
        Frame frame = drawing.frame(sim.poses(), step, sim.ghost_poses(), trails, sim.broad_spheres(), o);
        frame.grid = names.count("grid") > 0;
        frame.axes = names.count("axes") > 0;
        renderer->draw(frame, camera, Viewport{0, 0, width, height}, context->framebuffer());
        write_frame(context->read_pixels(), a.output, f);
    }
    renderer.reset(); // GL objects go before their context
    return 0;
}

// The "Key:" field of a /proc file, in bytes (its kB times 1024); 0 when it cannot be read.
uint64_t proc_kib_field(const char* file, const std::string& key) {
    std::ifstream in(file);
    std::string word;
    uint64_t kib = 0;
    while (in >> word) {
        if (word == key && in >> kib) return kib * 1024;
        in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    }
    return 0;
}

// What this process may still take: the memory the kernel says is available, and no more than
// an address-space limit (ulimit -v) leaves above what is mapped now. 0: unknown.
uint64_t available_memory_bytes() {
    uint64_t have = proc_kib_field("/proc/meminfo", "MemAvailable:");
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
        const uint64_t mapped = proc_kib_field("/proc/self/status", "VmSize:");
        const uint64_t left = uint64_t(limit.rlim_cur) > mapped ? uint64_t(limit.rlim_cur) - mapped : 1;
        have = have ? std::min(have, left) : left;
    }
    return have;
}

// Linux grants a render's allocations and kills the process when it touches more than there
// is: a size that cannot fit is refused before any work, with what it needs.
void check_render_fits(const std::string& size, int width, int height) {
    const uint64_t need = offscreen_render_bytes(width, height), have = available_memory_bytes();
    if (have == 0 || need <= have) return;
    const double gib = 1024.0 * 1024.0 * 1024.0;
    char msg[256];
    std::snprintf(msg, sizeof msg,
                  "--size %s needs about %.2f GiB of memory to render and %.2f GiB are available: choose a smaller size",
                  size.c_str(), double(need) / gib, double(have) / gib);
    throw Error(ErrorKind::Usage, msg);
}

int run_render(const RenderArgs& a) {
    const auto [width, height] = parse_size(a.size);
    check_render_fits(a.size, width, height);
    const std::vector<int> frames = parse_frames(a);
    if (frames.size() > 1 && a.output.find("{frame}") == std::string::npos)
        throw Error(ErrorKind::Usage, "-o " + a.output + ": with --frames, the output name needs {frame}");
    const bool contacts = a.color_by == "contacts";
    if (contacts && (a.scene.empty() || a.object.empty()))
        throw Error(ErrorKind::Usage, "--color-by contacts needs --scene SCENE.json and --object NAME: the motion whose "
                                      "contacts colour the spheres");
    if (!contacts && (!a.scene.empty() || !a.object.empty() || a.motion_steps > 0))
        throw Error(ErrorKind::Usage, "--scene, --object and --motion-steps are for --color-by contacts");
    if (is_scene_file(a.input)) {
        if (contacts) throw Error(ErrorKind::Usage, "--color-by contacts is for a mesh or .spt INPUT, not a scene");
        if (a.view == "quad") throw Error(ErrorKind::Usage, "--view quad is for a mesh or .spt INPUT, not a scene");
        return run_scene_render(a, width, height, frames);
    }
    for (const std::string& n : a.overlays)
        if (kSceneOnly.count(n)) throw Error(ErrorKind::Usage, "--overlay " + n + " needs a scene (SCENE.json) INPUT");

    std::set<std::string> overlays(a.overlays.begin(), a.overlays.end());
    const bool spt_input = is_spt_file(a.input);
    if (a.overlays.empty()) overlays = spt_input ? std::set<std::string>{"spheres", "grid", "axes"}
                                                 : std::set<std::string>{"grid", "axes"};
    if (overlays.count("none") && overlays.size() > 1)
        throw Error(ErrorKind::Usage, "--overlay none cannot be combined with other overlays");
    const bool needs_tree = overlays.count("spheres") || overlays.count("bounds") || overlays.count("node");
    if (contacts && !overlays.count("spheres") && !overlays.count("node"))
        throw Error(ErrorKind::Usage, "--color-by contacts colours sampling spheres: add spheres (or node) to --overlay");
    if (spt_input && !a.tree_path.empty())
        throw Error(ErrorKind::Usage, a.input + " is already a .spt file; --tree takes the tree of a mesh INPUT");

    if (a.time_given && a.clip.empty()) throw Error(ErrorKind::Usage, "--time needs --clip: the clip to pose the mesh by");
    if (!a.clip.empty() && spt_input)
        throw Error(ErrorKind::Usage, "--clip poses a mesh; " + a.input + " is a .spt file, which holds no animation");
    if (!a.clip.empty() && (overlays.count("bounds") || overlays.count("node")))
        throw Error(ErrorKind::Usage, "--overlay bounds and node draw the tree's bind pose: not with --clip");

    StepTimer timer(a.timings);
    // Geometry: a mesh, and a sampling tree when an overlay needs one.
    std::optional<TriangleMesh> mesh;
    std::optional<SptDocument> doc;
    std::shared_ptr<AnimatedMesh> animated; // with --clip
    const Clip* clip = nullptr;
    if (spt_input) {
        doc = load_spt(a.input);
    } else {
        if (!a.clip.empty()) {
            animated = std::make_shared<AnimatedMesh>(import_animated_mesh(a.input));
            clip = &animated->clips[animated->find_clip(a.clip)];
            mesh = animated->imported.mesh;
        } else {
            mesh = import_mesh(a.input).mesh;
        }
        timer.step("import mesh");
        if (!a.tree_path.empty()) {
            doc = load_spt(a.tree_path);
            const std::string mismatch = check_mesh_matches(doc->mesh, *mesh);
            if (!mismatch.empty())
                throw_bad_input(a.tree_path, "was not made from " + a.input + ": " + mismatch);
        } else if (needs_tree) {
            doc = make_document(*mesh);
        }
    }
    if (doc) timer.step(spt_input || !a.tree_path.empty() ? "load tree" : "build tree");
    const SamplingTree* tree = nullptr;
    if (doc) {
        if (doc->trees.empty()) throw_bad_input(spt_input ? a.input : a.tree_path, "holds no sampling tree");
        tree = a.tree_name.empty() ? &doc->trees.front() : doc->tree(a.tree_name);
        if (!tree) {
            std::string names;
            for (const auto& t : doc->trees) names += (names.empty() ? "'" : ", '") + t.name() + "'";
            throw Error(ErrorKind::Usage, "--tree-name " + a.tree_name + ": " +
                                              (spt_input ? a.input : a.tree_path) + " holds " + names);
        }
        if ((overlays.count("bounds") || overlays.count("node")) && !tree->find(a.node))
            throw Error(ErrorKind::Usage, "--node " + std::to_string(a.node) + ": tree '" + tree->name() +
                                              "' has no node with that id");
    }

    auto context = make_offscreen_context(a.backend, width, height);
    auto renderer = std::make_unique<Renderer>(context->loader());
    timer.step("create context");

    Frame frame;
    frame.grid = overlays.count("grid") > 0;
    frame.axes = overlays.count("axes") > 0;
    const bool show_spheres = overlays.count("spheres") > 0;
    const bool show_node = overlays.count("node") > 0;
    // Geometry is uploaded relative to the model's local origin and placed back by its pose:
    // far from the origin, float keeps its detail only so.
    const Eigen::Vector3d origin = doc ? doc->samples.origin : mesh ? Renderer::drawing_origin(*mesh) : Eigen::Vector3d::Zero();
    // --clip: the mesh and its spheres at the pose (the spheres follow it as a scene's do).
    std::optional<DeformingModel> posed;
    if (clip) {
        mesh = posed_mesh(*animated, clip, a.time);
        if (doc) {
            posed.emplace(*doc, animated, tree ? tree->name() : std::string(), false);
            posed->pose(clip, a.time);
        }
        timer.step("pose");
    }
    if (mesh) {
        MeshItem item;
        item.mesh = renderer->add_mesh(*mesh, origin);
        item.pose = local_frame(origin);
        item.style.shading = a.shading == "flat" ? Shading::Flat : a.shading == "none" ? Shading::None : Shading::Smooth;
        item.style.wireframe = overlays.count("wire") > 0;
        item.style.points = overlays.count("points") > 0;
        // Sampling spheres lie inside the surface: show them through a see-through mesh.
        const double opacity = a.mesh_opacity >= 0 ? a.mesh_opacity : (show_spheres || show_node) ? 0.3 : 1.0;
        item.style.opacity = float(opacity);
        frame.meshes.push_back(item);
    }
    // --color-by contacts: the scene run with this tree in place of the object's model (core's
    // record_motion), each sample coloured by the steps its sphere was in contact.
    std::vector<uint32_t> contact_steps;
    if (contacts && tree) {
        MotionOptions mo;
        mo.steps = a.motion_steps;
        mo.threads = hardware_threads();
        const MotionRecording rec = record_motion(load_scene(a.scene), a.object,
                                                  MotionModel{std::make_shared<const SptDocument>(*doc), tree->name(), animated}, mo);
        contact_steps = rec.contact_steps;
        timer.step("record motion");
        std::cout << "contacts: " << a.scene << " object " << a.object << ", " << rec.steps.size() << " steps, "
                  << rec.steps_in_contact << " in contact" << (heat_scale(contact_steps).log ? " (log scale)" : "") << "\n";
        for (const HeatLegendRow& row : heat_legend(heat_scale(contact_steps), contact_steps))
            std::cout << "  " << row.from << (row.to != row.from ? "-" + std::to_string(row.to) : std::string())
                      << " steps: " << row.samples << " samples\n";
    }
    if (tree && (show_spheres || show_node)) {
        const CompactTree compact = posed ? posed->model().tree() : CompactTree(*tree, doc->samples);
        const ColorBy by = contacts ? ColorBy::Contacts : a.color_by == "node" ? ColorBy::Node : ColorBy::Level;
        const SphereSetHandle set = renderer->add_spheres(sampling_spheres(compact, *tree, by, origin, &contact_steps));
        if (show_node) {
            for (SphereItem item : highlighted_node(set, renderer->sphere_count(set),
                                                    sphere_range(compact, *tree, a.node), show_spheres,
                                                    contacts || is_inner_node(*tree, a.node))) {
                item.pose = local_frame(origin);
                frame.spheres.push_back(item);
            }
        } else {
            SphereItem all;
            all.spheres = set;
            all.pose = local_frame(origin);
            frame.spheres.push_back(all);
        }
    }
    if (tree && overlays.count("bounds"))
        for (const WireSphere& w : bounding_spheres(*tree, doc->samples.origin, a.node, a.bounds_depth, highlight_color()))
            frame.wire_spheres.push_back(w);
    if (tree && show_node && !overlays.count("bounds"))
        frame.wire_spheres.push_back(bounding_spheres(*tree, doc->samples.origin, a.node, 0, highlight_color()).front());

    timer.step("upload");
    Bounds bounds = renderer->bounds(frame);
    if (bounds.empty()) bounds.add(Eigen::Vector3f::Zero());
    if (a.view == "quad")
        renderer->draw_quad(frame, fit_quad_cameras(bounds), width, height, context->framebuffer());
    else
        renderer->draw(frame, fit_camera(parse_view(a.view), bounds), Viewport{0, 0, width, height},
                      context->framebuffer());
    const Image image = context->read_pixels();
    timer.step("draw and read back");
    renderer.reset(); // GL objects go before their context
    context.reset();
    timer.step("release context");

    // A mesh or a tree alone does not move: every frame is the same picture.
    for (int f : frames) write_frame(image, a.output, f);
    timer.step("write png");
    return 0;
}

} // namespace

Action add_render_command(CLI::App& app) {
    auto a = std::make_shared<RenderArgs>();
    CLI::App* c = app.add_subcommand("render", "Render a mesh and its sampling tree off screen to PNG");
    c->footer("Overlays: spheres (sampling spheres), bounds (bounding spheres of --node and --bounds-depth levels\n"
              "below), node (highlight --node), wire (mesh edges), points (mesh vertices), grid, axes, none.\n"
              "A scene (SCENE.json) INPUT: frame k is the state after step k; overlays contacts, normals, manifold\n"
              "(contact manifold points of effect dynamics, new and kept), pairs, ghost (pose before the response),\n"
              "trails, bounds (objects' bounding spheres), broad (broad-phase spheres of the step), spheres, grid,\n"
              "axes (docs/scenes.md).\n"
              "Default overlays: grid,axes (a .spt INPUT: spheres,grid,axes). {frame} in OUT is replaced by the\n"
              "frame number. Exit codes: 0 ok, 1 usage, 2 bad input, 3 cannot write. See docs/rendering.md.");
    c->add_option("input", a->input, "Mesh file (any format assimp reads), a .spt file (spheres only) or a scene (.json)")
        ->required();
    c->add_option("-o,--output", a->output, "Output PNG; {frame} is replaced by the frame number")->required();
    c->add_option("--tree", a->tree_path, "Sampling-tree file of the mesh (default: built when an overlay needs it)");
    c->add_option("--tree-name", a->tree_name, "Tree to show from the file (default: the first)");
    c->add_option("--view", a->view, "View: top, front, side, camera (perspective) or quad (all four)")
        ->check(CLI::IsMember({"top", "front", "side", "camera", "quad"}));
    c->add_option("--size", a->size, "Image size WxH in pixels (default 512x512)");
    auto* frame = c->add_option("--frame", a->frame, "Frame to render (scenes; a mesh is static)")
                      ->check(CLI::Range(0, 1 << 30));
    c->add_option("--frames", a->frames, "Frames A:B, inclusive; OUT must contain {frame}")->excludes(frame);
    c->add_option("--backend", a->backend, "Off-screen backend: osmesa (default) or egl")
        ->check(CLI::IsMember({"osmesa", "egl"}));
    c->add_option("--overlay", a->overlays, "Comma-separated overlays (see below)")
        ->delimiter(',')
        ->check(CLI::IsMember(kOverlays));
    c->add_option("--shading", a->shading, "Mesh faces: smooth (default), flat or none")
        ->check(CLI::IsMember({"smooth", "flat", "none"}));
    c->add_option("--mesh-opacity", a->mesh_opacity, "Mesh opacity 0-1 (default 1; 0.3 with spheres or node)")
        ->check(finite_in(0, 1, "from 0 to 1"));
    c->add_option("--color-by", a->color_by,
                  "Sampling-sphere colours: node (default; the two children of a split in opposite hues), level (tree "
                  "depth), or contacts (steps in contact during the motion of --object in --scene)")
        ->check(CLI::IsMember({"level", "node", "contacts"}));
    c->add_option("--scene", a->scene, "With --color-by contacts: the scene (SCENE.json) run with this tree");
    c->add_option("--object", a->object, "With --color-by contacts: the scene's object whose model the tree replaces");
    c->add_option("--motion-steps", a->motion_steps, "With --color-by contacts: steps to run (default: the scene's)")
        ->check(CLI::Range(1, 1 << 24));
    c->add_option("--node", a->node, "Paper id of the node for the bounds and node overlays (default 1, the root)")
        ->check(CLI::Range(uint64_t(1), ~uint64_t(0)));
    c->add_option("--bounds-depth", a->bounds_depth, "Levels below --node whose bounding spheres are drawn (default 1)")
        ->check(CLI::Range(0, 62));
    c->add_option("--clip", a->clip, "Animation clip (name or index) to pose a mesh INPUT by (spt info lists them)");
    c->add_option("--time", a->time, "Clip time in seconds for --clip (default 0; held at the clip's ends)")
        ->check(finite_in(-1e9, 1e9, "from -1e9 to 1e9"))
        ->each([a](const std::string&) { a->time_given = true; });
    c->add_flag("--timings", a->timings, "Print the time of each step to stderr");
    return [a] { return run_render(*a); };
}

} // namespace spt::cli
