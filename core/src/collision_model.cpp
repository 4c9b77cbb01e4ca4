#include "spt/collision_model.hpp"
#include "spt/error.hpp"
#include "spt/tri_tri.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace spt {
namespace {

// Float radius that still contains a double one after rounding.
float round_up(double r) { return std::nextafter(float(r * (1 + 1e-6)), std::numeric_limits<float>::infinity()); }

const SamplingTree& pick_tree(const SptDocument& doc, const std::string& name) {
    if (doc.trees.empty()) throw_bad_input(doc.mesh.name, "the document holds no sampling tree");
    if (name.empty()) return doc.trees.front();
    const SamplingTree* t = doc.tree(name);
    if (!t) throw_bad_input(doc.mesh.name, "no tree named '" + name + "'");
    return *t;
}

} // namespace

CollisionModel::CollisionModel(const SptDocument& doc, const std::string& tree_name) { init(doc, tree_name); }

CollisionModel::CollisionModel(const SptDocument& doc, const TriangleMesh& mesh, const std::string& tree_name) {
    init(doc, tree_name);
    const std::string mismatch = check_mesh_matches(doc.mesh, mesh);
    if (!mismatch.empty()) throw_bad_input(mesh.name, mismatch);
    ExactData& e = exact_;
    e.positions = mesh.positions;
    e.triangles = mesh.triangles;
    const auto& nodes = tree_.nodes();
    const size_t nv = e.positions.size(), nt = e.triangles.size(), nn = nodes.size();

    // Vertex -> incident triangles.
    e.vertex_tri_begin.assign(nv + 1, 0);
    for (const auto& t : e.triangles)
        for (uint32_t v : t) ++e.vertex_tri_begin[v + 1];
    for (size_t v = 0; v < nv; ++v) e.vertex_tri_begin[v + 1] += e.vertex_tri_begin[v];
    e.vertex_tris.resize(e.vertex_tri_begin[nv]);
    {
        std::vector<uint32_t> fill(e.vertex_tri_begin.begin(), e.vertex_tri_begin.end() - 1);
        for (uint32_t f = 0; f < nt; ++f)
            for (uint32_t v : e.triangles[f]) e.vertex_tris[fill[v]++] = f;
    }

    // Which compact node holds each sample, and the lowest sample on each vertex and face.
    const size_t ns = doc.samples.size();
    std::vector<uint32_t> node_of_sample(ns, UINT32_MAX);
    for (uint32_t i = 0; i < nn; ++i)
        for (uint32_t k = nodes[i].first; nodes[i].is_active() && k < nodes[i].first + nodes[i].count; ++k)
            node_of_sample[tree_.sample_index()[k]] = i;
    std::vector<uint32_t> vertex_sample(nv, UINT32_MAX), face_sample(nt, UINT32_MAX);
    for (uint32_t s = 0; s < ns; ++s) {
        const uint32_t src = doc.samples.source_index(s);
        auto& slot = doc.samples.is_face_sample(s) ? face_sample[src] : vertex_sample[src];
        slot = std::min(slot, s);
    }
    e.sphere_source.resize(tree_.sphere_count());
    for (size_t k = 0; k < tree_.sphere_count(); ++k) e.sphere_source[k] = doc.samples.sources[tree_.sample_index()[k]];

    // Owner node of each triangle.
    std::vector<uint32_t> owner(nt, UINT32_MAX);
    e.tri_sphere.assign(nt * 4, 0);
    for (uint32_t f = 0; f < nt; ++f) {
        const auto& t = e.triangles[f];
        const Eigen::Vector3d &a = e.positions[t[0]], &b = e.positions[t[1]], &c = e.positions[t[2]];
        const Eigen::Vector3d centre = (a + b + c) / 3.0;
        const double r = std::max({(a - centre).norm(), (b - centre).norm(), (c - centre).norm()});
        e.tri_sphere[4 * f + 0] = float(centre.x()), e.tri_sphere[4 * f + 1] = float(centre.y());
        e.tri_sphere[4 * f + 2] = float(centre.z());
        // The float centre moved by rounding: grow the radius by that distance.
        const Eigen::Vector3d fc(e.tri_sphere[4 * f], e.tri_sphere[4 * f + 1], e.tri_sphere[4 * f + 2]);
        e.tri_sphere[4 * f + 3] = round_up(r + (fc - centre).norm());
        reach_ = std::max({reach_, a.norm(), b.norm(), c.norm()});
        if (is_degenerate_triangle(a, b, c)) {
            ++e.degenerate_triangles;
            continue;
        }
        uint32_t s = face_sample[f];
        for (uint32_t v : t) s = std::min(s, vertex_sample[v]);
        if (s != UINT32_MAX) {
            owner[f] = node_of_sample[s];
            continue;
        }
        double best = INFINITY; // no sample on it: nearest active node
        for (uint32_t i = 0; i < nn; ++i) {
            if (!nodes[i].is_active()) continue;
            const double d = (centre - Eigen::Vector3d(nodes[i].center[0], nodes[i].center[1], nodes[i].center[2])).norm();
            if (d < best) best = d, owner[f] = i;
        }
    }
    e.node_tri_begin.assign(nn + 1, 0);
    for (uint32_t f = 0; f < nt; ++f)
        if (owner[f] != UINT32_MAX) ++e.node_tri_begin[owner[f] + 1];
    for (size_t i = 0; i < nn; ++i) {
        e.max_node_tris = std::max(e.max_node_tris, e.node_tri_begin[i + 1]);
        e.node_tri_begin[i + 1] += e.node_tri_begin[i];
    }
    e.node_tris.resize(e.node_tri_begin[nn]);
    {
        std::vector<uint32_t> fill(e.node_tri_begin.begin(), e.node_tri_begin.end() - 1);
        for (uint32_t f = 0; f < nt; ++f)
            if (owner[f] != UINT32_MAX) e.node_tris[fill[owner[f]]++] = f;
    }

    // Reach: children follow their parent in depth-first order, so go backwards.
    // Two radii: triangles only (what a collide decision needs), and triangles and
    // spheres (what the deepest sphere pair needs as well).
    e.node_reach.assign(nn, 0);
    e.node_tri_reach.assign(nn, 0);
    std::vector<uint8_t> has_tris(nn, 0);
    for (size_t i = nn; i-- > 0;) {
        const CompactNode& n = nodes[i];
        const Eigen::Vector3d c(n.center[0], n.center[1], n.center[2]);
        double r = n.bv_radius, rt = 0;
        if (n.is_active()) {
            for (uint32_t k = e.node_tri_begin[i]; k < e.node_tri_begin[i + 1]; ++k)
                for (uint32_t v : e.triangles[e.node_tris[k]]) rt = std::max(rt, (e.positions[v] - c).norm());
            has_tris[i] = e.node_tri_begin[i + 1] > e.node_tri_begin[i];
        } else {
            for (uint32_t child : {uint32_t(i + 1), n.first}) {
                const CompactNode& m = nodes[child];
                const double d = (Eigen::Vector3d(m.center[0], m.center[1], m.center[2]) - c).norm();
                r = std::max(r, d + e.node_reach[child]);
                if (has_tris[child]) rt = std::max(rt, d + e.node_tri_reach[child]), has_tris[i] = 1;
            }
        }
        e.node_tri_reach[i] = has_tris[i] ? round_up(rt) : -1.0f; // negative: nothing to test below
        e.node_reach[i] = round_up(std::max(r, rt));
    }

    // Slabs: a node's subtree is a contiguous run of nodes, so its triangles are a
    // contiguous run of node_tris.
    std::vector<uint32_t> subtree_end(nn);
    for (size_t i = nn; i-- > 0;) subtree_end[i] = nodes[i].is_active() ? uint32_t(i + 1) : subtree_end[nodes[i].first];
    e.node_slab.assign(nn, Slab{});
    std::vector<Eigen::Vector3d> corners;
    for (size_t i = 0; i < nn; ++i) {
        corners.clear();
        for (uint32_t k = e.node_tri_begin[i]; k < e.node_tri_begin[subtree_end[i]]; ++k)
            for (uint32_t v : e.triangles[e.node_tris[k]]) corners.push_back(e.positions[v]);
        e.node_slab[i] = fit_slab(corners);
    }
}

void CollisionModel::init(const SptDocument& doc, const std::string& tree_name) {
    const SamplingTree& t = pick_tree(doc, tree_name);
    tree_ = CompactTree(t, doc.samples);
    diagonal_ = doc.mesh.diagonal;
    reach_ = 0;
    for (const CompactNode& n : tree_.nodes()) {
        if (!n.is_active()) continue;
        max_leaf_ = std::max(max_leaf_, n.count);
        for (uint32_t k = n.first; k < n.first + n.count; ++k)
            reach_ = std::max(reach_, Eigen::Vector3d(tree_.x()[k], tree_.y()[k], tree_.z()[k]).norm() + n.ss_radius);
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
    for (const CompactNode& n : tree_.nodes())
        reach_ = std::max(reach_, Eigen::Vector3d(n.center[0], n.center[1], n.center[2]).norm() + n.bv_radius);
}

size_t CollisionModel::memory_bytes() const {
    const ExactData& e = exact_;
    return tree_.memory_bytes() + e.positions.capacity() * sizeof(Eigen::Vector3d) +
           e.triangles.capacity() * sizeof(Triangle) +
           (e.node_tri_begin.capacity() + e.node_tris.capacity() + e.vertex_tri_begin.capacity() +
            e.vertex_tris.capacity() + e.sphere_source.capacity()) * sizeof(uint32_t) +
           (e.node_reach.capacity() + e.node_tri_reach.capacity() + e.tri_sphere.capacity()) * sizeof(float) +
           e.node_slab.capacity() * sizeof(Slab);
}

} // namespace spt
