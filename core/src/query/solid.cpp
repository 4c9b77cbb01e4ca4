// Solid data of a model, and the exact point-in-solid test by a ray's winding number.
#include "query/solid.hpp"
#include "query/exact_data.hpp"
#include "geometry/predicates.hpp"
#include "geometry/ray_parity.hpp"
#include "spt/compact_tree.hpp"
#include <algorithm>
#include <numeric>

namespace spt {
namespace {

// Anchors from the sampling tree: a sphere centre (inside the object, on its piece) of the
// first active node below every node three levels down; spread over the model.
void tree_anchors(const CompactTree& tree, std::vector<Eigen::Vector3f>& out) {
    const auto& nodes = tree.nodes();
    if (nodes.empty()) return;
    std::vector<std::pair<uint32_t, int>> stack{{0u, 0}};
    while (!stack.empty()) {
        auto [i, depth] = stack.back();
        stack.pop_back();
        if (depth < 3 && !nodes[i].is_active()) {
            stack.push_back({nodes[i].first, depth + 1});
            stack.push_back({i + 1, depth + 1});
            continue;
        }
        while (!nodes[i].is_active()) ++i; // the left child follows its parent
        out.push_back(tree.sphere_center(nodes[i], nodes[i].first));
    }
}

// One vertex of every vertex-connected component of the mesh.
void mesh_anchors(const ExactData& e, SolidData& s) {
    std::vector<uint32_t> parent(e.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::vector<uint8_t> used(e.positions.size(), 0);
    for (const auto& t : e.triangles) {
        for (uint32_t v : t) used[v] = 1;
        parent[find(t[1])] = find(t[0]), parent[find(t[2])] = find(t[0]);
    }
    std::vector<uint8_t> seen(e.positions.size(), 0);
    for (uint32_t v = 0; v < e.positions.size(); ++v) {
        if (!used[v] || seen[find(v)]) continue;
        seen[find(v)] = 1;
        s.anchors.push_back(e.positions[v].cast<float>());
        s.anchor_vertex.push_back(v);
    }
}

} // namespace

SolidData SolidData::build(const CompactTree& tree, const ExactData& e, const std::vector<uint8_t>& wall) {
    SolidData s;
    s.of_spheres = SolidGrid::of_spheres(tree, wall);
    if (!e.triangles.empty()) {
        s.of_triangles = SolidGrid::of_triangles(e);
        mesh_anchors(e, s);
    } else {
        tree_anchors(tree, s.anchors);
    }
    return s;
}

size_t SolidData::memory_bytes() const {
    return of_spheres.memory_bytes() + of_triangles.memory_bytes() + anchors.capacity() * sizeof(Eigen::Vector3f) +
           anchor_vertex.capacity() * sizeof(uint32_t);
}

bool inside_closed_parts(const ExactData& e, const Eigen::Vector3d& p) {
    if (e.tri_nodes.empty()) return false;
    double reach = 0;
    for (const auto& v : e.positions) reach = std::max(reach, v.norm());
    const double length = 2 * (reach + p.norm()) + 1;
    std::vector<uint32_t> stack;
    for (const Eigen::Vector3d& dir : parity_directions()) {
        const Eigen::Vector3d q = p + length * dir;
        const Eigen::Vector3d seg = q - p;
        const double seg2 = seg.squaredNorm();
        int winding = 0;
        bool degenerate = false;
        stack.assign(1, 0u);
        while (!stack.empty() && !degenerate) {
            const TriangleNode& n = e.tri_nodes[stack.back()];
            const uint32_t self = stack.back();
            stack.pop_back();
            // Prune nodes whose sphere the segment misses (grown for the float centre).
            const Eigen::Vector3d c(n.center[0], n.center[1], n.center[2]);
            const double s = std::clamp((c - p).dot(seg) / seg2, 0.0, 1.0);
            const double r = double(n.radius) * (1 + 1e-6) + 1e-9 * length;
            if ((p + s * seg - c).squaredNorm() > r * r) continue;
            if (!n.is_leaf()) {
                stack.push_back(n.first), stack.push_back(self + 1);
                continue;
            }
            for (uint32_t k = n.first; k < n.first + n.count; ++k) {
                const uint32_t f = e.tri_order[k];
                if (!e.closed[f]) continue;
                const auto& t = e.triangles[f];
                const Crossing x = segment_crossing(p, q, e.positions[t[0]], e.positions[t[1]], e.positions[t[2]]);
                if (x == Crossing::StartsOn) return true;
                if (x == Crossing::Degenerate) degenerate = true;
                // Signed: the ray leaves a part through faces turned one way and enters through
                // faces turned the other, so the sum counts the parts around p.
                if (x == Crossing::Crosses)
                    winding += orient3d(e.positions[t[0]], e.positions[t[1]], e.positions[t[2]], p) > 0 ? 1 : -1;
            }
        }
        if (!degenerate) return winding != 0;
    }
    return false; // every direction grazed an edge: not provably inside
}

} // namespace spt
