// Tree-against-tree collision query (paper §3-4-2) with lazy update, normal
// culling, three levels and three modes. Everything happens in A's frame.
#include "spt/query.hpp"
#include "spt/error.hpp"
#include "geometry/sphere_block.hpp"
#include "query/exact_data.hpp"
#include "query/query_run.hpp"
#include <algorithm>
#include <cstring>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif
#include <cmath>
#include <limits>

namespace spt {
namespace {

typedef float v4f __attribute__((vector_size(16)));
typedef int32_t v4i __attribute__((vector_size(16)));

v4f splat(float x) { return v4f{x, x, x, x}; }

// Four points of B's frame into A's, in place; the one expression every move of B
// uses, so leaf spheres and node centres round alike (no fused multiply-add).
void b_to_a(const QueryFrame& f, v4f& x, v4f& y, v4f& z) {
    const Eigen::Matrix3f& R = f.R;
    const v4f bx = x, by = y, bz = z;
    x = splat(R(0, 0)) * bx + splat(R(0, 1)) * by + splat(R(0, 2)) * bz + splat(f.t.x());
    y = splat(R(1, 0)) * bx + splat(R(1, 1)) * by + splat(R(1, 2)) * bz + splat(f.t.y());
    z = splat(R(2, 0)) * bx + splat(R(2, 1)) * by + splat(R(2, 2)) * bz + splat(f.t.z());
}

} // namespace

void check_pose(const Pose& p, const char* what) {
    if (!p.translation.allFinite())
        throw Error(ErrorKind::BadInput, std::string(what) + ": the translation is not finite");
    const Eigen::Vector4d q = p.rotation.coeffs();
    if (!q.allFinite() || q.cwiseAbs().maxCoeff() == 0)
        throw Error(ErrorKind::BadInput, std::string(what) + ": the rotation quaternion is zero or not finite");
}

Eigen::Quaterniond unit_rotation(const Eigen::Quaterniond& q) {
    if (std::abs(q.squaredNorm() - 1) <= 1e-12) return q; // unit already: leave the bits alone
    return unit_quaternion(q);
}

double model_radius(const CollisionModel& m) {
    double r = m.extent();
    if (!m.tree().nodes().empty()) {
        const CompactNode& root = m.tree().nodes()[0];
        const double c = Eigen::Vector3d(root.center[0], root.center[1], root.center[2]).norm();
        r = std::max({r, c + root.bv_radius, c + (m.bounds_reach().empty() ? 0.0 : m.bounds_reach()[0])});
    }
    return r;
}

bool cannot_meet(const CollisionModel& a, const CollisionModel& b, const Eigen::Vector3d& td, double inflate) {
    // Every piece of B lies within model_radius(b) of td, every piece of A within
    // model_radius(a) of 0: a larger gap on one axis means no pair can meet. Slack of
    // 1e-6 for the rounding of the radii; NaN never happens (poses are checked).
    const double reach = (model_radius(a) + model_radius(b) + std::max(0.0, inflate)) * (1 + 1e-6);
    return !(td.cwiseAbs().maxCoeff() <= reach);
}

QueryFrame::QueryFrame(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a, float inflate) {
    check_pose(b_in_a, "pose of B in A's frame");
    Rd = unit_rotation(b_in_a.rotation).toRotationMatrix();
    td = local_translation(a, b, Rd, b_in_a.translation);
    apart = cannot_meet(a, b, td, inflate); // also when td overflowed to infinity
    if (!td.allFinite()) td = clamp_far(td); // far, finite, same direction
    R = Rd.cast<float>();
    t = td.cast<float>();
    // Float moves of B's centres are off by a few ulps of |t| + |x|; pruning and the
    // exact level's prefilters add this so rounding can never prune a real contact.
    // Every term is local (the pair's offset and the models' sizes), so the margin does
    // not grow with the distance from any origin. |t| bounded by its 1-norm: no square
    // root on the way to the first test.
    margin = float(1e-5 * (td.cwiseAbs().sum() + a.extent() + b.extent()));
}

void prepare_scratch(detail::ScratchBuffers& s, const CollisionModel& a, const CollisionModel& b, bool exact) {
    const size_t la = a.max_leaf() + 8, lb = b.max_leaf() + 8;
    if (s.d2.size() < la * lb) s.d2.resize(la * lb);
    if (s.moved_b.size() < 3 * lb) s.moved_b.resize(3 * lb);
    if (s.ga.size() < 3 * la) s.ga.resize(3 * la), s.ia.resize(la);
    if (s.gb.size() < 3 * lb) s.gb.resize(3 * lb), s.ib.resize(lb);
    if (s.stack.capacity() < 256) s.stack.reserve(256);
    if (s.visits.size() < 256) s.visits.resize(256);
    if (exact) {
        const size_t nv = b.exact().positions.size(), nt = b.exact().triangles.size();
        if (s.bverts.size() < nv) s.bverts.resize(nv), s.vert_stamp.resize(nv, 0);
        if (s.btri.size() < 4 * nt) s.btri.resize(4 * nt), s.tri_stamp.resize(nt, 0);
        const size_t nn = b.exact().tri_nodes.size();
        if (s.bboxes.size() < nn) s.bboxes.resize(nn), s.bbox_stamp.resize(nn, 0);
    }
    if (++s.epoch == 0) { // wrapped: forget every stamp
        std::fill(s.vert_stamp.begin(), s.vert_stamp.end(), 0);
        std::fill(s.tri_stamp.begin(), s.tri_stamp.end(), 0);
        std::fill(s.bbox_stamp.begin(), s.bbox_stamp.end(), 0);
        s.epoch = 1;
    }
    s.pairs.clear();
    s.tri_pairs.clear();
}

Eigen::Vector3f QueryRun::b_node_centre(uint32_t j) const {
    const CompactNode& n = B.tree().nodes()[j];
    return f.R * Eigen::Vector3f(n.center[0], n.center[1], n.center[2]) + f.t;
}

void QueryRun::move_leaf(uint32_t j, float* x, float* y, float* z) const {
    const CompactNode& n = B.tree().nodes()[j];
    const float* c = B.tree().centres(n);
    const float *bx = c, *by = c + n.count, *bz = c + 2 * n.count;
    // Four spheres at a time; the last group reads past the block into the next one (or
    // the array's padding) and writes up to 3 floats past count, which callers allow.
    for (uint32_t k = 0; k < n.count; k += 4) {
        v4f px, py, pz;
        std::memcpy(&px, bx + k, sizeof px), std::memcpy(&py, by + k, sizeof py), std::memcpy(&pz, bz + k, sizeof pz);
        b_to_a(f, px, py, pz);
        std::memcpy(x + k, &px, sizeof px), std::memcpy(y + k, &py, sizeof py), std::memcpy(z + k, &pz, sizeof pz);
    }
}

void QueryRun::record(uint32_t node_a, uint32_t node_b, uint32_t a, uint32_t b, const Eigen::Vector3f& ca,
                      const Eigen::Vector3f& cb, float reach, float ra, float d2) {
    const float dist = std::sqrt(d2);
    const float depth = reach - dist;
    if (o.mode == QueryMode::All) {
        s.pairs.push_back({a, b, node_a, node_b, depth, reach});
        return;
    }
    if (have_best && !(depth > res.deepest.depth)) return;
    have_best = true;
    Contact& c = res.deepest;
    c.depth = depth;
    c.a = a, c.b = b;
    const Eigen::Vector3d d = (cb - ca).cast<double>();
    c.normal = dist > 0 ? Eigen::Vector3d(d / d.norm()) : Eigen::Vector3d::UnitX();
    c.point = A.origin() + ca.cast<double>() + c.normal * (double(ra) - 0.5 * depth);
}

uint32_t QueryRun::sphere_leaf_pair(uint32_t i, uint32_t j, const Eigen::Vector3f& ca) {
    const CompactTree &ta = A.tree(), &tb = B.tree();
    const CompactNode &na = ta.nodes()[i], &nb = tb.nodes()[j];
    // Lazy update: B's spheres are moved only here, for the leaf the walk reached,
    // into a small buffer that stays in L1 (a whole-model copy would not).
    const size_t lb = s.moved_b.size() / 3;
    float *bx = s.moved_b.data(), *by = bx + lb, *bz = by + lb;
    move_leaf(j, bx, by, bz);
    const float* block_a = ta.centres(na);
    const float *ax = block_a, *ay = block_a + na.count, *az = block_a + 2 * na.count;
    uint32_t count_a = na.count, count_b = nb.count;
    const bool cull = o.normal_culling;
    if (cull) {
        // u: from A's node towards B's node. A keeps n.u >= -cos; B, in its own frame, n.(-u) >= -cos.
        // A two-sided sphere faces both ways: always kept.
        Eigen::Vector3f u = b_node_centre(j) - ca;
        const float len = u.norm();
        const float limit = -o.cull_cos * 127.0f; // normals are snorm8
        const size_t la = s.ia.size();
        float *gax = s.ga.data(), *gay = gax + la, *gaz = gay + la;
        float *gbx = s.gb.data(), *gby = gbx + lb, *gbz = gby + lb;
        if (len > 0) {
            u /= len;
            const Eigen::Vector3f ub = -(f.R.transpose() * u);
            const uint8_t *two_a = ta.two_sided(), *two_b = tb.two_sided();
            count_a = 0;
            for (uint32_t p = 0, k = na.first; p < na.count; ++p, ++k)
                if ((two_a && two_a[k]) || ta.nx()[k] * u.x() + ta.ny()[k] * u.y() + ta.nz()[k] * u.z() >= limit)
                    gax[count_a] = ax[p], gay[count_a] = ay[p], gaz[count_a] = az[p], s.ia[count_a++] = k;
            count_b = 0;
            for (uint32_t q = 0, k = nb.first; q < nb.count; ++q, ++k)
                if ((two_b && two_b[k]) || tb.nx()[k] * ub.x() + tb.ny()[k] * ub.y() + tb.nz()[k] * ub.z() >= limit)
                    gbx[count_b] = bx[q], gby[count_b] = by[q], gbz[count_b] = bz[q], s.ib[count_b++] = k;
            ax = gax, ay = gay, az = gaz, bx = gbx, by = gby, bz = gbz;
        } else {
            for (uint32_t k = 0; k < na.count; ++k) s.ia[k] = na.first + k;
            for (uint32_t k = 0; k < nb.count; ++k) s.ib[k] = nb.first + k;
        }
        if (count_a == 0 || count_b == 0) return 0;
    }
    res.counters.sphere_tests += uint64_t(count_a) * count_b;
    const float reach = na.ss_radius + nb.ss_radius + o.inflate;
    const float limit2 = reach * reach;
    float* d2 = s.d2.data();
    const float best = sphere_block_d2(ax, ay, az, count_a, bx, by, bz, count_b, d2);
    if (!(best < limit2)) return 0;
    const uint32_t stride = sphere_block_stride(count_b);
    auto sphere_a = [&](uint32_t k) { return cull ? s.ia[k] : na.first + k; };
    auto sphere_b = [&](uint32_t k) { return cull ? s.ib[k] : nb.first + k; };
    auto centre = [](const float* x, const float* y, const float* z, uint32_t k) { return Eigen::Vector3f(x[k], y[k], z[k]); };
    if (o.mode != QueryMode::All) { // any and deepest want only the closest pair (the first, on ties)
        for (uint32_t p = 0; p < count_a; ++p)
            for (uint32_t q = 0; q < count_b; ++q)
                if (d2[size_t(p) * stride + q] == best) {
                    record(i, j, sphere_a(p), sphere_b(q), centre(ax, ay, az, p), centre(bx, by, bz, q), reach,
                           na.ss_radius, best);
                    return 1;
                }
    }
    uint32_t hits = 0;
    for (uint32_t p = 0; p < count_a; ++p)
        for (uint32_t q = 0; q < count_b; ++q) {
            const float v = d2[size_t(p) * stride + q];
            if (!(v < limit2)) continue;
            ++hits;
            record(i, j, sphere_a(p), sphere_b(q), centre(ax, ay, az, p), centre(bx, by, bz, q), reach, na.ss_radius,
                   v);
        }
    return hits;
}

namespace {

// Bit k set when lane k is true.
int movemask(v4i m) {
#if defined(__SSE__)
    return _mm_movemask_ps(__m128(m));
#else
    int bits = 0;
    for (int k = 0; k < 4; ++k) bits |= (m[k] & 1) << k;
    return bits;
#endif
}

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
};

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
                float ra, float rb, float d2) {
    detail::NodePairVisit& v = stack.buf[stack.size++];
    v.a = a, v.b = b;
    v.ca[0] = ax, v.ca[1] = ay, v.ca[2] = az;
    v.cb[0] = cb.x(), v.cb[1] = cb.y(), v.cb[2] = cb.z();
    v.ra = ra, v.rb = rb, v.d2 = d2;
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
    VisitStack stack{s.visits};
    // Every pair on the stack overlaps: it was tested when pushed, four children at a
    // time, and the same distances order the descent.
    // The pair in hand (the root first, then in mode any the nearest child) stays in
    // registers instead of going through the stack: a store and a load less a step.
    uint32_t ref_a = an[0].is_active() ? kActive : 0, ref_b = bn[0].is_active() ? kActive : 0;
    Eigen::Vector3f ca(an[0].center[0], an[0].center[1], an[0].center[2]), cb = b_node_centre(0);
    float ra = reach_a ? reach_a[0] : an[0].bv_radius, rb = reach_b ? reach_b[0] : bn[0].bv_radius;
    float d2 = (ca - cb).squaredNorm();
    ++res.counters.bound_tests;
    if (const float prune = ra + rb + pad; d2 > prune * prune) return;
    roots_overlap = true;
    bool carried = true;
    for (;;) {
        if (!carried) {
            if (stack.size == 0) break;
            const detail::NodePairVisit& top = stack.buf[--stack.size];
            ref_a = top.a, ref_b = top.b;
            ca = Eigen::Vector3f(top.ca[0], top.ca[1], top.ca[2]);
            cb = Eigen::Vector3f(top.cb[0], top.cb[1], top.cb[2]);
            ra = top.ra, rb = top.rb, d2 = top.d2;
        }
        carried = false;
        ++res.counters.node_pairs;
        // Deepest: no sphere below this pair can be deeper than the bounds' overlap.
        if (deepest && have_best && !(ra + rb + pad - std::sqrt(d2) > float(res.deepest.depth))) continue;
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
            if (sphere_leaf_pair(i, j, ca)) {
                res.collide = true;
                if (any) return;
            }
            continue;
        }
        // Descend the larger sphere (paper: both children are visited; here the
        // grandchildren of an inner child too).
        const bool side_a = leaf_b || (!leaf_a && ra >= rb);
        const Grandchildren w = side_a ? Grandchildren(an, ref_a, reach_a) : Grandchildren(bn, ref_b, reach_b);
        v4f x = w.x, y = w.y, z = w.z;
        Eigen::Vector3f other = cb;
        if (!side_a) { // B's children into A's frame
            b_to_a(f, x, y, z);
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
                push_visit(stack, w.ref[k], ref_b, lx[k], ly[k], lz[k], cb, lr[k], rb, ld2[k]);
            else
                push_visit(stack, ref_a, w.ref[k], ca.x(), ca.y(), ca.z(), Eigen::Vector3f(lx[k], ly[k], lz[k]), ra,
                           lr[k], ld2[k]);
        };
        const unsigned first = nearest >= 0 ? 1u << nearest : 0u;
        for (unsigned bits = unsigned(movemask(pass)) & ~first; bits; bits &= bits - 1) push(__builtin_ctz(bits));
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
    : A(a), B(b), EA(a.exact()), EB(b.exact()), o(options), s(scratch.buffers()), f(a, b, b_in_a, options.inflate),
      exact(options.level == QueryLevel::Exact) {
    if (exact && !(a.has_mesh() && b.has_mesh()))
        throw Error(ErrorKind::Usage, "level 'exact' needs the triangles of both objects (give meshes, not only .spt files)");
    prepare_scratch(s, a, b, exact);
}

QueryResult collide_relative(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                             const QueryOptions& options, QueryScratch& scratch) {
    QueryRun run(a, b, b_in_a, options, scratch);
    if (run.f.apart) { // the models cannot meet: one bound test, decided in double
        run.res.counters.bound_tests = 1;
        return run.res;
    }
    if (options.level != QueryLevel::Exact) {
        run.run();
        run.check_containment();
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

QueryResult collide(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                    const QueryOptions& options, QueryScratch& scratch) {
    check_pose(pose_a, "pose of A");
    check_pose(pose_b, "pose of B");
    const Pose ua{unit_rotation(pose_a.rotation), pose_a.translation};
    const Pose ub{unit_rotation(pose_b.rotation), pose_b.translation};
    QueryResult r = collide_relative(a, b, relative_pose(ua, ub), options, scratch);
    r.deepest.point = ua.apply(r.deepest.point);
    r.deepest.normal = ua.rotate(r.deepest.normal);
    return r;
}

QueryScratch::QueryScratch() : b_(std::make_unique<detail::ScratchBuffers>()) {}
QueryScratch::~QueryScratch() = default;
QueryScratch::QueryScratch(QueryScratch&&) noexcept = default;
QueryScratch& QueryScratch::operator=(QueryScratch&&) noexcept = default;
const std::vector<SpherePair>& QueryScratch::pairs() const { return b_->pairs; }
const std::vector<TrianglePair>& QueryScratch::triangle_pairs() const { return b_->tri_pairs; }

} // namespace spt
