// Lazy refit (lazy_pose.hpp).
#include "anim/lazy_pose.hpp"
#include "geometry/vertex_faces.hpp"
#include "mesh/vertex_normals.hpp"
#include "tree/spheres_below.hpp"
#include "sampling/encoding.hpp"
#include "spt/samples.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {
namespace {

// Unique ids collected with a stamp per id, in the order first met.
struct IdSet {
    std::vector<uint32_t> stamp, ids;
    uint32_t epoch = 0;
    explicit IdSet(size_t n) : stamp(n, 0) {}
    void clear() { ids.clear(), ++epoch; }
    void add(uint32_t id) {
        if (stamp[id] != epoch) stamp[id] = epoch, ids.push_back(id);
    }
};

// Unique ids, each with the largest value it was added with.
struct IdMax {
    IdSet set;
    std::vector<float> value;
    explicit IdMax(size_t n) : set(n), value(n, 0) {}
    void clear() { set.clear(); }
    /// Adds id with value v; true when id is new since the last clear.
    bool add(uint32_t id, float v) {
        const bool fresh = set.stamp[id] != set.epoch;
        set.add(id);
        value[id] = fresh ? v : std::max(value[id], v);
        return fresh;
    }
    std::vector<float> values() const {
        std::vector<float> out;
        for (uint32_t id : set.ids) out.push_back(value[id]);
        return out;
    }
};

} // namespace

// The three corners of the triangle where two of a face's weights are at their least `a`
// (p0, p1, p2 the face's corners), each given to `to`.
template <class To>
void least_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                    const Eigen::Vector3d& p2, To&& to) {
    to((1 - a[1] - a[2]) * p0 + a[1] * p1 + a[2] * p2);
    to(a[0] * p0 + (1 - a[0] - a[2]) * p1 + a[2] * p2);
    to(a[0] * p0 + a[1] * p1 + (1 - a[0] - a[1]) * p2);
}

// The corners, as barycentric weights, of the patch of a face where each weight w_k lies in
// [least_k, most_k] (and they sum to 1). Each corner of that polygon (at most six) holds two of
// the bounds, so each is among the twelve points that hold two bounds of two weights, taken when
// the third weight is in its range too; a billionth of slack there keeps a corner that rounding
// puts a hair outside (samples along an edge hold one weight at the same value: the patch is a
// segment, and both its ends lie on the third weight's bounds). Posing is linear in the face's
// corners, so a face's posed samples lie in the hull of its posed patch corners: a patch along an
// edge or in a corner of a large face is much smaller than the triangle that the least weights
// alone give. Where no corner of that triangle reaches past its weight's most, that triangle is
// the patch: nothing is appended and 0 returned (three corners made from the least weights).
// Else appended to `out`; returns how many (no point twice).
uint8_t patch_corners(const Eigen::Vector3d& least, const Eigen::Vector3d& most, std::vector<Eigen::Vector3d>& out) {
    const double side = 1 - least.sum();
    if ((Eigen::Vector3d::Constant(side) + least - most).maxCoeff() <= 0) return 0;
    constexpr double slack = 1e-9;
    const size_t first = out.size();
    for (int k = 0; k < 3; ++k) { // k: the weight that follows from the other two
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        for (const double wi : {least[i], most[i]})
            for (const double wj : {least[j], most[j]}) {
                Eigen::Vector3d w;
                w[i] = wi, w[j] = wj, w[k] = 1 - wi - wj;
                if (!(w[k] >= least[k] - slack && w[k] <= most[k] + slack)) continue;
                if (std::find(out.begin() + std::ptrdiff_t(first), out.end(), w) == out.end()) out.push_back(w);
            }
    }
    return uint8_t(out.size() - first); // 0 only for weights that do not sum to 1: the triangle then
}

std::shared_ptr<const LazyLayout> make_lazy_layout(const CompactTree& tree, const TriangleMesh& mesh,
                                                   const std::vector<uint32_t>& source,
                                                   const std::vector<Eigen::Vector3d>& barycentric,
                                                   const std::vector<double>& offset, uint32_t region_samples) {
    const std::vector<CompactNode>& nodes = tree.nodes();
    if (nodes.empty()) return nullptr;
    auto layout = std::make_shared<LazyLayout>();
    const size_t n = nodes.size();
    // Spheres and nodes below each node (children follow their parent in the layout).
    const std::vector<uint32_t> spheres = spheres_below(nodes);
    std::vector<uint32_t> size(n);
    for (size_t i = n; i-- > 0;) size[i] = nodes[i].is_active() ? 1 : 1 + size[i + 1] + size[nodes[i].first];
    // Frontier: the highest nodes of at most region_samples spheres (or active).
    std::vector<uint32_t> frontier, stack{0};
    while (!stack.empty()) {
        const uint32_t i = stack.back();
        stack.pop_back();
        if (nodes[i].is_active() || spheres[i] <= region_samples) {
            frontier.push_back(i);
        } else {
            stack.push_back(nodes[i].first), stack.push_back(i + 1);
        }
    }
    std::sort(frontier.begin(), frontier.end());

    layout->need.assign(n, kNoRegion);
    // The covers and the nodes above them, which a region never refits: every node to begin with,
    // then a region's subtree cleared, its covers marked again.
    std::vector<uint8_t> kept(n, 1);
    // Vertex to faces, for the faces whose normals a vertex sums.
    const size_t nv = mesh.positions.size();
    layout->around = detail::vertex_faces(nv, mesh.triangles);
    const std::vector<uint32_t>&face_start = layout->around.start, &faces = layout->around.faces;
    auto each_sample = [&](uint32_t first, uint32_t last, auto&& f) {
        for (uint32_t i = first; i < last; ++i)
            if (nodes[i].is_active())
                for (uint32_t k = nodes[i].first; k < nodes[i].first + nodes[i].count; ++k) f(tree.sample_index()[k]);
    };
    IdSet vertex_set(nv), face_set(mesh.triangles.size()), sampled_set(mesh.triangles.size());
    IdMax cover_faces(mesh.triangles.size()), cover_flat_faces(mesh.triangles.size()), cover_vertices(nv),
        cover_flat_vertices(nv);
    // Per face: each weight's least and most over its samples in hand.
    std::vector<Eigen::Vector3d> least_weight(mesh.triangles.size()), most_weight(mesh.triangles.size());
    std::vector<uint32_t> slot_of(nv, kNoSlot), face_slot_of(mesh.triangles.size(), kNoSlot);
    for (uint32_t r = 0; r < frontier.size(); ++r) {
        const uint32_t f = frontier[r], end = f + size[f];
        for (uint32_t i = f; i < end; ++i) layout->need[i] = r, kept[i] = 0;
        // Covers: the frontier node if active, else its two children.
        std::vector<uint32_t> cover_nodes;
        if (nodes[f].is_active()) {
            cover_nodes = {f};
        } else {
            cover_nodes = {f + 1, nodes[f].first};
            kept[f] = 1;
        }
        for (uint32_t c : cover_nodes) {
            kept[c] = 1;
            LazyLayout::Cover cover;
            cover.node = c;
            // Four sets, each collected once: one-sided faces and vertices, then two-sided; each
            // with the largest radius of a sphere on it here.
            for (IdMax* set : {&cover_faces, &cover_vertices, &cover_flat_faces, &cover_flat_vertices}) set->clear();
            vertex_set.clear();
            double reach = 0;
            // The box of the samples' surface points at bind: a face's triangle of least weights
            // with a corner outside it widens the cover; one within it, hardly.
            Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
            for (uint32_t i = c; i < c + size[c]; ++i) {
                if (!nodes[i].is_active()) continue;
                const float r = nodes[i].ss_radius;
                reach = std::max(reach, double(r));
                for (uint32_t k = nodes[i].first; k < nodes[i].first + nodes[i].count; ++k) {
                    const uint32_t s = tree.sample_index()[k], src = source[s] & kMaxSourceIndex;
                    const bool flat = tree.two_sided() && tree.two_sided()[k];
                    cover.off = std::max(cover.off, offset[s]);
                    if (source[s] & kFaceSampleBit) {
                        for (int j = 0; j < 3; ++j) vertex_set.add(mesh.triangles[src][j]);
                        cover.spread = std::max(cover.spread, barycentric[s].cwiseAbs().sum());
                        const bool fresh = (flat ? cover_flat_faces : cover_faces).add(src, r);
                        least_weight[src] = fresh ? barycentric[s] : least_weight[src].cwiseMin(barycentric[s]);
                        most_weight[src] = fresh ? barycentric[s] : most_weight[src].cwiseMax(barycentric[s]);
                        const Triangle& t = mesh.triangles[src];
                        const Eigen::Vector3d& w = barycentric[s];
                        const Eigen::Vector3d p = w[0] * mesh.positions[t[0]] + w[1] * mesh.positions[t[1]] + w[2] * mesh.positions[t[2]];
                        lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
                    } else {
                        lo = lo.cwiseMin(mesh.positions[src]), hi = hi.cwiseMax(mesh.positions[src]);
                        vertex_set.add(src);
                        (flat ? cover_flat_vertices : cover_vertices).add(src, r);
                    }
                }
            }
            // A face takes its patch's corners (more items a pose) only where a corner of its
            // least weights' triangle lies outside that box by more than a millionth of the box.
            const double margin = 1e-6 * (hi - lo).norm();
            auto sticks_out = [&](uint32_t f) {
                const Triangle& t = mesh.triangles[f];
                bool outside = false;
                least_triangle(least_weight[f], mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]],
                               [&](const Eigen::Vector3d& q) {
                                   outside |= (lo - q).maxCoeff() > margin || (q - hi).maxCoeff() > margin;
                               });
                return outside;
            };
            size_t patch_items = 0;
            for (const bool flat : {false, true})
                for (uint32_t f : (flat ? cover_flat_faces : cover_faces).set.ids) {
                    std::vector<Eigen::Vector3d>& out = flat ? cover.flat_face_patch : cover.face_patch;
                    const uint8_t n = sticks_out(f) ? patch_corners(least_weight[f], most_weight[f], out) : 0;
                    (flat ? cover.flat_face_least : cover.face_least).push_back(least_weight[f]);
                    (flat ? cover.flat_face_patch_size : cover.face_patch_size).push_back(n);
                    patch_items += n ? n : 3;
                }
            cover.faces = cover_faces.set.ids, cover.face_reach = cover_faces.values();
            cover.vertices = cover_vertices.set.ids, cover.vertex_reach = cover_vertices.values();
            cover.flat_faces = cover_flat_faces.set.ids, cover.flat_face_reach = cover_flat_faces.values();
            cover.flat_vertices = cover_flat_vertices.set.ids, cover.flat_vertex_reach = cover_flat_vertices.values();
            // A sphere lies within twice its radius of its surface point (its centre is p - r*n).
            cover.corners = vertex_set.ids, cover.grow = 2 * reach * (1 + 1e-6) + cover.off;
            layout->most_items =
                std::max(layout->most_items, patch_items + cover.vertices.size() + cover.flat_vertices.size());
            layout->covers.push_back(std::move(cover));
        }
        LazyLayout::Region region;
        vertex_set.clear(), sampled_set.clear();
        each_sample(f, end, [&](uint32_t s) {
            const uint32_t src = source[s] & kMaxSourceIndex;
            region.samples.push_back(s);
            if (source[s] & kFaceSampleBit) {
                sampled_set.add(src);
                for (int k = 0; k < 3; ++k) vertex_set.add(mesh.triangles[src][k]);
            } else {
                vertex_set.add(src);
            }
        });
        region.normal_vertices = vertex_set.ids;
        for (uint32_t k = 0; k < region.normal_vertices.size(); ++k) slot_of[region.normal_vertices[k]] = k;
        region.sampled_faces = sampled_set.ids;
        for (uint32_t k = 0; k < region.sampled_faces.size(); ++k)
            face_slot_of[region.sampled_faces[k]] = uint32_t(region.normal_vertices.size()) + k;
        for (uint32_t s : region.samples) {
            const uint32_t src = source[s] & kMaxSourceIndex;
            region.sample_slot.push_back((source[s] & kFaceSampleBit) ? face_slot_of[src] : slot_of[src]);
        }
        for (uint32_t face : region.sampled_faces) face_slot_of[face] = kNoSlot;
        for (uint32_t face : region.sampled_faces)
            for (int k = 0; k < 3; ++k) region.sampled_corner_slot.push_back(slot_of[mesh.triangles[face][k]]);
        face_set.clear();
        for (uint32_t v : region.normal_vertices)
            for (uint32_t k = face_start[v]; k < face_start[v + 1]; ++k) face_set.add(faces[k]);
        region.normal_faces = face_set.ids;
        std::sort(region.normal_faces.begin(), region.normal_faces.end());
        for (uint32_t face : region.normal_faces)
            for (int k = 0; k < 3; ++k) region.corner_slot.push_back(slot_of[mesh.triangles[face][k]]);
        for (uint32_t v : region.normal_vertices) slot_of[v] = kNoSlot;
        for (uint32_t i = f; i < end; ++i) {
            if (nodes[i].is_active()) region.active.push_back(i);
            if (kept[i]) continue;
            if (nodes[i].is_active()) region.fit_active.push_back(i);
        }
        for (uint32_t i = end; i-- > f;)
            if (!kept[i] && !nodes[i].is_active()) region.fit_inner.push_back(i);

        layout->regions.push_back(std::move(region));
    }
    // Upper: inner nodes kept that are not covers (strict ancestors of the frontier, inner frontier nodes).
    std::vector<uint8_t> is_cover(n, 0);
    for (const LazyLayout::Cover& c : layout->covers) is_cover[c.node] = 1;
    for (size_t i = n; i-- > 0;)
        if (kept[i] && !is_cover[i] && !nodes[i].is_active()) layout->upper.push_back(uint32_t(i));
    // Covers come in node order, and a node's subtree is a run of nodes: the covers below an upper
    // node are a run too.
    auto first_cover_from = [&](uint32_t node) {
        return uint32_t(std::lower_bound(layout->covers.begin(), layout->covers.end(), node,
                                         [](const LazyLayout::Cover& c, uint32_t x) { return c.node < x; }) -
                        layout->covers.begin());
    };
    for (uint32_t i : layout->upper) layout->upper_covers.emplace_back(first_cover_from(i), first_cover_from(i + size[i]));
    layout->loose.assign(n, 0);
    for (const LazyLayout::Cover& c : layout->covers) layout->loose[c.node] = 1;
    for (uint32_t i : layout->upper) layout->loose[i] = 1;
    return layout;
}

LazyPose::LazyPose(DeformingModel* owner, std::shared_ptr<const LazyLayout> layout)
    : owner_(owner), layout_(std::move(layout)), posed_flags_(new std::atomic<uint8_t>[layout_->regions.size()]) {
    need_ = layout_->need.data();
    loose_ = layout_->loose.data();
    posed_ = posed_flags_.get();
}

void LazyPose::begin() {
    const TriangleMesh& mesh = owner_->mesh_->imported.mesh;
    const size_t faces = mesh.triangles.size(), verts = mesh.positions.size();
    if (face_stamp_.size() != faces) {
        face_stamp_.assign(faces, 0), corner_add_.resize(3 * faces), face_adds_.resize(faces);
        sampled_stamp_.assign(faces, 0), face_snap_.resize(faces), face_ok_.resize(faces);
        vertex_stamp_.assign(verts, 0), vertex_unit_.resize(verts), vertex_snap_.resize(verts), vertex_ok_.resize(verts);
    }
    if (++pose_stamp_ == 0) { // wrapped: forget every stamp
        for (auto* stamps : {&face_stamp_, &sampled_stamp_, &vertex_stamp_}) std::fill(stamps->begin(), stamps->end(), 0);
        pose_stamp_ = 1;
    }
    for (size_t r = 0; r < layout_->regions.size(); ++r) posed_flags_[r].store(0, std::memory_order_relaxed);
    CollisionModel& model = owner_->model_;
    model.node_slab_.clear(); // fitted to the bind pose's spheres
    CompactTree& tree = model.tree_;
    tree.ensure_boxes(); // before any walk: regions refit their nodes' boxes while walks read balls
    const std::vector<Eigen::Vector3d>& v = owner_->vertices_;
    if (tree.tight_refit_) {
        fit_tight_covers();
    } else {
        const Eigen::Vector3d& origin = tree.origin();
        for (const LazyLayout::Cover& c : layout_->covers) {
            Eigen::Vector3d lo = v[c.corners.front()], hi = lo;
            for (uint32_t k : c.corners) lo = lo.cwiseMin(v[k]), hi = hi.cwiseMax(v[k]);
            const Eigen::Vector3d mid = 0.5 * (lo + hi);
            double far = 0;
            for (uint32_t k : c.corners) far = std::max(far, (v[k] - mid).norm());
            // A sample is a weighted sum of its vertices (weights summing to 1), so it lies within
            // spread * far of the middle; the float layout rounds within a millionth of where it lies.
            const Eigen::Vector3d centre = mid - origin;
            const double r = c.spread * far + c.grow;
            tree.set_ball(c.node, centre, r + 1e-6 * (centre.norm() + r));
        }
        for (uint32_t i : layout_->upper) tree.fit_inner_ball(i, false); // the spheres below may be unposed
    }
    // Two-sided spheres: a node's disc is fitted to the spheres below it, which may be unposed; the
    // covers and the nodes above are balls until a settle (a walk tests a node without a disc by
    // its ball), and a region fits its own nodes' discs when it is posed.
    if (!tree.node_disc_.empty()) {
        auto no_disc = [&](uint32_t i) { std::fill_n(tree.node_disc_.data() + 4 * size_t(i), 4, -1.0f); };
        for (const LazyLayout::Cover& c : layout_->covers) no_disc(c.node);
        for (uint32_t i : layout_->upper) no_disc(i);
    }
    const CompactNode& root = tree.nodes()[0];
    const Eigen::Vector3d c(root.center[0], root.center[1], root.center[2]);
    model.extent_ = c.norm() + root.bv_radius;
    model.reach_ = (c + tree.origin()).norm() + root.bv_radius;
    // Without the triangles a pose has no exact level and no containment, as a full pose has
    // none: nothing then needs the rest posed but an explicit settle.
    if (!owner_->triangles_) model.exact_.reset(), model.solid_.reset();
    // The triangles' corners before any walk, whole (a region's would be shared with its
    // neighbours' walks): two-sided spheres answer with the faces their samples lie on
    // (query/sample_piece.cpp), and the exact level reads them. The triangles' balls and tree wait
    // for the first exact walk (ensure_triangles) or the settle.
    model.place_triangle_corners(v);
    model.grow_to_hold_triangles();
    triangles_posed_.store(0, std::memory_order_relaxed);
    model.pending_.pose = this;
}

void LazyPose::fit_tight_covers() {
    const TriangleMesh& mesh = owner_->mesh_->imported.mesh;
    const size_t faces = mesh.triangles.size();
    const std::vector<Eigen::Vector3d>& v = owner_->vertices_;
    CompactTree& tree = owner_->model_.tree_;
    // Every face's unit normal as a full pose makes it (follow()), and whether it has a share in
    // its corners' vertex normals (vertex_normals.hpp): a cover then knows on which side of its
    // surface points its spheres lie.
    cover_unit_.resize(faces), cover_share_.resize(faces);
    const double area_eps = degenerate_twice_area(owner_->diagonal_);
    for (size_t f = 0; f < faces; ++f) {
        const Triangle& t = mesh.triangles[f];
        cover_share_[f] = face_unit_normal(v[t[0]], v[t[1]], v[t[2]], area_eps, cover_unit_[f]) && !mesh.copies_earlier_face(f);
    }
    // Each cover from its items, made and fitted while they are in cache; then the nodes above
    // from the covers.
    const std::vector<LazyLayout::Cover>& covers = layout_->covers;
    items_.resize(layout_->most_items);
    cover_box_.resize(2 * covers.size());
    for (size_t k = 0; k < covers.size(); ++k) fit_cover(k, cover_items(covers[k]));
    // An upper node: the ball around the middle of its covers' items' boxes holding their balls
    // (fitted to the covers, not to two children's balls, whose slack grows with every level).
    const CompactNode* nodes = tree.nodes().data();
    for (size_t u = 0; u < layout_->upper.size(); ++u) {
        const auto [first, last] = layout_->upper_covers[u];
        Eigen::Vector3d lo = cover_box_[2 * first], hi = cover_box_[2 * first + 1];
        for (uint32_t k = first + 1; k < last; ++k) lo = lo.cwiseMin(cover_box_[2 * k]), hi = hi.cwiseMax(cover_box_[2 * k + 1]);
        const Eigen::Vector3d mid = 0.5 * (lo + hi);
        double far = 0;
        for (uint32_t k = first; k < last; ++k) {
            const CompactNode& n = nodes[covers[k].node];
            far = std::max(far, (Eigen::Vector3d(n.center[0], n.center[1], n.center[2]) - mid).norm() + double(n.bv_radius));
        }
        tree.set_ball(layout_->upper[u], mid, far + 1e-6 * (mid.norm() + far)); // (the float centre's rounding)
    }
}

size_t LazyPose::cover_items(const LazyLayout::Cover& c) {
    const TriangleMesh& mesh = owner_->mesh_->imported.mesh;
    const std::vector<Eigen::Vector3d>& v = owner_->vertices_;
    // A sphere of radius r <= R tangent at p on the inner side of unit normal n lies in the ball of
    // radius R tangent there, centred at q = p - R n. Stored normals are snapped within a
    // thousandth of the unit normal. Each item is a point q and how far past it the spheres it
    // stands for reach.
    constexpr double eps = 1e-3;
    Eigen::Vector4d* out = items_.data();
    auto item = [&](const Eigen::Vector3d& q, double add) { *out++ = Eigen::Vector4d(q.x(), q.y(), q.z(), add + c.off); };
    // A face's samples here have barycentric weights w with w_k >= a_k (the least over them) and
    // sum 1: they lie in the triangle of the three points where two of the weights are least, or,
    // where that triangle would widen the cover, in the hull of their patch's corners
    // (patch_corners); and so does each posed sample (posing is linear in the face's corners).
    const Eigen::Vector3d* patch = c.face_patch.data();
    auto each_corner = [&](uint32_t f, const Eigen::Vector3d& a, uint8_t corners, auto&& to) {
        const Triangle& t = mesh.triangles[f];
        const Eigen::Vector3d &p0 = v[t[0]], &p1 = v[t[1]], &p2 = v[t[2]];
        if (corners == 0) least_triangle(a, p0, p1, p2, to);
        for (uint8_t k = 0; k < corners; ++k, ++patch) to((*patch)[0] * p0 + (*patch)[1] * p1 + (*patch)[2] * p2);
    };
    for (size_t j = 0; j < c.faces.size(); ++j) {
        // Without a normal of its own (a face squeezed flat) a face's samples take one that may
        // point anywhere: then a sphere lies within 2R of its surface point.
        const uint32_t f = c.faces[j];
        const double R = c.face_reach[j];
        const Eigen::Vector3d shift = R * cover_unit_[f];
        const double add = cover_unit_[f].squaredNorm() > 0 ? R * (1 + 2 * eps) : 2 * R * (1 + eps);
        each_corner(f, c.face_least[j], c.face_patch_size[j], [&](const Eigen::Vector3d& p) { item(p - shift, add); });
    }
    patch = c.flat_face_patch.data();
    for (size_t j = 0; j < c.flat_faces.size(); ++j) {
        const double add = c.flat_face_reach[j] * (1 + eps);
        each_corner(c.flat_faces[j], c.flat_face_least[j], c.flat_face_patch_size[j],
                    [&](const Eigen::Vector3d& p) { item(p, add); });
    }
    // A vertex's normal is the unit sum of its faces' normals weighted by their angles there
    // (vertex_normals.hpp). When every such face's normal lies within angle t of their mean m
    // (t below a quarter turn), so does the unit sum (the cone is convex), which is then within
    // 2 sin(t / 2) of m. The sum has a direction (finish_normal) when it is longer than 1e-12,
    // as it is when one face's angle (at least its sine) times its cos t is: then the rest of the
    // sum, each term along m at least 0, cannot shorten it.
    const std::vector<uint32_t>&start = layout_->around.start, &around = layout_->around.faces;
    for (size_t j = 0; j < c.vertices.size(); ++j) {
        const uint32_t i = c.vertices[j];
        const double R = c.vertex_reach[j];
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        uint32_t some = kNoSlot;
        for (uint32_t a = start[i]; a < start[i + 1]; ++a)
            if (cover_share_[around[a]]) mean += cover_unit_[around[a]], some = around[a];
        double least = mean.norm() > 0 ? 1 : -1;
        if (least > 0) mean.normalize();
        for (uint32_t a = start[i]; a < start[i + 1] && least >= 0; ++a)
            if (cover_share_[around[a]]) least = std::min(least, cover_unit_[around[a]].dot(mean));
        bool sure = false;
        if (least >= 0) { // sin^2 of some's angle at i, times least^2, past 1e-24 (squares: no root)
            const Triangle& t = mesh.triangles[some];
            const int k = t[0] == i ? 0 : t[1] == i ? 1 : 2;
            const Eigen::Vector3d e1 = v[t[(k + 1) % 3]] - v[i], e2 = v[t[(k + 2) % 3]] - v[i];
            sure = e1.cross(e2).squaredNorm() * least * least > 4e-24 * e1.squaredNorm() * e2.squaredNorm();
        }
        if (sure)
            item(v[i] - R * mean, R * (1 + std::sqrt(std::max(0.0, 2 - 2 * least)) + 2 * eps));
        else
            item(v[i], 2 * R * (1 + eps));
    }
    for (size_t j = 0; j < c.flat_vertices.size(); ++j) item(v[c.flat_vertices[j]], c.flat_vertex_reach[j] * (1 + eps));
    return size_t(out - items_.data());
}

void LazyPose::fit_cover(size_t k, size_t items) {
    // The ball around the middle of the items' box reaching past every item.
    CompactTree& tree = owner_->model_.tree_;
    const Eigen::Vector3d origin = tree.origin();
    // Four boxes, each over every fourth item, so that one min does not wait on the last
    // (a min is exact: the same box whichever way the items are grouped).
    Eigen::Vector3d lo[4], hi[4];
    for (int g = 0; g < 4; ++g) lo[g] = hi[g] = items_[0].head<3>() - origin;
    size_t i = 1;
    for (; i + 4 <= items; i += 4)
        for (int g = 0; g < 4; ++g) {
            const Eigen::Vector3d q = items_[i + size_t(g)].head<3>() - origin;
            lo[g] = lo[g].cwiseMin(q), hi[g] = hi[g].cwiseMax(q);
        }
    for (; i < items; ++i) {
        const Eigen::Vector3d q = items_[i].head<3>() - origin;
        lo[0] = lo[0].cwiseMin(q), hi[0] = hi[0].cwiseMax(q);
    }
    for (int g = 1; g < 4; ++g) lo[0] = lo[0].cwiseMin(lo[g]), hi[0] = hi[0].cwiseMax(hi[g]);
    const Eigen::Vector3d mid = 0.5 * (lo[0] + hi[0]);
    double far = 0;
    for (size_t i = 0; i < items; ++i) {
        // Most items lie well inside the reach so far: told by squares, without the root (a margin
        // far above the rounding keeps the reach the same, bit for bit).
        const double d2 = (items_[i].head<3>() - origin - mid).squaredNorm(), room = far - items_[i][3];
        if (room > 0 && d2 < room * room * (1 - 1e-9)) continue;
        far = std::max(far, std::sqrt(d2) + items_[i][3]);
    }
    cover_box_[2 * k] = lo[0], cover_box_[2 * k + 1] = hi[0];
    // The float layout rounds within a millionth of where a centre lies.
    tree.set_ball(layout_->covers[k].node, mid, far + 1e-6 * (mid.norm() + far));
}

void LazyPose::settle() {
    // What a full pose makes, without posing again the regions queries have posed: the rest of
    // the regions, then the balls above them as refit_bounds fits them (children before parents).
    std::lock_guard<std::mutex> lock(mutex_);
    for (uint32_t r = 0; r < layout_->regions.size(); ++r)
        if (!posed_flags_[r].load(std::memory_order_relaxed)) pose_region_locked(r);
    CollisionModel& model = owner_->model_;
    CompactTree& tree = model.tree_;
    for (const LazyLayout::Cover& c : layout_->covers)
        tree.nodes_[c.node].is_active() ? tree.fit_active_ball(c.node) : tree.fit_inner_ball(c.node);
    for (uint32_t i : layout_->upper) tree.fit_inner_ball(i);
    if (!tree.node_disc_.empty()) tree.build_node_discs(); // as a full pose: every node's from the posed balls
    model.follow_triangles(owner_->vertices_, owner_->triangles_);
    owner_->vertex_normals_stale_ = true;
    model.pending_.pose = nullptr;
}

void LazyPose::pose_triangles() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (triangles_posed_.load(std::memory_order_relaxed)) return; // another walk did
    owner_->model_.fit_triangle_tree();
    triangles_posed_.store(1, std::memory_order_release);
}

void LazyPose::pose_region(uint32_t r) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!posed_flags_[r].load(std::memory_order_relaxed)) pose_region_locked(r); // else another walk did
}

void LazyPose::pose_region_locked(uint32_t r) {
    const LazyLayout::Region& R = layout_->regions[r];
    DeformingModel& d = *owner_;
    const TriangleMesh& m = d.mesh_->imported.mesh;
    const std::vector<Eigen::Vector3d>& v = d.vertices_;
    const size_t nvl = R.normal_vertices.size(), nfl = R.sampled_faces.size();
    // Vertex normals summed over the faces in the order a full pose sums them: the same bits.
    normal_sum_.assign(nvl, Eigen::Vector3d::Zero());
    const double area_eps = degenerate_twice_area(d.diagonal_);
    for (size_t k = 0; k < R.normal_faces.size(); ++k) {
        const uint32_t f = R.normal_faces[k];
        if (!m.is_copy.empty() && m.is_copy[f]) continue;
        if (face_stamp_[f] != pose_stamp_) {
            const Triangle& t = m.triangles[f];
            face_adds_[f] = face_corner_normals(v[t[0]], v[t[1]], v[t[2]], area_eps, &corner_add_[3 * size_t(f)]);
            face_stamp_[f] = pose_stamp_;
        }
        if (!face_adds_[f]) continue;
        for (int c = 0; c < 3; ++c)
            if (const uint32_t slot = R.corner_slot[3 * k + c]; slot != kNoSlot)
                normal_sum_[slot] += corner_add_[3 * size_t(f) + size_t(c)];
    }
    // A vertex's or face's normal is the same in every region that reads it: made once a pose.
    for (size_t k = 0; k < nvl; ++k) {
        const uint32_t vi = R.normal_vertices[k];
        if (vertex_stamp_[vi] == pose_stamp_) continue;
        vertex_stamp_[vi] = pose_stamp_;
        vertex_ok_[vi] = finish_normal(normal_sum_[k]);
        vertex_unit_[vi] = normal_sum_[k];
        if (vertex_ok_[vi]) vertex_snap_[vi] = snap_normal(normal_sum_[k].cast<float>());
    }
    for (size_t q = 0; q < nfl; ++q) {
        const uint32_t f = R.sampled_faces[q];
        if (sampled_stamp_[f] == pose_stamp_) continue;
        sampled_stamp_[f] = pose_stamp_;
        const Triangle& t = m.triangles[f];
        Eigen::Vector3d normal = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]);
        if (!(normal.norm() > 0)) normal = vertex_unit_[t[0]] + vertex_unit_[t[1]] + vertex_unit_[t[2]];
        face_ok_[f] = normal.norm() > 0;
        if (face_ok_[f]) face_snap_[f] = snap_normal(normal.normalized().cast<float>());
    }
    for (size_t k = 0; k < R.samples.size(); ++k) {
        const uint32_t slot = R.sample_slot[k];
        const Eigen::Vector3f* snapped = nullptr;
        if (slot < nvl) {
            const uint32_t vi = R.normal_vertices[slot];
            if (vertex_ok_[vi]) snapped = &vertex_snap_[vi];
        } else {
            const uint32_t f = R.sampled_faces[slot - nvl];
            if (face_ok_[f]) snapped = &face_snap_[f];
        }
        d.place_sample(R.samples[k], snapped);
    }
    CompactTree& tree = d.model_.tree_;
    for (uint32_t a : R.active) tree.place_spheres(a, d.points_.data(), d.normals_.data());
    for (uint32_t a : R.fit_active) tree.fit_active_ball(a);
    for (uint32_t i : R.fit_inner) tree.fit_inner_ball(i);
    if (!tree.node_disc_.empty()) { // children before parents, as the balls
        for (uint32_t a : R.fit_active) tree.fit_node_disc(a);
        for (uint32_t i : R.fit_inner) tree.fit_node_disc(i);
    }
    posed_flags_[r].store(1, std::memory_order_release);
}

} // namespace spt::detail
