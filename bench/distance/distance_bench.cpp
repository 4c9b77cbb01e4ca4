// distance_bench: spt's distance query against FCL's (OBBRSS) on the same meshes and poses, in one
// process, in interleaved rounds. Cases: two copies of the accuracy benchmark's meshes scaled
// into [-1, 1]^3 at its random poses (centre distances 0.2..2.4), and any pair of meshes (FCL's
// env.obj and rob.obj) at random poses in A's bounding box or given extents, as FCL's tests pose
// them. Prints a markdown table a case: agreement with FCL and the median and mean time of each
// query. Figures and commands: docs/queries.md.
#include "exit_code.hpp"
#include "mesh/shapes.hpp"
#include "peers.hpp"
#include "spt/convert.hpp"
#include "spt/distance.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace spt;
using Clock = std::chrono::steady_clock;

struct Case {
    std::string name;
    TriangleMesh a, b;
    std::vector<Pose> poses;
};

// One model of a mesh converted with spt convert's defaults, and what the conversion allows:
// how far its spheres may poke out of the surface and leave it uncovered (model units).
struct Converted {
    SptDocument doc;
    CollisionModel model;
    double protrusion = 0, uncovered = 0;
};

std::unique_ptr<Converted> convert(const TriangleMesh& mesh) {
    auto c = std::make_unique<Converted>();
    ConvertStats stats;
    c->doc = make_document(mesh, {}, &stats);
    c->model = CollisionModel(c->doc, mesh);
    c->protrusion = kDefaultProtrusion * mesh.diagonal();
    c->uncovered = stats.worst_predicted_gap;
    return c;
}

Eigen::Quaterniond random_rotation(std::mt19937& rng) {
    std::normal_distribution<double> n;
    return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
}

// The accuracy benchmark's random poses: 12 centre distances 0.2..2.4, random directions and turns.
std::vector<Pose> ring_poses(int per_ring, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> n;
    std::vector<Pose> out;
    for (int k = 1; k <= 12; ++k)
        for (int i = 0; i < per_ring; ++i) {
            const Eigen::Vector3d u = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
            out.push_back(Pose::from(0.2 * k * u, random_rotation(rng)));
        }
    return out;
}

std::vector<Pose> box_poses(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Pose> out;
    for (int i = 0; i < count; ++i) {
        const Eigen::Vector3d t(lo.x() + u(rng) * (hi.x() - lo.x()), lo.y() + u(rng) * (hi.y() - lo.y()),
                                lo.z() + u(rng) * (hi.z() - lo.z()));
        out.push_back(Pose::from(t, random_rotation(rng)));
    }
    return out;
}

// A row of the table: FCL's distance, or spt's with these options.
struct Method {
    std::string name;
    std::optional<DistanceOptions> spt;         // none: FCL
    std::vector<double> answer, ns;             // a pose's distance (+inf beyond a maximum), best time
    std::vector<double> node_pairs, leaf_tests; // spt: a pose's counters
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2];
}
double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0 : s / double(v.size());
}
std::string time_text(double ns) {
    char b[32];
    if (ns >= 1e6) std::snprintf(b, sizeof b, "%.2f ms", ns / 1e6);
    else if (ns >= 1e3) std::snprintf(b, sizeof b, "%.2f µs", ns / 1e3);
    else std::snprintf(b, sizeof b, "%.0f ns", ns);
    return b;
}

void run_case(const Case& c, int rounds, double relative_error) {
    const auto ca = convert(c.a), cb = convert(c.b);
    const bench::FclPeer fcl(c.a, c.b);
    const double diag = std::max(c.a.diagonal(), c.b.diagonal());
    const double margin = 0.01 * diag; // max_distance of the "planner's margin" rows
    QueryScratch scratch;
    const double inf = std::numeric_limits<double>::infinity();
    auto row = [&](std::string name, QueryLevel level, double max_distance, double absolute_error = 0,
                   bool depth = true) {
        DistanceOptions o;
        o.level = level;
        o.max_distance = max_distance;
        o.absolute_error = absolute_error;
        o.depth = depth;
        o.relative_error = relative_error;
        return Method{std::move(name), o, {}, {}, {}, {}};
    };
    // The spheres' own accuracy: no need to tell apart gaps closer than what sampling leaves uncovered.
    const double sampling = ca->uncovered + cb->uncovered;
    std::vector<Method> methods = {
        {"FCL distance (OBBRSS)", std::nullopt, {}, {}, {}, {}},
        row("spt exact", QueryLevel::Exact, inf),
        row("spt spheres", QueryLevel::Spheres, inf),
        row("spt exact, max 1% of diagonal", QueryLevel::Exact, margin),
        row("spt spheres, max 1% of diagonal", QueryLevel::Spheres, margin),
        row("spt spheres, absolute error = uncovered depths", QueryLevel::Spheres, inf, sampling),
        // Without depth (DistanceOptions::depth): overlapping poses answer 0 at once, as FCL's do.
        row("spt exact, no depth", QueryLevel::Exact, inf, 0, false),
        row("spt spheres, no depth", QueryLevel::Spheres, inf, 0, false),
        row("spt exact, max 1%, no depth", QueryLevel::Exact, margin, 0, false),
        row("spt spheres, max 1%, no depth", QueryLevel::Spheres, margin, 0, false),
    };
    const size_t n = c.poses.size();
    for (Method& m : methods) m.answer.assign(n, 0), m.ns.assign(n, inf), m.node_pairs.assign(n, 0), m.leaf_tests.assign(n, 0);
    // Interleaved rounds: every method through every pose, then again; a pose's time is its best.
    for (int r = 0; r < rounds; ++r)
        for (Method& m : methods) {
            for (size_t i = 0; i < n; ++i) {
                DistanceResult d;
                const auto t0 = Clock::now();
                if (m.spt) d = distance_relative(ca->model, cb->model, c.poses[i], *m.spt, scratch);
                else d.distance = fcl.distance(c.poses[i]);
                const double ns = double(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count());
                m.ns[i] = std::min(m.ns[i], ns);
                m.answer[i] = d.beyond ? inf : d.distance;
                m.node_pairs[i] = double(d.counters.node_pairs);
                m.leaf_tests[i] = double(d.counters.sphere_tests + d.counters.triangle_tests);
            }
        }

    const std::vector<double>& truth = methods[0].answer;
    const double tol = 1e-6 * diag;
    // Poses where one object lies inside the other's closed part without the surfaces meeting: FCL
    // (and spt exact) measure the surfaces' gap, the spheres fill the solids and overlap.
    std::vector<bool> contained(n, false);
    size_t contained_count = 0;
    QueryOptions solid;
    solid.level = QueryLevel::Exact;
    for (size_t i = 0; i < n; ++i)
        if (truth[i] > 0 && collide_relative(ca->model, cb->model, c.poses[i], solid, scratch).collide)
            contained[i] = true, ++contained_count;
    const double below = ca->protrusion + cb->protrusion, above = ca->uncovered + cb->uncovered;
    size_t apart = 0, near = 0;
    for (double d : truth) apart += d > 0, near += d > 0 && d < margin;
    std::printf("### %s\n\nA: %zu triangles, %zu samples; B: %zu triangles, %zu samples; %zu poses, %zu apart, "
                "%zu within 1%% of the diagonal (%.6g), %zu with one inside the other; %d interleaved rounds, each pose's best; spt's relative error allowance %g.\n"
                "Spheres' bound: from %.3g below FCL's distance (the protrusions) to %.3g above it (the largest "
                "uncovered depths).\n\n",
                c.name.c_str(), c.a.triangles.size(), ca->doc.samples.size(), c.b.triangles.size(), cb->doc.samples.size(),
                n, apart, near, diag, contained_count, rounds, relative_error, below, above);
    std::printf("| query | agrees with FCL | worst error / diagonal | median | mean | FCL median / this | FCL mean / this "
                "| apart: median, FCL / this | meeting: median, FCL / this | apart: node pairs, leaf tests (medians) | meeting: node pairs, leaf tests |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|\n");
    const double fcl_med = median(methods[0].ns), fcl_mean = mean(methods[0].ns);
    // Times of the poses whose meshes are apart (meet) by FCL's answer.
    auto split = [&](const Method& m, bool meeting, const std::vector<double>& of) {
        std::vector<double> v;
        for (size_t i = 0; i < n; ++i)
            if ((truth[i] <= 0) == meeting) v.push_back(of[i]);
        return median(v);
    };
    for (const Method& m : methods) {
        const bool exact = m.spt && m.spt->level == QueryLevel::Exact;
        const bool capped = m.spt && std::isfinite(m.spt->max_distance);
        size_t agree = 0;
        double worst = 0;
        // A row with an absolute error allowance may answer that much above the spheres' gap.
        const double above_here = above + (m.spt ? m.spt->absolute_error : 0);
        for (size_t i = 0; i < n; ++i) {
            const double f = truth[i], d = m.answer[i];
            bool ok = true;
            if (!m.spt) {
                ok = true;
            } else if (capped && f >= margin + tol) {
                ok = std::isinf(d) || (!exact && d <= f + above); // beyond the margin: "more than max"
            } else if (exact) {
                // FCL gives 0 for meshes that meet; spt minus the depth of the deepest overlap.
                const double e = f > 0 ? std::abs(d - f) : std::max(d, 0.0);
                worst = std::max(worst, e / diag);
                ok = e <= tol;
            } else if (contained[i]) {
                ok = d <= f + above_here + tol; // the spheres fill the solids: they may overlap deeply
            } else if (f > 0) {
                ok = d >= f - below - tol && d <= f + above_here + tol;
                worst = std::max(worst, std::abs(d - f) / diag);
            } else {
                ok = d <= above_here + tol; // meshes meet: the spheres meet or nearly
            }
            agree += ok;
        }
        std::printf("| %s | %.2f%% | %.2g | %s | %s | %.2f | %.2f | %s, %.2f | %s, %.2f | %.0f, %.0f | %.0f, %.0f |\n", m.name.c_str(),
                    100.0 * double(agree) / double(n), worst, time_text(median(m.ns)).c_str(), time_text(mean(m.ns)).c_str(),
                    fcl_med / median(m.ns), fcl_mean / mean(m.ns), time_text(split(m, false, m.ns)).c_str(),
                    split(methods[0], false, methods[0].ns) / split(m, false, m.ns), time_text(split(m, true, m.ns)).c_str(),
                    split(methods[0], true, methods[0].ns) / split(m, true, m.ns), split(m, false, m.node_pairs),
                    split(m, false, m.leaf_tests), split(m, true, m.node_pairs), split(m, true, m.leaf_tests));
    }
    std::printf("\nmax_distance 1%% of the diagonal against none (mean): exact %.2fx, spheres %.2fx faster; "
                "without depth: exact %.2fx, spheres %.2fx\n\n",
                mean(methods[1].ns) / mean(methods[3].ns), mean(methods[2].ns) / mean(methods[4].ns),
                mean(methods[6].ns) / mean(methods[8].ns), mean(methods[7].ns) / mean(methods[9].ns));
    std::fflush(stdout);
}

int usage() {
    std::fprintf(stderr, "usage: distance_bench [--mesh torus|bracket|wuson] [--pair A_MESH B_MESH [--extents X0 Y0 Z0 X1 Y1 Z1]]\n"
                         "                      [--poses N] [--rounds R] [--seed S] [--relative-error E]\n"
                         "  without --pair: the accuracy benchmark's meshes (all three, or --mesh), N orientations a ring\n"
                         "  (12 rings; default 50); with --pair: N random poses of B (default 600) in A's box or EXTENTS;\n"
                         "  E: spt's relative error allowance (DistanceOptions::relative_error, default 0)\n");
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    std::string only, pa, pb;
    std::optional<std::array<double, 6>> extents;
    int poses = 0, rounds = 3;
    double relative_error = 0;
    unsigned seed = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) std::exit(usage());
            return argv[++i];
        };
        auto number = [&](long lo, long hi) {
            const std::string s = next();
            char* end = nullptr;
            const long v = std::strtol(s.c_str(), &end, 10);
            if (*end || v < lo || v > hi) std::exit(usage());
            return v;
        };
        if (a == "--mesh") only = next();
        else if (a == "--pair") pa = next(), pb = next();
        else if (a == "--extents") {
            std::array<double, 6> e{};
            for (double& x : e) {
                const std::string s = next();
                char* end = nullptr;
                x = std::strtod(s.c_str(), &end);
                if (*end || !std::isfinite(x)) return usage();
            }
            extents = e;
        } else if (a == "--poses") poses = int(number(1, 10000000));
        else if (a == "--relative-error") {
            const std::string v = next();
            char* end = nullptr;
            relative_error = std::strtod(v.c_str(), &end);
            if (*end || !(relative_error >= 0 && relative_error < 1)) return usage();
        } else if (a == "--rounds") rounds = int(number(1, 100));
        else if (a == "--seed") seed = unsigned(number(0, 4294967295L));
        else return usage();
    }
    try {
        std::vector<Case> cases;
        if (!pa.empty()) {
            Case c;
            c.a = import_mesh(pa).mesh, c.b = import_mesh(pb).mesh;
            c.name = std::filesystem::path(pa).filename().string() + " and " + std::filesystem::path(pb).filename().string();
            auto [lo, hi] = c.a.bounds();
            if (extents) lo = {(*extents)[0], (*extents)[1], (*extents)[2]}, hi = {(*extents)[3], (*extents)[4], (*extents)[5]};
            c.poses = box_poses(lo, hi, poses ? poses : 600, seed);
            cases.push_back(std::move(c));
        } else {
            std::vector<std::pair<std::string, TriangleMesh>> meshes;
            if (only.empty() || only == "torus") meshes.emplace_back("torus", make_torus(1.0, 0.35, 160, 72));
            if (only.empty() || only == "bracket") meshes.emplace_back("bracket", make_bracket());
            const std::string wuson = "/usr/share/assimp/models/PLY/Wuson.ply";
            if ((only.empty() || only == "wuson") && std::filesystem::exists(wuson))
                meshes.emplace_back("wuson", import_mesh(wuson).mesh);
            if (meshes.empty()) return usage();
            for (auto& [name, raw] : meshes) {
                Case c;
                c.name = name + " against itself";
                c.a = c.b = scale_to_unit_cube(raw);
                c.poses = ring_poses(poses ? poses : 50, seed);
                cases.push_back(std::move(c));
            }
        }
        for (const Case& c : cases) run_case(c, rounds, relative_error);
        return 0;
    } catch (const Error& e) {
        std::fprintf(stderr, "distance_bench: %s\n", e.what());
        return spt::cli::exit_code(e.kind());
    }
}
