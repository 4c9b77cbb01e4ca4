#pragma once
// Pieces of the query shared by query.cpp, the brute-force reference, response and CCD.
#include "query/model_access.hpp"
#include "spt/query.hpp"
#include "query/scratch.hpp"
#include <algorithm>
#include <cmath>

namespace spt {

// Translation taking B's local frame into A's (CollisionModel::origin), given B's rotation
// and translation in A's object frame; in double, so far-away origins cancel exactly enough.
inline Eigen::Vector3d local_translation(const CollisionModel& a, const CollisionModel& b, const Eigen::Matrix3d& rot,
                                         const Eigen::Vector3d& t) {
    return rot * b.origin() + (t - a.origin());
}

// Throws Error(BadInput) naming `what` unless the pose is finite with a non-zero quaternion.
void check_pose(const Pose& p, const char* what);

// The pose's rotation as a unit quaternion, whatever its length (finite, non-zero; see
// unit_quaternion); a quaternion of unit length within 1e-12 is used as it is.
Eigen::Quaterniond unit_rotation(const Eigen::Quaterniond& q);

// Radius around the model's local origin holding everything a query can test: spheres,
// triangles and, at level bounds, the leaf bounding spheres below the root (model units).
double model_radius(const CollisionModel& m);

// True when B, its local origin at `td` in A's local frame, cannot meet A even with every
// sphere grown by `inflate`: decided in double on the largest axis of td, so any finite
// (or overflowed) td answers without a float that could overflow.
bool cannot_meet(const CollisionModel& a, const CollisionModel& b, const Eigen::Vector3d& td, double inflate);

// B's pose in A's frame, between the models' local frames, in double and float, and the
// rounding margin. `apart`: the models cannot meet even grown by `inflate` (decided in
// double before any float, so a translation up to the largest double answers at once).
struct QueryFrame {
    QueryFrame(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a, float inflate);
    Eigen::Matrix3d Rd;
    Eigen::Vector3d td;
    Eigen::Matrix3f R;
    Eigen::Vector3f t;
    float margin = 0;
    bool apart = false;
};

namespace detail {

// B's exact-level data moved into A's frame at most once a query, where a walk first needs it: the
// scratch's stamped slots, which prepare_scratch sizes and gives a new epoch. The exact collide
// walk and the exact distance share it.
struct MovedB {
    ScratchBuffers& s;
    const ExactData& e; // B's
    const QueryFrame& f;
    // Vertex v of B, in double.
    const Eigen::Vector3d& vertex(uint32_t v) {
        if (s.vert_stamp[v] != s.epoch) s.vert_stamp[v] = s.epoch, s.bverts[v] = f.Rd * e.positions[v] + f.td;
        return s.bverts[v];
    }
    // The bounding sphere of B's triangle `tri`: centre xyz, radius.
    const float* tri_sphere(uint32_t tri) {
        float* out = &s.btri[4 * size_t(tri)];
        if (s.tri_stamp[tri] != s.epoch) {
            s.tri_stamp[tri] = s.epoch;
            const float* in = &e.tri_sphere[4 * size_t(tri)];
            const Eigen::Vector3f c = f.R * Eigen::Vector3f(in[0], in[1], in[2]) + f.t;
            out[0] = c.x(), out[1] = c.y(), out[2] = c.z(), out[3] = in[3];
        }
        return out;
    }
    // The plane of B's triangle `tri`: unit normal xyz, offset (ExactData::tri_plane).
    const float* tri_plane(uint32_t tri) {
        float* out = &s.bplane[4 * size_t(tri)];
        if (s.plane_stamp[tri] != s.epoch) {
            s.plane_stamp[tri] = s.epoch;
            const float* in = &e.tri_plane[4 * size_t(tri)];
            const Eigen::Vector3f n = f.R * Eigen::Vector3f(in[0], in[1], in[2]);
            out[0] = n.x(), out[1] = n.y(), out[2] = n.z(), out[3] = in[3] + n.dot(f.t);
        }
        return out;
    }
    // The centre and slab axis (axis 0) of node j of B's triangle tree (as tri_box's, without
    // the other axes).
    const ScratchBuffers::MovedNode& tri_node(uint32_t j) {
        if (s.bcentre_stamp[j] != s.epoch) {
            const TriangleNode& n = e.tri_nodes[j];
            s.bcentre_stamp[j] = s.epoch;
            s.bcentres[j] = {f.R * Eigen::Vector3f(n.center[0], n.center[1], n.center[2]) + f.t,
                             f.R * Eigen::Vector3f(n.axis[0][0], n.axis[0][1], n.axis[0][2])};
        }
        return s.bcentres[j];
    }
    // The box of node j of B's triangle tree.
    const Obb& tri_box(uint32_t j) {
        if (s.bbox_stamp[j] != s.epoch) s.bbox_stamp[j] = s.epoch, place_into(e.tri_nodes[j].box(), f.R, f.t, s.bboxes[j]);
        return s.bboxes[j];
    }
};

// collide_relative in mode deepest, allowed to answer a depth up to `slack` short of the deepest
// (model units): node pairs that cannot beat the best by more are not walked. Distance queries
// with an absolute error allowance ask this.
QueryResult deepest_within(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                           const QueryOptions& options, float slack, QueryScratch& scratch);
// The same at world poses (as collide), the contact in the world.
QueryResult deepest_within(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b, const Pose& pose_b,
                           const QueryOptions& options, float slack, QueryScratch& scratch);

// How far short of the deepest a deep overlap's depth, and how far past the last exit its parting
// distance, may be (model units): kDeepAllowance of the two models' largest sampling-sphere radii
// together (docs/scenes.md, "Deep overlaps"). Such an overlap holds thousands of sphere pairs within
// a few thousandths of the deepest; proving which one is deepest would cost a walk through them all.
constexpr double kDeepAllowance = 0.02;
double deep_allowance(const CollisionModel& a, const CollisionModel& b);

// The exact backtrack's question at one shift (response.cpp): B moving on by s * back (unit,
// A's local frame), the largest s at which a pair overlapping now stops overlapping. Answered
// by a walk that keeps only that root and skips node pairs whose own bounding spheres part
// sooner, instead of recording every overlapping pair.
struct ExitSearch {
    Eigen::Vector3d back = Eigen::Vector3d::UnitX();
    bool found = false; // some pair overlaps (at level bounds: some leaf bound pair)
    double root = 0;    // the largest exit root among them (model units along back)
    double reach = 0;   // the largest reach among the pairs with that root
};

// Where two balls whose centres differ by w (B's minus A's) and whose radii sum to `reach`
// stop overlapping as B moves by s * back: the larger root of |w + s back| = reach.
inline double exit_root(const Eigen::Vector3d& w, double reach, const Eigen::Vector3d& back) {
    const double half_b = w.dot(back), c = w.squaredNorm() - reach * reach;
    return -half_b + std::sqrt(std::max(0.0, half_b * half_b - c));
}

// Whether the exit root of two such balls may reach S (lie at or beyond it), told without a
// square root: the middle of their chord lies at or beyond S, or they still overlap at S. The
// reach is widened by a millionth (of it and of |w|) so that rounding never drops a tie.
inline bool exit_may_reach(const Eigen::Vector3d& w, double reach, const Eigen::Vector3d& back, double S) {
    if (-w.dot(back) >= S) return true;
    const double wide = reach + 1e-6 * (reach + w.cwiseAbs().sum());
    return (w + S * back).squaredNorm() <= wide * wide;
}

// Local-frame centre of one side of a recorded pair (SpherePair): sphere k of active node
// `node`, or at level bounds node k itself, in double.
inline Eigen::Vector3d pair_centre(const CompactTree& t, bool bounds, uint32_t node, uint32_t k) {
    if (bounds) {
        const CompactNode& n = t.nodes()[k];
        return Eigen::Vector3f(n.center[0], n.center[1], n.center[2]).cast<double>();
    }
    return t.sphere_center(t.nodes()[node], k).cast<double>();
}

// Keeps pair (root, reach) if it beats or ties the search's best.
inline void keep_exit(ExitSearch& e, double root, double reach) {
    if (!e.found || root > e.root) e.found = true, e.root = root, e.reach = reach;
    else if (root == e.root) e.reach = std::max(e.reach, reach);
}

// Adds one query's counters to a sum of several.
inline void add_counters(QueryCounters& to, const QueryCounters& c) {
    to.node_pairs += c.node_pairs, to.bound_tests += c.bound_tests, to.sphere_tests += c.sphere_tests;
    to.triangle_tests += c.triangle_tests;
}

// A deep pair overlaps by more than half its reach (r_a + r_b, grown): its surfaces have crossed
// by a sampling radius, rather than press (docs/scenes.md, "Deep overlaps").
inline bool is_deep_pair(const SpherePair& p) { return p.reach - p.depth < 0.5f * p.reach; }

} // namespace detail

// Mode all at a non-exact level with `search` answered instead of pairs recorded: sets
// res.collide (sphere pairs or containment) and the search; scratch.pairs() stays empty.
QueryResult collide_exit(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                         const QueryOptions& options, detail::ExitSearch& search, QueryScratch& scratch);

// Mode all at level spheres (world poses, as collide) that gives up at the first leaf pair whose
// overlapping spheres hold a deep pair, overlapping by more than half its reach (r_a + r_b, grown by
// inflate), so that the surfaces cross there rather than press (docs/scenes.md, "Deep overlaps"). Then `deep` is set and the
// scratch holds only the pairs found before; otherwise the answer and pairs are collide's, bit for
// bit. Other levels: collide's mode all, `deep` false.
QueryResult collide_all_unless_deep(const CollisionModel& a, const Pose& pose_a, const CollisionModel& b,
                                    const Pose& pose_b, const QueryOptions& options, QueryScratch& scratch,
                                    bool& deep);

// Grows the scratch for this pair of models and starts a new epoch of lazy stamps.
void prepare_scratch(detail::ScratchBuffers& s, const CollisionModel& a, const CollisionModel& b, bool exact);

// One query in progress.
struct QueryRun {
    QueryRun(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a, const QueryOptions& options,
             QueryScratch& scratch);
    void run();
    // B's spheres of active node j in A's frame, into columns x, y, z (count floats each,
    // rounded up to 4: each column needs 3 floats of room past count); the one place
    // B's spheres are moved, so the walk and the brute-force reference round them alike.
    void move_leaf(uint32_t j, float* x, float* y, float* z) const;
    // Centre of B's compact node j in A's frame.
    Eigen::Vector3f b_node_centre(uint32_t j) const;
    const Eigen::Vector3d& b_vertex(uint32_t v);
    const float* b_tri_sphere(uint32_t tri);
    // The box of node j of B's triangle tree in A's frame (moved once per query, when a box
    // test first needs it: a small tree's nodes meet many of the other's).
    const Obb& b_tri_box(uint32_t j);
    bool triangle_pair(uint32_t ta, uint32_t tb);
    // Level `exact`: walks the triangle trees; sets res.collide (and, in mode all, the triangle pairs).
    void run_triangles();
    // collide_all_unless_deep's first look (query/deep_probe.cpp): one descent from the roots into
    // the child pair whose balls overlap most, down to a leaf pair; true when that leaf pair holds a
    // deep pair (the walk would then stop at its own first one). Records nothing.
    bool probe_deep();
    // With options.solids, after a walk that found nothing though the roots overlap: is a piece
    // of either model inside a closed part of the other? Sets res.collide and the contact.
    void check_containment();
    // Tests the spheres of active nodes i (A) and j (B), ca being i's centre; returns how
    // many pairs it recorded (mode all: every overlapping pair; any and deepest: the
    // closest one, or none).
    uint32_t sphere_leaf_pair(uint32_t i, uint32_t j, const Eigen::Vector3f& ca);
    // Whether A's sphere sa and B's sphere sb, centres ca and cb in A's frame, radii ra and rb,
    // whose balls overlap, still touch when a two-sided one is taken as its disc.
    bool shapes_touch(uint32_t sa, uint32_t sb, const Eigen::Vector3f& ca, const Eigen::Vector3f& cb, float ra,
                      float rb);
    // Whether A's node i and B's node j, centres ca and cb in A's frame, bounding radii ra and
    // rb, may hold spheres that touch, when either node's two-sided spheres lie in a flat disc
    // (CompactTree::node_disc): the walk prunes the pair otherwise.
    bool node_discs_touch(uint32_t i, uint32_t j, const Eigen::Vector3f& ca, const Eigen::Vector3f& cb, float ra,
                          float rb) const;
    // With the mesh: whether the faces that two-sided spheres sa and/or sb stand for still
    // touch the other's face or ball (their discs met; query/sample_piece.cpp).
    bool pieces_touch(uint32_t sa, uint32_t sb, bool disc_a, bool disc_b, const Eigen::Vector3f& ca,
                      const Eigen::Vector3f& cb, float ra, float rb);
    // Records a colliding pair: spheres a, b of active nodes node_a, node_b (at `bounds`, the nodes).
    void record(uint32_t node_a, uint32_t node_b, uint32_t a, uint32_t b, const Eigen::Vector3f& ca,
                const Eigen::Vector3f& cb, float reach, float ra, float d2);

    const CollisionModel& A;
    const CollisionModel& B;
    const ExactData& EA; // detail::exact_of(A) and detail::exact_of(B), looked up once
    const ExactData& EB;
    const QueryOptions& o;
    detail::ScratchBuffers& s;
    QueryFrame f;
    bool exact;
    bool have_best = false;
    float deepest_slack = 0;    // mode deepest: a pair must beat the best by more than this to be walked
    bool roots_overlap = false; // set by the walks: containment is possible only then
    bool stop_when_deep = false; // collide_all_unless_deep: the walk ends at a deep leaf pair...
    bool stopped_deep = false;   // ...and says so here
    bool leaf_deep = false;      // sphere_leaf_pair (mode all): it recorded a deep pair
    struct {
        uint32_t a, b;
        bool meet, valid;
    } piece_memo{0, 0, false, false}; // the last face pair pieces_touch tested: a leaf's hits share faces
    QueryResult res; // res.deepest is written only by record(), so it stays default without a contact
    detail::ExitSearch* exit = nullptr; // collide_exit: record() feeds it, run() prunes by it
    // Whether node pair (centres ca, cb in A's frame, radii ra, rb grown by pad) may hold a pair
    // whose exit root reaches the search's best: their bounding balls must stay met that long.
    bool may_exit_later(const Eigen::Vector3f& ca, const Eigen::Vector3f& cb, float ra, float rb, float pad) const;
    // The exit root of sphere pair a, b (of nodes node_a, node_b; at level bounds the nodes), from
    // their centres moved in double as the backtrack moves them.
    void keep_exit_root(uint32_t node_a, uint32_t node_b, uint32_t a, uint32_t b, float reach);
    // Mode all: records overlapping pair a, b (of nodes node_a, node_b), squared centre distance
    // d2, with its depth.
    void keep_pair(uint32_t node_a, uint32_t node_b, uint32_t a, uint32_t b, float reach, float d2) {
        s.pairs.push_back({a, b, node_a, node_b, reach - std::sqrt(d2), reach});
    }
    // An overlapping pair met by an exit search (centres ca, cb in A's frame, in float).
    void exit_pair(uint32_t node_a, uint32_t node_b, uint32_t a, uint32_t b, const Eigen::Vector3f& ca,
                   const Eigen::Vector3f& cb, float reach) {
        // Most pairs part well before the best root found so far: bounded from the walk's
        // float centres (within the frame's margin of the double ones) before the exact root.
        if (exit->found && !may_exit_later(ca, cb, reach, 0.0f, f.margin)) return;
        keep_exit_root(node_a, node_b, a, b, reach);
    }
};

inline bool QueryRun::may_exit_later(const Eigen::Vector3f& ca, const Eigen::Vector3f& cb, float ra, float rb,
                                     float pad) const {
    // Every sphere below lies in its node's bounding ball, so a pair of them overlaps only
    // while the balls do; the walk's float centres are within pad of the exact ones.
    return detail::exit_may_reach((cb - ca).cast<double>(), double(ra) + double(rb) + double(pad), exit->back,
                                  exit->root);
}

} // namespace spt
