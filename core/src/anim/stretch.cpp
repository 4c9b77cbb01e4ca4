// How far a clip stretches the surface: edge lengths at poses across the clip (spt/animation.hpp).
#include "anim/keyframes.hpp"
#include "spt/animation.hpp"
#include <algorithm>
#include <cmath>
#include <utility>

namespace spt {
namespace {

// Each undirected edge of the mesh once (faces left out as copies skipped), with its bind length.
std::vector<std::pair<uint32_t, uint32_t>> edges_of(const TriangleMesh& m) {
    std::vector<std::pair<uint32_t, uint32_t>> e;
    e.reserve(3 * m.triangles.size());
    for (size_t f = 0; f < m.triangles.size(); ++f) {
        if (m.copies_earlier_face(f)) continue;
        const Triangle& t = m.triangles[f];
        for (int k = 0; k < 3; ++k) e.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
    }
    std::sort(e.begin(), e.end());
    e.erase(std::unique(e.begin(), e.end()), e.end());
    return e;
}

} // namespace

ClipStretch measure_stretch(const AnimatedMesh& mesh, const Clip& clip, double frames_per_second) {
    ClipStretch out;
    const TriangleMesh& m = mesh.imported.mesh;
    const std::vector<std::pair<uint32_t, uint32_t>> edges = edges_of(m);
    std::vector<double> bind(edges.size());
    for (size_t i = 0; i < edges.size(); ++i) bind[i] = (m.positions[edges[i].first] - m.positions[edges[i].second]).norm();
    const double shortest = 1e-9 * m.diagonal(); // an edge of (almost) no length at bind has no ratio to speak of
    const detail::ClipPoses poses(clip, frames_per_second, 60);
    std::vector<Eigen::Vector3d> posed;
    bool found = false;
    for (int k = 0; k <= poses.count; ++k) {
        const double t = poses.time(k);
        pose_vertices(mesh, &clip, t, posed);
        for (size_t i = 0; i < edges.size(); ++i) {
            if (!(bind[i] > shortest)) continue;
            const double r = (posed[edges[i].first] - posed[edges[i].second]).norm() / bind[i];
            out.smallest = std::min(out.smallest, r);
            if (!found || r > out.largest) {
                found = true;
                out.largest = r, out.time = t;
                out.edge[0] = edges[i].first, out.edge[1] = edges[i].second;
            }
        }
    }
    if (!found) return out;
    out.where = 0.5 * (m.positions[out.edge[0]] + m.positions[out.edge[1]]);
    const Rig& rig = mesh.rig;
    if (rig.skinned && out.edge[0] < rig.influences.size()) {
        const VertexInfluences& in = rig.influences[out.edge[0]];
        const int k = int(std::max_element(in.weight.begin(), in.weight.end()) - in.weight.begin());
        out.joint = rig.nodes[rig.bone_slots[in.slot[k]].node].name;
    }
    return out;
}

} // namespace spt
