// The batches behind spt.collide, spt.distance and spt.backtrack (docs/queries.md, "Python").
#include "queries.hpp"
#include "pose_array.hpp"
#include "spt/query_batch.hpp"
#include "spt/response.hpp"
#include "spt/task_system.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace py = pybind11;

namespace spt::python {
namespace {

// The level `spt query --level` names; anything else is the caller's mistake (ValueError).
QueryLevel level_of(const std::string& level) {
    if (const std::optional<QueryLevel> named = query_level_named(level)) return *named;
    throw py::value_error("level: expected 'bounds', 'spheres' or 'exact', got '" + level + "'");
}

// A number as Python's str() would show it in the message ("0", "-1.5", "nan").
std::string shown(double x) { return py::str(py::float_(x)).cast<std::string>(); }

// Negative counts are a mistake; 0 is every core, as BatchOptions reads it.
void check_threads(int threads) {
    if (threads < 0) throw py::value_error("threads: expected 0 (every core) or more, got " + std::to_string(threads));
}

// The options `spt query` builds from its flags (run_query), checked as its parser checks them.
QueryOptions query_options(const CollideArgs& args) {
    if (!(args.cull_angle >= 0 && args.cull_angle <= 90))
        throw py::value_error("cull_angle: expected degrees from 0 to 90, got " + shown(args.cull_angle));
    check_threads(args.threads);
    QueryOptions o;
    o.level = level_of(args.level);
    o.normal_culling = args.culling;
    o.solids = !args.surfaces;
    o.cull_cos = float(std::cos(args.cull_angle * 3.14159265358979323846 / 180.0));
    return o;
}

// Threads only: a call is timed by its caller, so the batch times nothing itself.
BatchOptions batch_options(int threads) {
    BatchOptions batch;
    batch.threads = threads;
    return batch;
}

} // namespace

py::array_t<bool> collide(const Model& a, const Model& b, const py::handle& poses, const CollideArgs& args) {
    const QueryOptions o = query_options(args);
    const std::vector<Pose> b_in_a = poses_from_array(poses, "poses");
    std::vector<QueryResult> results;
    {
        py::gil_scoped_release unlocked;
        results = query_batch(a.model, b.model, b_in_a, o, batch_options(args.threads));
    }
    py::array_t<bool> out(py::ssize_t(results.size()));
    bool* hit = out.mutable_data();
    for (size_t i = 0; i < results.size(); ++i) hit[i] = results[i].collide;
    return out;
}

py::object distance(const Model& a, const Model& b, const py::handle& poses, const std::string& level,
                    double max_distance, double relative_error, double absolute_error, bool depth, int threads,
                    bool return_points) {
    check_threads(threads);
    DistanceOptions d;
    d.level = level_of(level);
    d.max_distance = max_distance;
    d.relative_error = relative_error;
    d.absolute_error = absolute_error;
    d.depth = depth;
    const std::vector<Pose> b_in_a = poses_from_array(poses, "poses");
    std::vector<DistanceResult> results;
    {
        py::gil_scoped_release unlocked;
        results = distance_batch(a.model, b.model, b_in_a, d, batch_options(threads));
    }
    const py::ssize_t n = py::ssize_t(results.size());
    py::array_t<double> gap(n), pa({n, py::ssize_t(3)}), pb({n, py::ssize_t(3)});
    double* g = gap.mutable_data();
    double* xa = pa.mutable_data();
    double* xb = pb.mutable_data();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (size_t i = 0; i < results.size(); ++i) {
        const DistanceResult& r = results[i];
        g[i] = r.beyond ? std::numeric_limits<double>::infinity() : r.distance;
        for (int k = 0; k < 3; ++k) { // `spt query` leaves a beyond pose's points empty
            xa[3 * i + size_t(k)] = r.beyond ? nan : r.point_a[k];
            xb[3 * i + size_t(k)] = r.beyond ? nan : r.point_b[k];
        }
    }
    if (!return_points) return std::move(gap);
    return py::make_tuple(gap, pa, pb);
}

py::array_t<double> backtrack(const Model& a, const Model& b, const py::handle& poses, const py::handle& directions,
                              const CollideArgs& args, const std::string& rule, double max_distance) {
    const QueryOptions o = query_options(args);
    if (rule != "exact" && rule != "paper")
        throw py::value_error("rule: expected 'exact' or 'paper', got '" + rule + "'");
    if (!(max_distance > 0))
        throw py::value_error("max_distance: expected a distance > 0, got " + shown(max_distance));
    const BacktrackRule r = rule == "paper" ? BacktrackRule::Paper : BacktrackRule::Exact;
    const std::vector<Pose> b_in_a = poses_from_array(poses, "poses");
    const std::vector<Eigen::Vector3d> motion = directions_from_array(directions, "directions", b_in_a.size());
    py::array_t<double> out(py::ssize_t(b_in_a.size()));
    double* back = out.mutable_data();
    {
        py::gil_scoped_release unlocked;
        // A contiguous share of the poses a job, one scratch each (a scratch serves one thread).
        const size_t n = b_in_a.size();
        const size_t cores = size_t(args.threads > 0 ? args.threads : hardware_threads());
        const int jobs = int(std::max<size_t>(1, std::min(cores, n)));
        run_parallel(jobs, [&](int job) {
            QueryScratch scratch;
            for (size_t i = n * size_t(job) / size_t(jobs); i < n * size_t(job + 1) / size_t(jobs); ++i) {
                const BacktrackResult res =
                    backtrack_relative(a.model, b.model, b_in_a[i], motion[i], o, r, scratch, max_distance);
                back[i] = res.beyond ? std::numeric_limits<double>::infinity() : res.distance;
            }
        });
    }
    return out;
}

double time_collide_batch(const Model& a, const Model& b, const py::handle& poses, const CollideArgs& args) {
    const QueryOptions o = query_options(args);
    const std::vector<Pose> b_in_a = poses_from_array(poses, "poses");
    py::gil_scoped_release unlocked;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<QueryResult> results = query_batch(a.model, b.model, b_in_a, o, batch_options(args.threads));
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace spt::python
