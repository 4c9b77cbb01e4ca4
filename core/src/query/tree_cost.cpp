// Cost runs: random and near-contact poses, timed as `spt query --repeat` times them.
#include "spt/tree_cost.hpp"
#include "query/pending_pose.hpp"
#include "spt/error.hpp"
#include "spt/query_scratch.hpp"
#include "base/cancel.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

namespace spt {
namespace {

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    // One draw a statement: the order of a call's arguments is the compiler's choice, and a
    // seed must give the same poses from every build. z first: the order of the poses before.
    const double z = g(rng), y = g(rng), x = g(rng), w = g(rng);
    Eigen::Quaterniond q(w, x, y, z);
    return q.norm() > 1e-9 ? q.normalized() : Eigen::Quaterniond::Identity();
}

Eigen::Vector3d random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    for (;;) {
        const double z = g(rng), y = g(rng), x = g(rng); // as in random_rotation
        const Eigen::Vector3d v(x, y, z);
        if (v.norm() > 1e-9) return v.normalized();
    }
}

// Distance along `u` at which B (rotated by q) first touches A coming in from outside: the
// first colliding sample of a march inwards from where the bounding spheres are apart, then
// bisection to 1e-6 of `reach`. Negative if B never touches A along this line.
double contact_distance(const CollisionModel& a, const CollisionModel& b, const Eigen::Vector3d& u,
                        const Eigen::Quaterniond& q, double reach, const QueryOptions& o, QueryScratch& s) {
    auto collides = [&](double d) { return collide_relative(a, b, Pose::from(d * u, q), o, s).collide; };
    constexpr int kMarch = 64;
    double outside = reach, inside = -1;
    for (int k = 1; k <= kMarch; ++k) {
        const double d = reach * (1.0 - double(k) / kMarch);
        if (collides(d)) {
            inside = d;
            break;
        }
        outside = d;
    }
    if (inside < 0) return -1;
    for (int k = 0; k < 60 && outside - inside > 1e-6 * reach; ++k) {
        const double mid = 0.5 * (inside + outside);
        (collides(mid) ? inside : outside) = mid;
    }
    return outside;
}

CostFigures run(const CollisionModel& a, const CollisionModel& b, const std::vector<Pose>& poses,
                const CostOptions& o, QueryScratch& s, const std::atomic<bool>* cancel,
                const std::function<void()>& tick, bool* cancelled) {
    CostFigures f;
    std::vector<int64_t> medians, times(size_t(std::max(1, o.repeats)));
    size_t colliding = 0;
    double node_pairs = 0, sphere_tests = 0;
    for (const Pose& p : poses) {
        if (detail::cancel_requested(cancel)) {
            *cancelled = true;
            break;
        }
        QueryResult r;
        for (int64_t& ns : times) {
            const auto t0 = std::chrono::steady_clock::now();
            r = collide_relative(a, b, p, o.query, s);
            ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
        }
        std::nth_element(times.begin(), times.begin() + long(times.size() / 2), times.end());
        medians.push_back(times[times.size() / 2]);
        f.counters.push_back(r.counters);
        colliding += r.collide;
        node_pairs += double(r.counters.node_pairs);
        sphere_tests += double(r.counters.sphere_tests);
        if (tick) tick();
    }
    if (medians.empty()) return f;
    const double n = double(medians.size());
    std::nth_element(medians.begin(), medians.begin() + long(medians.size() / 2), medians.end());
    f.median_ns = double(medians[medians.size() / 2]);
    f.mean_node_pairs = node_pairs / n;
    f.mean_sphere_tests = sphere_tests / n;
    f.collide_share = double(colliding) / n;
    return f;
}

} // namespace

CostPoses cost_poses(const CollisionModel& a, const CollisionModel& b, const CostOptions& o) {
    detail::settle(a), detail::settle(b); // a lazy pose is posed in full first
    if (o.random_poses < 0 || o.near_poses < 0 || o.random_poses > 1000000 || o.near_poses > 1000000)
        throw Error(ErrorKind::BadInput, "cost run: pose counts must be 0 to 1,000,000");
    CostPoses out;
    std::mt19937_64 rng(o.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0), jitter(-0.01, 0.01);
    // Reach: B's origin farther than this from A's leaves the two models apart.
    const double reach = a.extent() + b.extent() + a.origin().norm() + b.origin().norm();
    for (int i = 0; i < o.random_poses; ++i) {
        const double r = std::cbrt(unit(rng)); // drawn before the direction, as before
        const Eigen::Vector3d t = random_unit(rng) * reach * r;
        out.random.push_back(Pose::from(t, random_rotation(rng)));
    }
    QueryOptions find = o.query;
    find.mode = QueryMode::Any;
    QueryScratch s;
    const double diagonal = std::max(a.diagonal(), b.diagonal());
    // Directions along which B never touches A (an empty model) are skipped, with a bound on tries.
    for (int tries = 0; int(out.near.size()) < o.near_poses && tries < 4 * o.near_poses + 16; ++tries) {
        const Eigen::Vector3d u = random_unit(rng);
        const Eigen::Quaterniond q = random_rotation(rng);
        const double d = contact_distance(a, b, u, q, reach, find, s);
        const double move = jitter(rng) * diagonal;
        if (d < 0) continue;
        out.near.push_back(Pose::from((d + move) * u, q));
    }
    return out;
}

TreeCost measure_cost(const CollisionModel& a, const CollisionModel& b, const CostPoses& poses,
                      const CostOptions& o, const std::atomic<bool>* cancel,
                      const std::function<void(double)>& progress) {
    detail::settle(a), detail::settle(b); // a lazy pose is posed in full first
    TreeCost c;
    c.memory_bytes = a.memory_bytes();
    QueryScratch s;
    const size_t total = poses.random.size() + poses.near.size();
    size_t done = 0;
    const std::function<void()> tick = [&] {
        ++done;
        if (progress && (done % 16 == 0 || done == total)) progress(double(done) / double(std::max<size_t>(total, 1)));
    };
    c.random = run(a, b, poses.random, o, s, cancel, tick, &c.cancelled);
    if (!c.cancelled) c.near = run(a, b, poses.near, o, s, cancel, tick, &c.cancelled);
    return c;
}

} // namespace spt
