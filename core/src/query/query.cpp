// Tree-against-tree collision query (paper §3-4-2) with lazy update, normal
// culling, three levels and three modes. Everything happens in A's frame.
#include "spt/query.hpp"
#include "spt/error.hpp"
#include "geometry/sphere_block.hpp"
#include "query/exact_data.hpp"
#include "query/lanes.hpp"
#include "query/pending_pose.hpp"
#include <algorithm>
#include <cstring>
#include <cmath>
#include <limits>

namespace spt {

using detail::b_to_a;
using detail::movemask;
using detail::splat;
using detail::v4f;
using detail::v4i;

namespace {

// Lanes swapped in pairs (1 0 3 2) and in halves (2 3 0 1); GCC and clang spell it apart
// (clang builds the fuzz targets).
#if defined(__clang__)
v4f swap_pairs(v4f v) { return __builtin_shufflevector(v, v, 1, 0, 3, 2); }
v4f swap_halves(v4f v) { return __builtin_shufflevector(v, v, 2, 3, 0, 1); }
#else
v4f swap_pairs(v4f v) { return __builtin_shuffle(v, v4i{1, 0, 3, 2}); }
v4f swap_halves(v4f v) { return __builtin_shuffle(v, v4i{2, 3, 0, 1}); }
#endif

// Lane of the smallest value among the lanes set in `mask`, or -1 if none is set.
int lane_of_min(v4f v, v4i mask) {
    v4f m = v < swap_pairs(v) ? v : swap_pairs(v);
    m = m < swap_halves(m) ? m : swap_halves(m);
    const v4i hit = (v == m) & mask;
    const int bits = movemask(hit);
    return bits ? __builtin_ctz(unsigned(bits)) : -1; // no branch per lane
}

constexpr uint32_t kActive = 0x80000000u; // a stack reference to an active node
constexpr float kLooseWeight = 3; // measured: 1.5, 2 and 4 walked more node pairs (docs/deforming.md)
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// The children of inner node i, with each inner child replaced by its own two
// children: two to four nodes tested in one 4-lane step, so a walk to a leaf takes
// half the steps. Lanes 0-1 come from the left child, 2-3 from the right; a child
// that is active fills one lane and leaves the other empty (a NaN centre fails every
// test). Fixed slots instead of packing the lanes: packing branched on whether each
// child is a leaf, a coin toss near the bottom of the tree, and a mispredicted branch
// costs more than the step.
struct Grandchildren {
    v4f x, y, z, r;
    uint32_t ref[4];
    uint32_t count = 4;
    Grandchildren(const std::vector<CompactNode>& nodes, uint32_t i, const float* reach) {
        static const CompactNode none = {{kNaN, kNaN, kNaN}, 0, 0, 0, 0, 0};
        const CompactNode* base = nodes.data();
        const CompactNode* n[4];
        uint32_t idx[4];
        const uint32_t child[2] = {i + 1, base[i].first};
        for (int h = 0; h < 2; ++h) {
            const uint32_t c = child[h];
            const bool active = base[c].count != 0;
            idx[2 * h] = active ? c : c + 1;
            idx[2 * h + 1] = active ? 0 : base[c].first; // 0: any valid index for the empty lane
            n[2 * h] = base + idx[2 * h];
            n[2 * h + 1] = active ? &none : base + idx[2 * h + 1];
            count -= active;
        }
        float lr[4];
        for (int k = 0; k < 4; ++k) {
            ref[k] = idx[k] | (n[k]->count != 0 ? kActive : 0);
            lr[k] = reach ? reach[idx[k]] : n[k]->bv_radius;
        }
        // Built from scalars, not loaded from the scalar stores above (a wide load of
        // narrow stores stalls).
        x = v4f{n[0]->center[0], n[1]->center[0], n[2]->center[0], n[3]->center[0]};
        y = v4f{n[0]->center[1], n[1]->center[1], n[2]->center[1], n[3]->center[1]};
        z = v4f{n[0]->center[2], n[1]->center[2], n[2]->center[2], n[3]->center[2]};
        r = v4f{lr[0], lr[1], lr[2], lr[3]};
    }
    explicit Grandchildren(const detail::NodeGroup& g) : count(g.count) {
        std::memcpy(&x, g.x, sizeof x), std::memcpy(&y, g.y, sizeof y), std::memcpy(&z, g.z, sizeof z);
        std::memcpy(&r, g.r, sizeof r), std::memcpy(ref, g.ref, sizeof ref);
    }
    void store(detail::NodeGroup& g) const {
        std::memcpy(g.x, &x, sizeof x), std::memcpy(g.y, &y, sizeof y), std::memcpy(g.z, &z, sizeof z);
        std::memcpy(g.r, &r, sizeof r), std::memcpy(g.ref, ref, sizeof ref);
        g.count = count;
    }
};

// B's inner node i's group moved into A's frame, made once a query and kept (a small model's
// node of B meets many of A's).
Grandchildren cached_b_group(const QueryFrame& f, detail::ScratchBuffers& s, const std::vector<CompactNode>& nodes,
                             uint32_t i, const float* reach) {
    if (s.b_group_stamp[i] == s.epoch) return Grandchildren(s.b_groups[i]);
    Grandchildren w(nodes, i, reach);
    b_to_a(f, w.x, w.y, w.z);
    s.b_group_stamp[i] = s.epoch, w.store(s.b_groups[i]);
    return w;
}

// The stack is a scratch vector used up to `size`; it grows (rarely) by doubling.
struct VisitStack {
    std::vector<detail::NodePairVisit>& buf;
    size_t size = 0;
    void make_room(size_t n) {
        if (size + n > buf.size()) buf.resize(2 * buf.size() + n);
    }
};

// Field by field: a visit built whole on the stack and copied with wide moves makes
// the copy wait on narrower stores (store forwarding fails; this doubled the time of
// a walk to a contact).
void push_visit(VisitStack& stack, uint32_t a, uint32_t b, float ax, float ay, float az, const Eigen::Vector3f& cb,
                float ra, float rb, float d2, float cap) {
    detail::NodePairVisit& v = stack.buf[stack.size++];
    v.a = a, v.b = b;
    v.ca[0] = ax, v.ca[1] = ay, v.ca[2] = az;
    v.cb[0] = cb.x(), v.cb[1] = cb.y(), v.cb[2] = cb.z();
    v.ra = ra, v.rb = rb, v.d2 = d2, v.cap = cap;
}

} // namespace

void QueryRun::run() {
    const auto &an = A.tree().nodes(), &bn = B.tree().nodes();
    if (an.empty() || bn.empty()) return;
    const bool bounds = o.level == QueryLevel::Bounds;
    const bool any = o.mode == QueryMode::Any, deepest = o.mode == QueryMode::Deepest;
    const float* reach_a = bounds ? A.bounds_reach().data() : nullptr;
    const float* reach_b = bounds ? B.bounds_reach().data() : nullptr;
    const float pad = o.inflate + f.margin;
    const bool flat = !bounds && (A.tree().node_disc() || B.tree().node_disc());
    const float *disc_a = A.tree().node_disc(), *disc_b = B.tree().node_disc();
    const float* max_r_a = bounds ? nullptr : detail::node_max_radius_of(A);
    const float* max_r_b = max_r_a ? detail::node_max_radius_of(B) : nullptr;
    if (!max_r_b) max_r_a = nullptr;
    // Most node pairs have no disc on either side (h < 0): told here, without the call.
    auto node_is_disc = [](const float* disc, uint32_t ref) { return disc && disc[4 * size_t(ref & ~kActive) + 3] >= 0; };
    // Lazily posed models: a part is posed before the walk first reads below it.
    detail::PendingPose *lazy_a = detail::pending_of(A), *lazy_b = detail::pending_of(B);
    VisitStack stack{s.visits};
    // Every pair on the stack overlaps: it was tested when pushed, four children at a
    // time, and the same distances order the descent.
    // The pair in hand (the root first, then the child taken next: in mode any the nearest,
    // in an exit search the one likely to part last, else the one the stack would give back
    // first) stays in registers instead of going through the stack: a store and a load less a step.
    uint32_t ref_a = an[0].is_active() ? kActive : 0, ref_b = bn[0].is_active() ? kActive : 0;
    Eigen::Vector3f ca(an[0].center[0], an[0].center[1], an[0].center[2]), cb = b_node_centre(0);
    float ra = reach_a ? reach_a[0] : an[0].bv_radius, rb = reach_b ? reach_b[0] : bn[0].bv_radius;
    float d2 = (ca - cb).squaredNorm();
    ++res.counters.bound_tests;
    if (const float prune = ra + rb + pad; d2 > prune * prune) return;
    roots_overlap = true;
    // Mode deepest: the depth bound of the pair in hand, no more than its ancestors' (a child's
    // ball can poke out of its parent's). The descent takes the deepest-bounded child first, so
    // that a pair near the deepest comes early and its depth prunes the rest (and an allowance
    // the near-ties).
    float cap = std::numeric_limits<float>::infinity();
    bool carried = true;
    for (;;) {
        if (!carried) {
            if (stack.size == 0) break;
            const detail::NodePairVisit& top = stack.buf[--stack.size];
            ref_a = top.a, ref_b = top.b;
            ca = Eigen::Vector3f(top.ca[0], top.ca[1], top.ca[2]);
            cb = Eigen::Vector3f(top.cb[0], top.cb[1], top.cb[2]);
            ra = top.ra, rb = top.rb, d2 = top.d2, cap = top.cap;
        }
        carried = false;
        ++res.counters.node_pairs;
        // Exit search: no pair below can leave later than its bounding balls part.
        if (exit && exit->found && !may_exit_later(ca, cb, ra, rb, pad)) continue;
        // Deepest: no sphere below this pair can be deeper than the bounds' overlap.
        // Nor deeper than their largest spheres' radii together: once the balls lie deep in each
        // other, that is the bound that prunes.
        if (deepest) {
            cap = std::min(cap, ra + rb + pad - std::sqrt(d2));
            if (max_r_a) cap = std::min(cap, max_r_a[ref_a & ~kActive] + max_r_b[ref_b & ~kActive] + pad);
            if (have_best && !(cap > float(res.deepest.depth) + deepest_slack)) continue;
        }
        // Flat nodes of two-sided spheres are discs: two sheets side by side are apart here,
        // not after a walk down to every pair of their leaves.
        if (flat && node_is_disc(disc_a, ref_a) | node_is_disc(disc_b, ref_b) &&
            !node_discs_touch(ref_a & ~kActive, ref_b & ~kActive, ca, cb, ra, rb))
            continue;
        const bool leaf_a = ref_a & kActive, leaf_b = ref_b & kActive;
        if (leaf_a && leaf_b) {
            const uint32_t i = ref_a & ~kActive, j = ref_b & ~kActive;
            if (bounds) {
                // B's centre moved as the brute-force reference moves it (4-lane rounding differs by ulps).
                const Eigen::Vector3f cb_leaf = b_node_centre(j);
                const float sum = ra + rb + o.inflate, d2_leaf = (ca - cb_leaf).squaredNorm();
                if (!(d2_leaf < sum * sum)) continue;
                res.collide = true;
                record(i, j, i, j, ca, cb_leaf, sum, an[i].bv_radius, d2_leaf);
                if (any) return;
                continue;
            }
            if (lazy_a) lazy_a->ensure(i);
            if (lazy_b) lazy_b->ensure(j);
            if (sphere_leaf_pair(i, j, ca)) {
                res.collide = true;
                if (any) return;
                if (stop_when_deep && leaf_deep) { // the caller takes the deepest-pair route instead
                    stopped_deep = true;
                    return;
                }
            }
            continue;
        }
        // Descend the larger sphere (paper: both children are visited; here the
        // grandchildren of an inner child too). A lazy pose's loose ball (fitted to vertices, not
        // to its spheres) counts as kLooseWeight times its radius: its children's balls are much
        // smaller than it, so splitting it first prunes more, unless the other ball is far larger
        // (docs/deforming.md, "Lazy refit").
        bool side_a = leaf_b || (!leaf_a && ra >= rb);
        if (!leaf_a && !leaf_b && (lazy_a || lazy_b)) {
            const float wa = lazy_a && lazy_a->loose(ref_a) ? kLooseWeight : 1.0f;
            const float wb = lazy_b && lazy_b->loose(ref_b) ? kLooseWeight : 1.0f;
            side_a = wa * ra >= wb * rb;
        }
        const bool cached = !side_a && s.group_cache;
        if (detail::PendingPose* lazy = side_a ? lazy_a : lazy_b) lazy->ensure(side_a ? ref_a : ref_b);
        const Grandchildren w = side_a   ? Grandchildren(an, ref_a, reach_a)
                                : cached ? cached_b_group(f, s, bn, ref_b, reach_b)
                                         : Grandchildren(bn, ref_b, reach_b);
        v4f x = w.x, y = w.y, z = w.z;
        Eigen::Vector3f other = cb;
        if (!side_a) { // B's children into A's frame (a cached group is already there)
            if (!cached) b_to_a(f, x, y, z);
            other = ca;
        }
        const v4f dx = x - splat(other.x()), dy = y - splat(other.y()), dz = z - splat(other.z());
        const v4f dd = dx * dx + dy * dy + dz * dz;
        const v4f r = w.r;
        const v4f limit = r + splat((side_a ? rb : ra) + pad);
        const v4i pass = dd <= limit * limit; // false for an empty lane (NaN centre)
        float lx[4], ly[4], lz[4], ld2[4], lr[4];
        std::memcpy(lx, &x, sizeof lx), std::memcpy(ly, &y, sizeof ly), std::memcpy(lz, &z, sizeof lz);
        std::memcpy(ld2, &dd, sizeof ld2), std::memcpy(lr, &r, sizeof lr);
        res.counters.bound_tests += w.count;
        // Any: the nearest child is taken next (carried on below, the others pushed), so a
        // contact comes sooner. Nearest by power, |c - p|^2 - r^2 (p the other centre):
        // it orders lanes about as well as the gap |c - p| - r and keeps a square root
        // off the path from one step to the next.
        int nearest = -1;
        if (any) {
            const v4f inf = splat(std::numeric_limits<float>::infinity());
            nearest = lane_of_min(pass ? dd - r * r : inf, pass);
        }
        // The passing lanes are walked as the bits of a mask: a branch on each lane's
        // test mispredicts often, and writing every lane regardless costs more stores
        // than it saves on walks that prune most lanes.
        stack.make_room(4);
        auto push = [&](int k) {
            if (side_a)
                push_visit(stack, w.ref[k], ref_b, lx[k], ly[k], lz[k], cb, lr[k], rb, ld2[k], cap);
            else
                push_visit(stack, ref_a, w.ref[k], ca.x(), ca.y(), ca.z(), Eigen::Vector3f(lx[k], ly[k], lz[k]), ra,
                           lr[k], ld2[k], cap);
        };
        if (exit) {
            // Exit search: the lane likely to part last on top of the stack, so that the best
            // root comes early and prunes more: by how far B's side lies behind A's along
            // back, plus the radii (the root when the centres are in line).
            // (The order only steers the pruning: the root found is the same in any order.)
            int order[4], n = 0;
            float key[4];
            const Eigen::Vector3f back = exit->back.cast<float>();
            const v4f along = side_a ? dx * splat(back.x()) + dy * splat(back.y()) + dz * splat(back.z())
                                     : -(dx * splat(back.x()) + dy * splat(back.y()) + dz * splat(back.z()));
            const v4f k4 = along + r;
            std::memcpy(key, &k4, sizeof key);
            for (unsigned bits = unsigned(movemask(pass)); bits; bits &= bits - 1) {
                const int k = __builtin_ctz(bits);
                int m = n++;
                for (; m > 0 && key[order[m - 1]] > key[k]; --m) order[m] = order[m - 1];
                order[m] = k;
            }
            // The last, taken first, is carried on below instead of pushed and popped at once.
            for (int m = 0; m + 1 < n; ++m) push(order[m]);
            nearest = n > 0 ? order[n - 1] : -1;
        } else {
            unsigned bits = unsigned(movemask(pass));
            // Mode all: the last lane pushed would be popped at once; carried instead, the walk
            // visits the same pairs in the same order. Mode deepest carries the deepest-bounded.
            if (!any && bits) nearest = 31 - __builtin_clz(bits);
            if (deepest && bits) { // the lane whose balls overlap most
                float most = -std::numeric_limits<float>::infinity();
                const float other_r = side_a ? rb : ra;
                for (unsigned b = bits; b; b &= b - 1) {
                    const int k = __builtin_ctz(b);
                    if (const float bound = lr[k] + other_r - std::sqrt(ld2[k]); bound > most) most = bound, nearest = k;
                }
            }
            for (bits &= ~(nearest >= 0 ? 1u << nearest : 0u); bits; bits &= bits - 1) push(__builtin_ctz(bits));
        }
        if (nearest >= 0) {
            const int k = nearest;
            if (side_a)
                ref_a = w.ref[k], ca = Eigen::Vector3f(lx[k], ly[k], lz[k]), ra = lr[k];
            else
                ref_b = w.ref[k], cb = Eigen::Vector3f(lx[k], ly[k], lz[k]), rb = lr[k];
            d2 = ld2[k];
            carried = true;
        }
    }
}

QueryRun::QueryRun(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a, const QueryOptions& options,
                   QueryScratch& scratch)
    : A(a), B(b), EA(detail::exact_of(a)), EB(detail::exact_of(b)), o(options), s(detail::buffers_of(scratch)),
      f(a, b, b_in_a, options.inflate), exact(options.level == QueryLevel::Exact) {
    if (exact && !(a.has_mesh() && b.has_mesh()))
        throw Error(ErrorKind::Usage, "level 'exact' needs the triangles of both objects (give meshes, not only .spt files)");
    prepare_scratch(s, a, b, exact);
}

namespace {

// collide_relative; with `deep` (mode all, not exact) the walk stops at the first leaf pair
// holding a deep pair and says so there.
QueryResult relative_query(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                           const QueryOptions& options, QueryScratch& scratch, bool* deep, float slack = 0) {
    // A lazy pose is posed where this walk descends at level spheres; at level exact its triangles
    // are refit (and at mode deepest, the spheres where the walk for the contact descends);
    // elsewhere in full first.
    const bool lazy = detail::pending_of(a) || detail::pending_of(b);
    if (lazy && options.level == QueryLevel::Bounds) detail::settle(a), detail::settle(b);
    if (lazy && options.level == QueryLevel::Exact) detail::ensure_triangles(a), detail::ensure_triangles(b);
    QueryRun run(a, b, b_in_a, options, scratch);
    run.stop_when_deep = deep != nullptr;
    run.deepest_slack = slack;
    if (run.f.apart) { // the models cannot meet: one bound test, decided in double
        run.res.counters.bound_tests = 1;
        return run.res;
    }
    if (options.level != QueryLevel::Exact) {
        if (deep && run.probe_deep()) { // crossed where the balls overlap most: no walk through the rest
            run.res.collide = true;
            *deep = true;
            return run.res;
        }
        run.run();
        if (deep) *deep = run.stopped_deep;
        // Containment asks a posed model's triangles (its anchors were placed with the lazy
        // pose): refit them where it will ask. (A lazily posed model without triangles has no
        // containment, as a full pose has none.)
        if (lazy && options.solids && !run.stopped_deep && !run.res.collide && run.roots_overlap)
            detail::ensure_triangles(a), detail::ensure_triangles(b);
        if (!run.stopped_deep) run.check_containment();
    } else {
        // Triangles decide; at deepest the contact then comes from the sampling spheres.
        run.run_triangles();
        run.check_containment();
        if (options.mode == QueryMode::Deepest && run.res.collide) {
            const Contact contained = run.res.deepest;
            run.run();
            if (!run.have_best) run.res.deepest = contained; // no spheres overlap: containment's contact
        }
    }
    return run.res;
}

// A query at world poses: B's pose relative to A's in double, the contact back in the world.
QueryResult world_query(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                        const QueryOptions& options, QueryScratch& scratch, bool* deep, float slack = 0) {
    check_pose(pose_a, "pose of A");
    check_pose(pose_b, "pose of B");
    const Pose ua{unit_rotation(pose_a.rotation), pose_a.translation};
    const Pose ub{unit_rotation(pose_b.rotation), pose_b.translation};
    QueryResult r = relative_query(a, b, relative_pose(ua, ub), options, scratch, deep, slack);
    r.deepest.point = ua.apply(r.deepest.point);
    r.deepest.normal = ua.rotate(r.deepest.normal);
    return r;
}

} // namespace

QueryResult collide_relative(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                             const QueryOptions& options, QueryScratch& scratch) {
    return relative_query(a, b, b_in_a, options, scratch, nullptr);
}

double detail::deep_allowance(const CollisionModel& a, const CollisionModel& b) {
    const float *ra = detail::node_max_radius_of(a), *rb = detail::node_max_radius_of(b);
    return ra && rb ? kDeepAllowance * (double(ra[0]) + double(rb[0])) : 0.0;
}

QueryResult detail::deepest_within(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                                   const QueryOptions& options, float slack, QueryScratch& scratch) {
    return relative_query(a, b, b_in_a, options, scratch, nullptr, slack);
}

QueryResult detail::deepest_within(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b,
                                   const Pose& pose_b, const QueryOptions& options, float slack, QueryScratch& scratch) {
    return world_query(a, pose_a, b, pose_b, options, scratch, nullptr, slack);
}

QueryResult collide_all_unless_deep(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b,
                                    const Pose& pose_b, const QueryOptions& options, QueryScratch& scratch,
                                    bool& deep) {
    QueryOptions all = options;
    all.mode = QueryMode::All;
    deep = false;
    return world_query(a, pose_a, b, pose_b, all, scratch, all.level == QueryLevel::Spheres ? &deep : nullptr);
}

QueryResult collide_exit(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                         const QueryOptions& options, detail::ExitSearch& search, QueryScratch& scratch) {
    detail::settle(a), detail::settle(b); // a lazy pose is posed in full first
    QueryOptions all = options;
    all.mode = QueryMode::All;
    QueryRun run(a, b, b_in_a, all, scratch);
    search.found = false, search.root = 0, search.reach = 0;
    run.exit = &search;
    if (run.f.apart) {
        run.res.counters.bound_tests = 1;
        return run.res;
    }
    run.run();
    run.check_containment();
    return run.res;
}

QueryResult collide(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                    const QueryOptions& options, QueryScratch& scratch) {
    return world_query(a, pose_a, b, pose_b, options, scratch, nullptr);
}

QueryScratch::QueryScratch() : b_(std::make_unique<detail::ScratchBuffers>()) {}
QueryScratch::~QueryScratch() = default;
QueryScratch::QueryScratch(QueryScratch&&) noexcept = default;
QueryScratch& QueryScratch::operator=(QueryScratch&&) noexcept = default;
const std::vector<SpherePair>& QueryScratch::pairs() const { return b_->pairs; }
const std::vector<TrianglePair>& QueryScratch::triangle_pairs() const { return b_->tri_pairs; }

} // namespace spt
