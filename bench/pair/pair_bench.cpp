// pair_bench A B: two different meshes (e.g. a robot and its environment, open soups
// allowed) at random poses inside A's bounding box, as FCL's own test suite poses them.
// Prints how often each level agrees with the exact level and the median time of each,
// next to FCL in the same run. Figures and commands: docs/hard-cases.md.
#include "exit_code.hpp"
#include "peers.hpp"
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "spt/query.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace spt;
using Clock = std::chrono::steady_clock;

struct Row {
    std::string name;
    std::vector<bool> answers;
    std::vector<double> ns;
};

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, size_t(q * double(v.size())))];
}

std::string time_text(double ns) {
    char b[32];
    if (ns >= 1e6) std::snprintf(b, sizeof b, "%.2f ms", ns / 1e6);
    else if (ns >= 1e3) std::snprintf(b, sizeof b, "%.2f us", ns / 1e3);
    else std::snprintf(b, sizeof b, "%.0f ns", ns);
    return b;
}

// Median of `repeat` timed calls; the answer of the last.
bool timed(const std::function<bool()>& f, int repeat, double& ns) {
    std::vector<double> t(static_cast<size_t>(repeat));
    bool answer = false;
    for (auto& x : t) {
        const auto t0 = Clock::now();
        answer = f();
        x = double(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count());
    }
    std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
    ns = t[t.size() / 2];
    return answer;
}

int usage() {
    std::fprintf(stderr, "usage: pair_bench A_MESH B_MESH [--poses N] [--seed S] [--repeat K]\n");
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> files;
    int poses = 2000, repeat = 5;
    unsigned seed = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto number = [&](long lo, long hi) {
            if (i + 1 >= argc) std::exit(usage());
            char* end = nullptr;
            const long v = std::strtol(argv[++i], &end, 10);
            if (*end || v < lo || v > hi) std::exit(usage());
            return v;
        };
        if (a == "--poses") poses = int(number(1, 10000000));
        else if (a == "--seed") seed = unsigned(number(0, 4294967295L));
        else if (a == "--repeat") repeat = int(number(1, 1000));
        else if (!a.empty() && a[0] == '-') return usage();
        else files.push_back(a);
    }
    if (files.size() != 2) return usage();
    try {
        const ImportedMesh ma = import_mesh(files[0]), mb = import_mesh(files[1]);
        const auto t0 = Clock::now();
        const SptDocument da = make_document(ma.mesh), db = make_document(mb.mesh);
        const double convert_s = std::chrono::duration<double>(Clock::now() - t0).count();
        const CollisionModel a(da, ma.mesh), b(db, mb.mesh);
        const bench::FclPeer fcl(ma.mesh, mb.mesh);

        // B anywhere in A's bounding box, any orientation: FCL's test-suite protocol.
        const auto [lo, hi] = ma.mesh.bounds();
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(0, 1);
        std::normal_distribution<double> n;
        std::vector<Pose> pose(static_cast<size_t>(poses));
        for (auto& p : pose) {
            const Eigen::Vector3d t(lo.x() + u(rng) * (hi.x() - lo.x()), lo.y() + u(rng) * (hi.y() - lo.y()),
                                    lo.z() + u(rng) * (hi.z() - lo.z()));
            p = Pose::from(t, Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)));
        }

        QueryScratch scratch;
        std::vector<Row> rows;
        for (QueryLevel level : {QueryLevel::Exact, QueryLevel::Spheres, QueryLevel::Bounds}) {
            QueryOptions o;
            o.level = level;
            Row r{query_level_name(level), {}, {}};
            for (const Pose& p : pose) {
                double ns = 0;
                r.answers.push_back(timed([&] { return collide_relative(a, b, p, o, scratch).collide; }, repeat, ns));
                r.ns.push_back(ns);
            }
            rows.push_back(std::move(r));
        }
        Row f{"FCL (OBBRSS)", {}, {}};
        for (const Pose& p : pose) {
            double ns = 0;
            f.answers.push_back(timed([&] { return fcl.collide(p); }, repeat, ns));
            f.ns.push_back(ns);
        }
        rows.push_back(std::move(f));

        const Row& exact = rows[0];
        size_t colliding = 0;
        for (bool c : exact.answers) colliding += c;
        std::printf("A: %s (%zu triangles, %s, %zu samples); B: %s (%zu triangles, %s, %zu samples); conversion %.2f s\n",
                    ma.mesh.name.c_str(), ma.mesh.triangles.size(), ma.report.closed ? "closed" : "open", da.samples.size(),
                    mb.mesh.name.c_str(), mb.mesh.triangles.size(), mb.report.closed ? "closed" : "open", db.samples.size(),
                    convert_s);
        std::printf("%d random poses in A's bounding box (seed %u), %zu colliding at the exact level; times: median of %d "
                    "runs per pose\n\n",
                    poses, seed, colliding, repeat);
        std::printf("| query | agrees with exact | false positives | false negatives | median | 90th percentile |\n");
        std::printf("|---|---|---|---|---|---|\n");
        for (const Row& r : rows) {
            size_t agree = 0, fp = 0, fn = 0;
            for (size_t i = 0; i < r.answers.size(); ++i) {
                agree += r.answers[i] == exact.answers[i];
                fp += r.answers[i] && !exact.answers[i];
                fn += !r.answers[i] && exact.answers[i];
            }
            std::printf("| %s | %.2f%% | %zu | %zu | %s | %s |\n", r.name.c_str(), 100.0 * double(agree) / double(poses), fp,
                        fn, time_text(percentile(r.ns, 0.5)).c_str(), time_text(percentile(r.ns, 0.9)).c_str());
        }
        const double fcl_med = percentile(rows.back().ns, 0.5);
        std::printf("\nmedian time against FCL: exact %.2fx faster, spheres %.2fx faster\n",
                    fcl_med / percentile(rows[0].ns, 0.5), fcl_med / percentile(rows[1].ns, 0.5));
        return 0;
    } catch (const Error& e) {
        std::fprintf(stderr, "pair_bench: %s\n", e.what());
        return spt::cli::exit_code(e.kind());
    }
}
