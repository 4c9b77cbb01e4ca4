// Backtrack along the motion (paper §3-4-3, made exact for the sphere model).
#include "spt/response.hpp"
#include "query/pending_pose.hpp"
#include "query/backtrack_from.hpp"
#include "query/node_slab.hpp"
#include "query/query_run.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace spt {
namespace {

// Steps of 1% of the diagonal taken before giving up (100 diagonals plus the two extents).
constexpr int kMaxSteps = 10200;

// Steps of 1% of the larger diagonal from `start` (where the model collides), then bisection
// to 1e-6 of it: for the exact level, and for a sphere model held by containment alone.
// A step that starts past `max_distance` ends the search: the answer lies beyond it.
BacktrackResult by_bisection(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                             const Eigen::Vector3d& back, const QueryOptions& options, QueryScratch& scratch,
                             double max_distance, double start = 0, int queries = 0) {
    BacktrackResult r;
    r.queries = queries;
    QueryOptions q = options;
    q.mode = QueryMode::Any;
    auto collides = [&](double s) {
        Pose p = b_in_a;
        p.translation += s * back;
        ++r.queries;
        return collide_relative(a, b, p, q, scratch).collide;
    };
    if (start == 0 && !collides(0)) return r;
    double diag = std::max({a.diagonal(), b.diagonal(), 2 * a.extent(), 2 * b.extent()});
    if (!(diag > 0)) diag = std::max(1.0, start); // no size to step by (a point model): any length serves
    const double step = 0.01 * diag;
    // Bounded counts, not only lengths: far from s = 0 a step or a halving can be below
    // the rounding of s, and a loop on lengths alone would never end.
    double lo = start, hi = start + step;
    for (int k = 0; collides(hi); ++k) {
        lo = hi, hi += step;
        if (lo > max_distance) { // collides at lo: the answer is past it
            r.distance = lo;
            r.beyond = true;
            return r;
        }
        if (k >= kMaxSteps || !(hi > lo)) {
            r.converged = false;
            break;
        }
    }
    for (int k = 0; r.converged && hi - lo > 1e-6 * diag && k < 64; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break; // no double between them: as close as it gets
        (collides(mid) ? lo : hi) = mid;
    }
    r.distance = hi;
    r.beyond = hi > max_distance;
    return r;
}

// Rule Exact at levels bounds and spheres. Every pair overlapping at s keeps overlapping until
// its own exit root, so the model collides on [s, largest root): jump there (and a millionth
// of that pair's reach past it) and look again. Each look asks only for the largest root
// (collide_exit), not for every overlapping pair.
// `start_pairs`: the pairs at s = 0 when the caller has them (then that query is not run).
// A jump past `max_distance` ends the search: the answer is at least that jump.
// `first`: the first look's answer when the caller has it (then no look is made there).
BacktrackResult by_exit_roots(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                              const Eigen::Vector3d& back, const QueryOptions& options,
                              const std::vector<SpherePair>* start_pairs, QueryScratch& scratch,
                              double max_distance, const detail::ExitSearch* first = nullptr) {
    BacktrackResult r;
    const bool bounds = options.level == QueryLevel::Bounds;
    double s = 0;
    for (int it = 0; it < 100000; ++it) {
        Pose p = b_in_a;
        p.translation += s * back;
        detail::ExitSearch exit;
        exit.back = back;
        if (it == 0 && first) {
            exit = *first;
            ++r.queries;
        } else if (it == 0 && start_pairs) {
            // As collide_exit would answer from these pairs: B's centres moved as the walk's
            // exit roots move them, once a sphere (a sphere is in many pairs).
            const Eigen::Matrix3d rot = unit_rotation(p.rotation).toRotationMatrix();
            const Eigen::Vector3d t = local_translation(a, b, rot, p.translation); // the centres are local
            detail::SphereMemo<Eigen::Vector3d>& moved = detail::buffers_of(scratch).memo_b;
            moved.start(std::max(b.tree().nodes().size(), b.tree().sphere_count()));
            for (const SpherePair& pair : *start_pairs) {
                const Eigen::Vector3d ca = detail::pair_centre(a.tree(), bounds, pair.node_a, pair.a);
                const Eigen::Vector3d& cb = moved.get(pair.b, [&] {
                    return Eigen::Vector3d(rot * detail::pair_centre(b.tree(), bounds, pair.node_b, pair.b) + t);
                });
                const Eigen::Vector3d w = cb - ca;
                const double reach = pair.reach;
                // A pair that parts before the best root so far is skipped without its square root.
                if (exit.found && !detail::exit_may_reach(w, reach, back, exit.root)) continue;
                detail::keep_exit(exit, detail::exit_root(w, reach, back), reach);
            }
        } else {
            ++r.queries;
            if (!collide_exit(a, b, p, options, exit, scratch).collide) {
                r.distance = s;
                return r;
            }
            // Held by containment alone (no sphere pairs to solve): step out instead.
            if (!exit.found) return by_bisection(a, b, b_in_a, back, options, scratch, max_distance, s, r.queries);
        }
        const double next = s + std::max(0.0, exit.root) + 1e-6 * exit.reach;
        if (!(next > s) || !std::isfinite(next)) break; // s no longer moves: report unconverged
        if (next > max_distance) {
            r.distance = next;
            r.beyond = true;
            return r;
        }
        s = next;
    }
    r.converged = false;
    r.distance = s;
    return r;
}

// Whether two balls, centres w apart (B's minus A's) and radii summing to `reach`, meet at some
// shift past S as B moves by s * back (S >= 0), told without a square root: they meet somewhere
// on the line, and the middle of their chord lies past S or they still overlap at S.
bool meet_past(const Eigen::Vector3d& w, double reach, const Eigen::Vector3d& back, double S) {
    const double half_b = w.dot(back), w2 = w.squaredNorm(), r2 = reach * reach;
    if (!(half_b * half_b - w2 + r2 > 0)) return false;
    return -half_b > S || w2 + S * (2 * half_b + S) < r2;
}

// Their exit root, when they meet (meet_past).
double exit_of(const Eigen::Vector3d& w, double reach, const Eigen::Vector3d& back) {
    const double half_b = w.dot(back);
    return -half_b + std::sqrt(half_b * half_b - w.squaredNorm() + reach * reach);
}

// Rule Exact at level spheres for a deep overlap (spheres overlapping at s = 0): the largest
// exit root of every sphere pair along back, by branch and bound. A node pair's bounding balls
// part no earlier than any pair of spheres below, so node pairs are taken largest bound first and
// the search ends when the largest bound left is no later than the best root: it visits the node
// pairs that could part last, not every pair the overlap holds. The looks of by_exit_roots stop
// instead at the first shift where nothing overlaps; the two agree unless the models, once parted
// along back, would meet again (docs/queries.md). Sets `root` and `reach` as an ExitSearch; false
// when no pair meets past s = 0, or the answer must come from the looks alone: two-sided spheres
// or culling (which the looks apply pair by pair) or a grown sphere. The search ends at the first
// root whose jump passes `max_distance`: the backtrack then says only that it lies beyond. With an
// `allowance` (model units) node pairs that cannot part later than the best by more are skipped,
// and `upper` (never early, at most the allowance late) is where every pair has parted; the search
// then also starts from the two spheres that reach furthest along back, and ends once the best root
// is within the allowance of where the models' reaches along back part.
bool last_exit(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a, const Eigen::Vector3d& back,
               const QueryOptions& options, QueryScratch& scratch, double max_distance, double allowance,
               const SpherePair* seed, detail::ExitSearch& best, double& upper) {
    const CompactTree &ta = a.tree(), &tb = b.tree();
    if (options.level != QueryLevel::Spheres || options.normal_culling || options.inflate != 0 || ta.two_sided() ||
        tb.two_sided() || ta.nodes().empty() || tb.nodes().empty())
        return false;
    const QueryFrame f(a, b, b_in_a, 0);
    if (f.apart) return false;
    const std::vector<CompactNode>&an = ta.nodes(), &bn = tb.nodes();
    detail::ScratchBuffers& s = detail::buffers_of(scratch);
    auto node_centre = [](const CompactNode& n) {
        return Eigen::Vector3d(double(n.center[0]), double(n.center[1]), double(n.center[2]));
    };
    auto b_centre = [&](const CompactNode& n) -> Eigen::Vector3d { return f.Rd * node_centre(n) + f.td; };
    // Bounds widened by a millionth (of the radii and the offset) so that rounding of the
    // stored float centres and radii never prunes a pair that parts later.
    auto wide = [](const Eigen::Vector3d& w, double r) { return r + 1e-6 * (r + w.cwiseAbs().sum()); };
    best = detail::ExitSearch{};
    best.back = back;
    std::vector<detail::ScratchBuffers::ExitBound>& stack = s.exit_stack;
    stack.clear();
    // A node's spheres reach along a direction no further than its disc does (query/node_slab.hpp).
    const float *slab_a = detail::node_slab_of(a), *slab_b = detail::node_slab_of(b);
    const Eigen::Vector3f back_a = back.cast<float>(), back_b = f.R.transpose() * -back_a; // each in its model's frame
    auto support = [](const CompactNode& n, const float* slab, uint32_t i, const Eigen::Vector3f& u) {
        return double(detail::NodeShape::of(n.bv_radius, slab, i).support(u));
    };
    // The bound of node pair (i, j), B's centre less A's w: the exit root of their balls, or -1
    // when they do not meet past the best root; and no later than their discs part along back (a
    // pair of spheres has parted once B's lies beyond A's along it), far tighter than the balls
    // across the caps that part last.
    auto bound = [&](uint32_t i, uint32_t j, const Eigen::Vector3d& w) {
        const double r = wide(w, double(an[i].bv_radius) + double(bn[j].bv_radius));
        if (!meet_past(w, r, back, best.found ? best.root : 0.0)) return -1.0;
        const double discs = support(an[i], slab_a, i, back_a) + support(bn[j], slab_b, j, back_b) - w.dot(back) +
                             1e-5 * r + 1e-6 * w.cwiseAbs().sum();
        const double root = std::min(exit_of(w, r, back), discs);
        return best.found && !(root > best.root) ? -1.0 : root;
    };
    // With an allowance, pairs that cannot part later than the best by more are skipped; the
    // latest bound skipped so is kept: past `upper`, the later of it and the best root, nothing
    // overlaps, and it is at most the allowance late.
    double skipped = -1;
    // With an allowance, also how far the two models reach along back (spheres_support): once B
    // lies wholly beyond A along it every pair has parted, so that bounds every root, and it ends
    // the search as soon as the best root comes within the allowance of it (two convex-ish shapes
    // parted along the line of their deepest points: a walk of a few dozen node pairs).
    // Where sphere a of A's active node `na` and sphere b of B's active node `nb` part, kept as
    // the best root if they meet past s = 0: a start for the search.
    auto start_from = [&](uint32_t na, uint32_t sa, uint32_t nb, uint32_t sb) {
        const Eigen::Vector3d w =
            f.Rd * tb.sphere_center(bn[nb], sb).cast<double>() + f.td - ta.sphere_center(an[na], sa).cast<double>();
        const double reach = double(an[na].ss_radius + bn[nb].ss_radius);
        if (meet_past(w, reach, back, 0.0)) detail::keep_exit(best, exit_of(w, reach, back), reach);
    };
    double projected = std::numeric_limits<double>::infinity();
    if (allowance > 0) {
        const detail::SphereSupport sa = detail::spheres_support(ta, slab_a, back, s.support_heap);
        const detail::SphereSupport sb = detail::spheres_support(tb, slab_b, -(f.Rd.transpose() * back), s.support_heap);
        projected = sa.reach + sb.reach - f.td.dot(back) + 1e-6 * (a.extent() + b.extent());
        // The two spheres that reach furthest, A's along back and B's against it, part last when
        // the shapes meet in line.
        start_from(sa.node, sa.sphere, sb.node, sb.sphere);
    }
    if (seed && seed->node_a < an.size() && seed->node_b < bn.size()) { // the caller's start
        const CompactNode &na = an[seed->node_a], &nb = bn[seed->node_b];
        if (na.is_active() && nb.is_active() && seed->a - na.first < na.count && seed->b - nb.first < nb.count)
            start_from(seed->node_a, seed->a, seed->node_b, seed->b);
    }
    std::vector<Eigen::Vector3d>& moved = s.exit_leaf_b;
    moved.resize(b.max_leaf());
    if (const double r0 = bound(0, 0, b_centre(bn[0]) - node_centre(an[0])); r0 >= 0) stack.push_back({r0, 0, 0});
    // Depth first, the pair that parts later taken first: a late root comes early and prunes the
    // rest, with none of a priority queue's upkeep (which cost more than the walk).
    while (!stack.empty() && !(best.found && best.root + 1e-6 * best.reach > max_distance) &&
           !(best.found && projected <= best.root + allowance)) {
        const detail::ScratchBuffers::ExitBound top = stack.back();
        stack.pop_back();
        if (best.found && top.root <= best.root + allowance) {
            if (top.root > best.root) skipped = std::max(skipped, top.root);
            continue;
        }
        const CompactNode &na = an[top.a], &nb = bn[top.b];
        if (na.is_active() && nb.is_active()) {
            for (uint32_t q = 0; q < nb.count; ++q)
                moved[q] = f.Rd * tb.sphere_center(nb, nb.first + q).cast<double>() + f.td;
            const Eigen::Vector3d cb_node = b_centre(nb);
            const double reach = double(na.ss_radius + nb.ss_radius); // as the walk's float reach
            const double row_reach = double(na.ss_radius) + double(nb.bv_radius);
            for (uint32_t p = na.first; p < na.first + na.count; ++p) {
                const Eigen::Vector3d ca = ta.sphere_center(na, p).cast<double>();
                const double S = best.found ? best.root : 0.0;
                // B's spheres lie in its node's ball: a sphere of A that has parted from the ball
                // by the best root has parted from each of them.
                if (!meet_past(cb_node - ca, wide(cb_node - ca, row_reach), back, S)) continue;
                for (uint32_t q = 0; q < nb.count; ++q) {
                    const Eigen::Vector3d w = moved[q] - ca;
                    if (!meet_past(w, reach, back, best.found ? best.root : 0.0)) continue;
                    detail::keep_exit(best, exit_of(w, reach, back), reach);
                }
            }
            continue;
        }
        // The larger ball is split, as the walk splits it.
        const bool side_a = nb.is_active() || (!na.is_active() && na.bv_radius >= nb.bv_radius);
        const CompactNode& split = side_a ? na : nb;
        const uint32_t at = side_a ? top.a : top.b;
        double key[2];
        const uint32_t child[2] = {at + 1, split.first};
        // No later than the parent's bound either (a child's ball can poke out of its parent's).
        for (int k = 0; k < 2; ++k)
            key[k] = std::min(top.root, side_a ? bound(child[k], top.b, b_centre(nb) - node_centre(an[child[k]]))
                                               : bound(top.a, child[k], b_centre(bn[child[k]]) - node_centre(na)));
        const int later = key[1] > key[0] ? 1 : 0; // pushed last, taken first
        for (const int k : {1 - later, later})
            if (key[k] >= 0)
                stack.push_back(side_a ? detail::ScratchBuffers::ExitBound{key[k], child[k], top.b}
                                      : detail::ScratchBuffers::ExitBound{key[k], top.a, child[k]});
    }
    // Every pair not walked was skipped within the allowance, or lies below `projected`.
    upper = std::max(best.root, stack.empty() ? std::min(skipped, projected) : projected);
    return best.found;
}

// Any finite non-zero motion gives a direction: scaled by its largest component before
// normalising, so 1e-300 and 1e300 are directions like 1. Zero without one.
Eigen::Vector3d back_direction(const Eigen::Vector3d& motion) {
    const double big = motion.cwiseAbs().maxCoeff();
    if (!(big > 0) || !std::isfinite(big)) return Eigen::Vector3d::Zero();
    return -(motion / big).normalized();
}

// backtrack_relative; `start_pairs` (may be null) as for backtrack_from_pairs, `deep` as for
// deep_backtrack.
BacktrackResult relative(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                         const Eigen::Vector3d& motion_in_a, const QueryOptions& options, BacktrackRule rule,
                         const std::vector<SpherePair>* start_pairs, QueryScratch& scratch, double max_distance,
                         bool deep = false, double allowance = 0, const SpherePair* seed = nullptr) {
    detail::settle(a), detail::settle(b); // a lazy pose is posed in full first
    BacktrackResult r;
    const Eigen::Vector3d back = back_direction(motion_in_a);
    if (back.isZero()) return r; // no motion: no direction to move back along
    QueryOptions q = options;
    if (rule == BacktrackRule::Paper) {
        q.mode = QueryMode::Deepest;
        const QueryResult res = collide_relative(a, b, b_in_a, q, scratch);
        r.queries = 1;
        r.distance = res.collide ? std::max(0.0, res.deepest.depth) : 0;
        r.beyond = r.distance > max_distance;
        return r;
    }
    if (options.level == QueryLevel::Exact) return by_bisection(a, b, b_in_a, back, options, scratch, max_distance);
    // A deep overlap's first jump goes straight to the last exit of every pair, past the jumps
    // the looks would make through the overlap; the looks then go on from there.
    detail::ExitSearch last;
    double upper = 0;
    if (deep && last_exit(a, b, b_in_a, back, options, scratch, max_distance, allowance, seed, last, upper)) {
        // Every sphere pair has parted by `upper` (in double, from widened bounds): the look there
        // would only confirm it. Past it by a hundred-thousandth of the models' extents, beyond the
        // walks' float rounding, so that a query there finds them apart too. Unless `upper` passes
        // max_distance while the best root does not: then the looks tell which side it lies.
        const double jump = std::max(0.0, upper) + 1e-6 * last.reach + 1e-5 * (a.extent() + b.extent());
        if (allowance > 0 && (jump <= max_distance || last.root + 1e-6 * last.reach > max_distance)) {
            r.queries = 1;
            r.distance = jump;
            r.beyond = jump > max_distance;
            return r;
        }
        return by_exit_roots(a, b, b_in_a, back, options, nullptr, scratch, max_distance, &last);
    }
    return by_exit_roots(a, b, b_in_a, back, options, start_pairs, scratch, max_distance);
}

// backtrack; `start_pairs` (may be null) as for backtrack_from_pairs, `deep` as for deep_backtrack.
BacktrackResult in_world(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                         const Eigen::Vector3d& motion, const QueryOptions& options, BacktrackRule rule,
                         const std::vector<SpherePair>* start_pairs, QueryScratch& scratch, double max_distance,
                         bool deep = false, double allowance = 0, const SpherePair* seed = nullptr) {
    detail::settle(a), detail::settle(b); // a lazy pose is posed in full first
    check_pose(pose_a, "pose of A");
    check_pose(pose_b, "pose of B");
    const Pose ua{unit_rotation(pose_a.rotation), pose_a.translation};
    const Pose ub{unit_rotation(pose_b.rotation), pose_b.translation};
    return relative(a, b, relative_pose(ua, ub), ua.rotation.conjugate() * motion, options, rule, start_pairs, scratch,
                    max_distance, deep, allowance, seed);
}

} // namespace

BacktrackResult backtrack_relative(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                                   const Eigen::Vector3d& motion_in_a, const QueryOptions& options,
                                   BacktrackRule rule, QueryScratch& scratch, double max_distance) {
    return relative(a, b, b_in_a, motion_in_a, options, rule, nullptr, scratch, max_distance);
}

BacktrackResult backtrack(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                          const Eigen::Vector3d& motion, const QueryOptions& options, BacktrackRule rule,
                          QueryScratch& scratch, double max_distance) {
    return in_world(a, pose_a, b, pose_b, motion, options, rule, nullptr, scratch, max_distance);
}

} // namespace spt

namespace spt::detail {

BacktrackResult backtrack_from_pairs(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b,
                                     const Pose& pose_b, const Eigen::Vector3d& motion, const QueryOptions& options,
                                     const std::vector<SpherePair>& start_pairs, QueryScratch& scratch,
                                     double max_distance) {
    return in_world(a, pose_a, b, pose_b, motion, options, BacktrackRule::Exact, &start_pairs, scratch, max_distance);
}

BacktrackResult deep_backtrack(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                               const Eigen::Vector3d& motion, const QueryOptions& options, QueryScratch& scratch,
                               double max_distance, double allowance, const SpherePair* seed) {
    return in_world(a, pose_a, b, pose_b, motion, options, BacktrackRule::Exact, nullptr, scratch, max_distance, true,
                    allowance, seed);
}

} // namespace spt::detail
