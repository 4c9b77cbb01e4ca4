// CollisionModel: the query layout, the reach that bounds motion, the exact level's triangles.
#include "query/model_access.hpp"
#include "query/pending_pose.hpp"
#include "spt/collision_model.hpp"
#include "spt/error.hpp"
#include "base/float_round.hpp"
#include "query/exact_data.hpp"
#include "query/solid.hpp"
#include "query/node_slab.hpp"
#include "query/triangle_tree.hpp"
#include "geometry/vertex_faces.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace spt {
namespace {

using detail::round_up;

// Per triangle, a float ball holding it (the tree's leaves and the walk test them).
void fit_triangle_spheres(ExactData& e) {
    const size_t nt = e.triangles.size();
    e.tri_sphere.assign(nt * 4, 0);
    for (uint32_t f = 0; f < nt; ++f) {
        const auto& t = e.triangles[f];
        const Eigen::Vector3d &a = e.positions[t[0]], &b = e.positions[t[1]], &c = e.positions[t[2]];
        const Eigen::Vector3d centre = (a + b + c) / 3.0;
        const double r = std::max({(a - centre).norm(), (b - centre).norm(), (c - centre).norm()});
        // The float centre moved by rounding: grow the radius by that distance.
        const Eigen::Vector3d fc = detail::float_rounded(centre);
        for (int k = 0; k < 3; ++k) e.tri_sphere[4 * f + k] = float(fc[k]);
        e.tri_sphere[4 * f + 3] = round_up(r + (fc - centre).norm());
    }
}

// Per triangle, its plane in float, and how far off it the corners lie at most (the distance
// walk bounds a leaf by its triangles' planes).
void fit_triangle_planes(ExactData& e) {
    const size_t nt = e.triangles.size();
    e.tri_plane.assign(nt * 4, 0);
    double pad = 0;
    for (uint32_t f = 0; f < nt; ++f) {
        const auto& t = e.triangles[f];
        const Eigen::Vector3d &a = e.positions[t[0]], &b = e.positions[t[1]], &c = e.positions[t[2]];
        const Eigen::Vector3d n = (b - a).cross(c - a);
        const double length = n.norm();
        if (!(length > 0) || !std::isfinite(length)) continue; // no plane: a gap of 0 (prunes nothing)
        // The stored values, read back (float_rounded: a cast there and back can be folded away).
        const Eigen::Vector3d nf = detail::float_rounded(n / length);
        const double d = double(detail::to_float(nf.dot((a + b + c) / 3.0)));
        for (int k = 0; k < 3; ++k) e.tri_plane[4 * f + k] = float(nf[k]);
        e.tri_plane[4 * f + 3] = float(d);
        for (const Eigen::Vector3d* p : {&a, &b, &c}) pad = std::max(pad, std::abs(nf.dot(*p) - d));
    }
    e.plane_pad = round_up(pad);
}

// Grows extent and reach to hold every triangle (local positions, `o` the local origin).
void measure_triangles(const ExactData& e, const Eigen::Vector3d& o, double& extent, double& reach) {
    for (const Triangle& t : e.triangles)
        for (uint32_t v : t) {
            const Eigen::Vector3d& p = e.positions[v];
            extent = std::max(extent, p.norm());
            reach = std::max(reach, (p + o).norm());
        }
}

const SamplingTree& pick_tree(const SptDocument& doc, const std::string& name) {
    if (doc.trees.empty()) throw_bad_input(doc.mesh.name, "the document holds no sampling tree");
    if (name.empty()) return doc.trees.front();
    const SamplingTree* t = doc.tree(name);
    if (!t) throw_bad_input(doc.mesh.name, "no tree named '" + name + "'");
    return *t;
}

} // namespace

CollisionModel::CollisionModel(const SptDocument& doc, const std::string& tree_name) {
    init(doc, tree_name);
    // Without the mesh its parts are unknown, but a two-sided sample is on an open part: it
    // walls in nothing.
    std::vector<uint8_t> wall(tree_.sphere_count(), 0);
    for (size_t k = 0; k < wall.size(); ++k) wall[k] = !doc.samples.is_two_sided(tree_.sample_index()[k]);
    solid_ = std::make_shared<SolidData>(SolidData::build(tree_, detail::exact_of(*this), wall));
}

CollisionModel::CollisionModel(const SptDocument& doc, const TriangleMesh& mesh, const std::string& tree_name) {
    init(doc, tree_name);
    const std::string mismatch = check_mesh_matches(doc.mesh, mesh);
    if (!mismatch.empty()) throw_bad_input(mesh.name, mismatch);
    auto data = std::make_shared<ExactData>();
    ExactData& e = *data;
    // Local like the spheres: float bounds of triangles far from the object origin keep their precision.
    const Eigen::Vector3d& o = origin();
    e.positions.resize(mesh.positions.size());
    for (size_t v = 0; v < mesh.positions.size(); ++v) e.positions[v] = mesh.positions[v] - o;
    e.triangles = mesh.triangles;
    // Unknown openness counts as open: no solid is assumed that the mesh does not close.
    e.closed.assign(e.triangles.size(), 0);
    if (mesh.on_open_part.size() == e.triangles.size())
        for (size_t f = 0; f < e.closed.size(); ++f) e.closed[f] = !mesh.on_open_part[f];
    // A later copy of a face walls in nothing its face does not: counted twice, a ray would
    // cross the wall twice and find itself outside.
    for (size_t f = 0; f < e.closed.size(); ++f)
        if (mesh.copies_earlier_face(f)) e.closed[f] = 0;
    const size_t nt = e.triangles.size();
    fit_triangle_spheres(e);
    fit_triangle_planes(e);
    measure_triangles(e, o, extent_, reach_);
    detail::build_triangle_tree(e);
    // Only the spheres of closed parts wall in a solid at the sphere levels, as only closed
    // triangles do at the exact level: an open part encloses nothing, however nearly closed.
    std::vector<uint8_t> vertex_closed(mesh.positions.size(), 0);
    for (size_t f = 0; f < nt; ++f)
        if (e.closed[f])
            for (uint32_t v : e.triangles[f]) vertex_closed[v] = 1;
    std::vector<uint8_t> wall(tree_.sphere_count(), 0);
    for (size_t k = 0; k < wall.size(); ++k) {
        const uint32_t i = tree_.sample_index()[k];
        const uint32_t src = doc.samples.source_index(i);
        wall[k] = !doc.samples.is_two_sided(i) &&
                  (doc.samples.is_face_sample(i) ? (src < nt && e.closed[src]) : (src < vertex_closed.size() && vertex_closed[src]));
    }
    if (tree_.two_sided()) { // the faces two-sided spheres stand for (query/sample_piece.cpp)
        e.sphere_source.resize(tree_.sphere_count());
        for (size_t k = 0; k < e.sphere_source.size(); ++k) e.sphere_source[k] = doc.samples.sources[tree_.sample_index()[k]];
        detail::VertexFaces around = detail::vertex_faces(e.positions.size(), e.triangles);
        e.vertex_face_start = std::move(around.start);
        e.vertex_faces = std::move(around.faces);
    }
    exact_ = std::move(data);
    solid_ = std::make_shared<SolidData>(SolidData::build(tree_, *exact_, wall));
}

bool CollisionModel::has_mesh() const { return exact_ && !exact_->triangles.empty(); }

void CollisionModel::init(const SptDocument& doc, const std::string& tree_name) {
    const SamplingTree& t = pick_tree(doc, tree_name);
    tree_ = CompactTree(t, doc.samples);
    diagonal_ = doc.mesh.diagonal;
    max_leaf_ = 0;
    for (const CompactNode& n : tree_.nodes()) max_leaf_ = std::max(max_leaf_, n.count);
    measure();
    node_slab_ = detail::node_slabs(tree_);
    node_max_radius_ = detail::node_max_radii(tree_);
}

void CollisionModel::measure(bool by_leaves) {
    extent_ = reach_ = 0;
    const Eigen::Vector3d& o = origin();
    auto grow = [&](const Eigen::Vector3d& local_centre, double radius) {
        extent_ = std::max(extent_, local_centre.norm() + radius);
        reach_ = std::max(reach_, (local_centre + o).norm() + radius);
    };
    // By leaves, the loop over every node's ball below holds the active nodes' too. Else each
    // active node's spheres, which share one radius: the farthest centre's square root once a
    // node (the square root is monotone and correctly rounded, so this is the largest norm bit
    // for bit; a square root a sphere was a tenth of a deformed pose's time).
    if (!by_leaves)
        for (const CompactNode& n : tree_.nodes()) {
            if (!n.is_active()) continue;
            double far_local = 0, far_object = 0;
            for (uint32_t k = n.first; k < n.first + n.count; ++k) {
                const Eigen::Vector3d c = tree_.sphere_center(n, k).cast<double>();
                far_local = std::max(far_local, c.squaredNorm());
                far_object = std::max(far_object, (c + o).squaredNorm());
            }
            extent_ = std::max(extent_, std::sqrt(far_local) + n.ss_radius);
            reach_ = std::max(reach_, std::sqrt(far_object) + n.ss_radius);
        }
    const auto& nodes = tree_.nodes();
    bounds_reach_.assign(nodes.size(), 0);
    for (size_t i = nodes.size(); i-- > 0;) { // children follow their parent
        const CompactNode& n = nodes[i];
        double r = n.bv_radius;
        if (!n.is_active())
            for (uint32_t child : {uint32_t(i + 1), n.first}) {
                const CompactNode& m = nodes[child];
                const Eigen::Vector3d d(m.center[0] - n.center[0], m.center[1] - n.center[1], m.center[2] - n.center[2]);
                r = std::max(r, d.norm() + bounds_reach_[child]);
            }
        bounds_reach_[i] = n.is_active() ? n.bv_radius : round_up(r);
    }
    // Node spheres too: continuous detection grows every tested sphere by the motion of its farthest point.
    for (const CompactNode& n : tree_.nodes()) grow(Eigen::Vector3d(n.center[0], n.center[1], n.center[2]), n.bv_radius);
    if (exact_) measure_triangles(*exact_, o, extent_, reach_);
}

void CollisionModel::follow_surface(const std::vector<Eigen::Vector3d>& positions,
                                    const std::vector<Eigen::Vector3f>& points, const std::vector<Eigen::Vector3f>& normals,
                                    bool triangles, int threads, TaskSystem* tasks) {
    tree_.follow_samples(points, normals, threads, tasks);
    node_slab_.clear(); // fitted to the spheres where they were
    follow_triangles(positions, triangles);
}

void CollisionModel::follow_triangles(const std::vector<Eigen::Vector3d>& positions, bool triangles) {
    if (!triangles) exact_.reset();
    if (!has_mesh()) solid_.reset(); // the grids were made for the bind pose: no containment without the triangles
    place_triangle_corners(positions);
    fit_triangle_tree();
    measure(true);
}

void CollisionModel::place_triangle_corners(const std::vector<Eigen::Vector3d>& positions) {
    if (!has_mesh()) return;
    // Shared with copies of this model: those keep the pose they had.
    auto e = exact_.use_count() == 1 ? std::const_pointer_cast<ExactData>(exact_) : std::make_shared<ExactData>(*exact_);
    for (size_t v = 0; v < e->positions.size(); ++v) e->positions[v] = positions[v] - origin();
    // The triangles' planes are only a tighter bound for the distance walk; fitted at every pose
    // they cost a third of a lazy exact update (deforming_bench), so a posed mesh goes without.
    e->tri_plane.clear(), e->plane_pad = 0;
    exact_ = std::move(e);
    // The grids were made for the bind pose; with the triangles, containment asks them instead.
    if (solid_) {
        auto posed = std::make_shared<SolidData>();
        posed->posed = true;
        posed->anchor_vertex = solid_->anchor_vertex;
        for (uint32_t v : posed->anchor_vertex) posed->anchors.push_back((positions[v] - origin()).cast<float>());
        solid_ = std::move(posed);
    }
}

void CollisionModel::grow_to_hold_triangles() {
    if (has_mesh()) measure_triangles(*exact_, origin(), extent_, reach_);
}

void CollisionModel::fit_triangle_tree() {
    if (!has_mesh()) return;
    ExactData& e = *std::const_pointer_cast<ExactData>(exact_);
    fit_triangle_spheres(e);
    detail::refit_triangle_tree(e);
}

namespace detail {

PendingHandle::PendingHandle(const PendingHandle& other) {
    if (other.pose) other.pose->settle();
}

PendingHandle& PendingHandle::operator=(const PendingHandle& other) {
    if (other.pose) other.pose->settle();
    pose = nullptr;
    return *this;
}

} // namespace detail

size_t CollisionModel::memory_bytes() const {
    const ExactData& e = detail::exact_of(*this);
    return tree_.memory_bytes() + (node_slab_.capacity() + node_max_radius_.capacity()) * sizeof(float) + e.positions.capacity() * sizeof(Eigen::Vector3d) +
           e.triangles.capacity() * sizeof(Triangle) +
           e.tri_nodes.capacity() * sizeof(TriangleNode) + e.tri_order.capacity() * sizeof(uint32_t) +
           e.tri_sphere.capacity() * sizeof(float) + e.tri_plane.capacity() * sizeof(float) + e.closed.capacity() +
           (e.sphere_source.capacity() + e.vertex_face_start.capacity() + e.vertex_faces.capacity()) * sizeof(uint32_t) +
           detail::solid_of(*this).memory_bytes();
}

} // namespace spt
