// spt query A B --poses FILE [--level bounds|spheres|exact] [--mode any|all|deepest] [--repeat K] [-o OUT.csv]
#include "commands.hpp"
#include "number_checks.hpp"
#include "spt/pose_file.hpp"
#include "spt/convert.hpp"
#include "spt/distance.hpp"
#include "spt/error.hpp"
#include "spt/query.hpp"
#include "spt/query_batch.hpp"
#include "spt/response.hpp"
#include <algorithm>
#include <limits>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>

namespace spt::cli {
namespace {

struct QueryArgs {
    std::string a, b, poses, output, level = "spheres", mode = "any", mesh_a, mesh_b, tree, backtrack = "exact";
    int repeat = 5;
    int threads = 1; // poses at once; 1 keeps each pose's ns what one thread alone takes
    bool culling = false, surfaces = false;
    double cull_angle = 60;
    double max_distance = std::numeric_limits<double>::infinity(); // --mode distance
    bool no_depth = false;                                         // --mode distance
};

// --mode distance: pose,collide,distance,ax,ay,az,bx,by,bz,node_pairs,sphere_tests,ns (points in A's
// frame; a distance beyond --max-distance is `inf` with empty points).
void write_distances(std::FILE* out, const CollisionModel& a, const CollisionModel& b, const std::vector<PoseLine>& poses,
                     const DistanceOptions& d, const BatchOptions& batch, const std::string& pose_file) {
    std::fprintf(out, "pose,collide,distance,ax,ay,az,bx,by,bz,node_pairs,sphere_tests,ns\n");
    std::vector<Pose> b_in_a;
    for (const PoseLine& pl : poses) b_in_a.push_back(pl.pose);
    std::vector<int64_t> times;
    const std::vector<DistanceResult> results = distance_batch(a, b, b_in_a, d, batch, &times);
    for (size_t i = 0; i < poses.size(); ++i) {
        const DistanceResult& r = results[i];
        if (!r.beyond && !std::isfinite(r.distance))
            throw Error(ErrorKind::BadInput, pose_file + ":" + std::to_string(poses[i].line) + ": the query gave a non-finite distance");
        if (r.beyond)
            std::fprintf(out, "%zu,0,inf,,,,,,,", i);
        else if (!r.point_a.allFinite() || !r.point_b.allFinite()) // overlapping, asked without depth
            std::fprintf(out, "%zu,%d,%.9g,,,,,,,", i, r.collide ? 1 : 0, r.distance);
        else
            std::fprintf(out, "%zu,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,", i, r.collide ? 1 : 0, r.distance, r.point_a.x(),
                         r.point_a.y(), r.point_a.z(), r.point_b.x(), r.point_b.y(), r.point_b.z());
        std::fprintf(out, "%llu,%llu,%lld\n", (unsigned long long)r.counters.node_pairs,
                     (unsigned long long)r.counters.sphere_tests, (long long)times[i]);
    }
}

// A document and, when one is known, its mesh; the model is built over both.
struct Loaded {
    SptDocument doc;
    std::optional<TriangleMesh> mesh;
    CollisionModel model;
};

std::unique_ptr<Loaded> load(const std::string& path, const std::string& mesh_path, const std::string& tree) {
    auto l = std::make_unique<Loaded>();
    if (is_spt_file(path)) {
        l->doc = load_spt(path);
        if (!mesh_path.empty()) l->mesh = import_mesh(mesh_path).mesh;
    } else {
        l->mesh = import_mesh(path).mesh;
        l->doc = make_document(*l->mesh);
    }
    l->model = l->mesh ? CollisionModel(l->doc, *l->mesh, tree) : CollisionModel(l->doc, tree);
    return l;
}

int run_query(const QueryArgs& args) {
    if (std::isfinite(args.max_distance) && args.mode != "distance")
        throw Error(ErrorKind::Usage, "--max-distance goes with --mode distance");
    if (args.no_depth && args.mode != "distance") throw Error(ErrorKind::Usage, "--no-depth goes with --mode distance");
    QueryOptions o;
    o.level = query_level_named(args.level).value_or(QueryLevel::Spheres); // the parser checked the name
    o.mode = args.mode == "all" ? QueryMode::All : args.mode == "deepest" ? QueryMode::Deepest : QueryMode::Any;
    o.normal_culling = args.culling;
    o.solids = !args.surfaces;
    o.cull_cos = float(std::cos(args.cull_angle * 3.14159265358979323846 / 180.0));
    const std::vector<PoseLine> poses = read_pose_file(args.poses); // throws BadInput naming the line
    const auto a = load(args.a, args.mesh_a, args.tree);
    const auto b = load(args.b, args.mesh_b, args.tree);
    if (o.level == QueryLevel::Exact && !(a->model.has_mesh() && b->model.has_mesh()))
        throw Error(ErrorKind::Usage,
                    "--level exact tests triangles, and a .spt file holds none: give the meshes as A and B, or add "
                    "--mesh-a/--mesh-b for .spt inputs");
    std::FILE* out = stdout;
    if (!args.output.empty()) {
        out = std::fopen(args.output.c_str(), "w");
        if (!out) throw Error(ErrorKind::CannotWrite, args.output + ": cannot open for writing: " + std::strerror(errno));
    }
    if (args.mode == "distance") {
        DistanceOptions d;
        d.level = o.level;
        d.max_distance = args.max_distance;
        d.depth = !args.no_depth;
        BatchOptions batch;
        batch.threads = args.threads;
        batch.repeat = std::max(1, args.repeat);
        write_distances(out, a->model, b->model, poses, d, batch, args.poses);
        if (out != stdout && std::fclose(out) != 0) throw Error(ErrorKind::CannotWrite, args.output + ": write failed");
        return 0;
    }
    std::fprintf(out, "pose,collide,depth,backtrack,node_pairs,sphere_tests,ns\n");
    QueryScratch scratch;
    QueryOptions deepest = o;
    deepest.mode = QueryMode::Deepest;
    if (deepest.level == QueryLevel::Exact) deepest.level = QueryLevel::Spheres; // depth is the sphere model's
    const BacktrackRule rule = args.backtrack == "paper" ? BacktrackRule::Paper : BacktrackRule::Exact;
    // Every pose in one batch (core's query_batch: the same answers on any --threads); the
    // depth and backtrack of the colliding ones after it.
    std::vector<Pose> b_in_a;
    b_in_a.reserve(poses.size());
    for (const PoseLine& pl : poses) b_in_a.push_back(pl.pose);
    BatchOptions batch;
    batch.threads = args.threads;
    batch.repeat = std::max(1, args.repeat);
    std::vector<int64_t> times;
    const std::vector<QueryResult> results = query_batch(a->model, b->model, b_in_a, o, batch, &times);
    for (size_t i = 0; i < poses.size(); ++i) {
        const PoseLine& pl = poses[i];
        const QueryResult& r = results[i];
        const int64_t median = times[i];
        double depth = 0, back = 0;
        if (r.collide) {
            const QueryResult d = collide_relative(a->model, b->model, pl.pose, deepest, scratch);
            depth = d.collide ? d.deepest.depth : 0;
            if (pl.direction)
                back = backtrack_relative(a->model, b->model, pl.pose, *pl.direction, o, rule, scratch).distance;
        }
        if (!std::isfinite(depth) || !std::isfinite(back)) // never write NaN or infinity
            throw Error(ErrorKind::BadInput, args.poses + ":" + std::to_string(pl.line) +
                                                 ": the query gave a non-finite depth or backtrack");
        std::fprintf(out, "%zu,%d,%.9g,%.9g,%llu,%llu,%lld\n", i, r.collide ? 1 : 0, depth, back,
                     (unsigned long long)r.counters.node_pairs, (unsigned long long)r.counters.sphere_tests,
                     (long long)median);
    }
    if (out != stdout && std::fclose(out) != 0) throw Error(ErrorKind::CannotWrite, args.output + ": write failed");
    return 0;
}

} // namespace

Action add_query_command(CLI::App& app) {
    auto a = std::make_shared<QueryArgs>();
    CLI::App* c = app.add_subcommand("query", "Collision queries of B against A at poses from a file (CSV out)");
    c->add_option("a", a->a, "Object A: .spt file or mesh (at the identity)")->required();
    c->add_option("b", a->b, "Object B: .spt file or mesh")->required();
    c->add_option("--poses", a->poses, "Poses of B in A's frame: 'tx ty tz qw qx qy qz [dx dy dz]' a line")->required();
    c->add_option("--level", a->level, "bounds | spheres | exact")->check(CLI::IsMember({"bounds", "spheres", "exact"}));
    c->add_option("--mode", a->mode, "any | all | deepest | distance (the gap, or minus the deepest overlap, and its points)")
        ->check(CLI::IsMember({"any", "all", "deepest", "distance"}));
    c->add_option("--max-distance", a->max_distance, "With --mode distance: gaps beyond this are written as inf")
        ->check(finite_in(std::numeric_limits<double>::min(), std::numeric_limits<double>::max(), "greater than 0"));
    c->add_flag("--no-depth", a->no_depth,
                "With --mode distance: overlapping poses are written as 0 with empty points, without the deepest "
                "overlap's walk (as FCL's distance answers)");
    c->add_option("--repeat", a->repeat, "Repeats per pose; ns is their median")->check(CLI::Range(1, 1000000));
    c->add_option("--threads", a->threads,
                  "Poses queried at once (default 1, so that ns is one thread's time; the answers are the same for any count)")
        ->check(CLI::Range(1, 1024));
    c->add_option("-o,--output", a->output, "CSV file (default: stdout)");
    c->add_option("--mesh-a", a->mesh_a, "Mesh of A when A is a .spt file (for --level exact)");
    c->add_option("--mesh-b", a->mesh_b, "Mesh of B when B is a .spt file (for --level exact)");
    c->add_option("--tree", a->tree, "Tree name in .spt files (default: the first)");
    c->add_flag("--culling", a->culling, "Normal culling (docs/queries.md)");
    c->add_flag("--surfaces", a->surfaces,
                "Surfaces only: an object wholly inside another's closed part does not collide (FCL's answer)");
    c->add_option("--cull-angle", a->cull_angle, "Culling cone half-angle in degrees (default 60)")->check(finite_in(0, 90, "of degrees from 0 to 90"));
    c->add_option("--backtrack", a->backtrack, "exact | paper (move back by the deepest depth)")
        ->check(CLI::IsMember({"exact", "paper"}));
    return [a] { return run_query(*a); };
}

} // namespace spt::cli
