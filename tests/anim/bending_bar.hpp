#pragma once
// The tests' deforming object: a bar that bends at its middle, converted with the defaults.
#include "spt/animation.hpp"
#include "spt/compact_tree.hpp"
#include "spt/convert.hpp"
#include "meshgen.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>

namespace spt::bending {

// A bar 2 long along x (0.4 thick), subdivided, whose right half turns about z at x = 0 with
// joint "tip"; vertices within 0.25 of x = 0 blend the two joints.
// Clip "bend": rig node 1 turns by 90 degrees about z over one second.
inline Clip quarter_turn() {
    Clip c;
    c.name = "bend", c.duration = 1;
    NodeChannel ch;
    ch.node = 1;
    ch.rotation.times = {0, 1};
    const Eigen::Quaterniond q(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
    ch.rotation.values = {Eigen::Vector4d(0, 0, 0, 1), Eigen::Vector4d(q.x(), q.y(), q.z(), q.w())};
    c.nodes = {ch};
    return c;
}

// The bar's mesh; `open`: without its two end caps (a tube, open at x = -1 and x = 1, whose
// samples are two-sided).
inline meshgen::RawMesh bar_mesh(bool open) {
    meshgen::RawMesh m = meshgen::box(2, 0.4, 0.4, 8);
    if (open) {
        std::vector<Triangle> kept;
        for (const Triangle& t : m.triangles) {
            bool cap = true;
            for (int k = 0; k < 3; ++k) cap = cap && std::abs(std::abs(m.positions[t[k]].x()) - 1) < 1e-9;
            if (!cap) kept.push_back(t);
        }
        m.triangles = kept;
    }
    return m;
}

inline std::shared_ptr<AnimatedMesh> bending_bar(bool open = false) {
    auto m = std::make_shared<AnimatedMesh>();
    m->imported = meshgen::prepare(bar_mesh(open), open ? "tube.obj" : "bar.obj");
    Rig& rig = m->rig;
    RigNode root;
    root.name = "root";
    root.rest_local.setIdentity();
    root.rest_translation.setZero(), root.rest_rotation.setIdentity(), root.rest_scale.setOnes();
    RigNode tip = root;
    tip.name = "tip", tip.parent = 0;
    rig.nodes = {root, tip};
    rig.bone_slots = {{0, Eigen::Matrix4d::Identity()}, {1, Eigen::Matrix4d::Identity()}};
    rig.skinned = true;
    rig.joint_nodes = {1, 1};
    rig.joint_count = 2;
    for (const Eigen::Vector3d& p : m->imported.mesh.positions) {
        rig.mesh_positions.push_back(p);
        const double w = std::clamp((p.x() + 0.25) / 0.5, 0.0, 1.0);
        VertexInfluences in;
        in.slot = {0, 1, 0, 0};
        in.weight = {1 - w, w, 0, 0};
        rig.influences.push_back(in);
    }
    m->clips = {quarter_turn()};
    return m;
}

struct Bar {
    explicit Bar(bool open = false) : mesh(bending_bar(open)), doc(make_document(mesh->imported.mesh)) {}
    std::shared_ptr<AnimatedMesh> mesh;
    SptDocument doc;
};

inline const Bar& bar() {
    static const Bar b;
    return b;
}

// The bar without its end caps: an open tube, every sample two-sided (its tree has node discs).
inline const Bar& open_bar() {
    static const Bar b(true);
    return b;
}

// Every sphere below a node lies in the node's bounding ball, in the float the walk uses.
inline void expect_bounds_hold(const CompactTree& t) {
    const auto& nodes = t.nodes();
    std::vector<std::pair<uint32_t, uint32_t>> stack; // (node, ancestor)
    for (uint32_t a = 0; a < nodes.size(); ++a) {
        stack.assign(1, {a, a});
        const Eigen::Vector3f ca(nodes[a].center[0], nodes[a].center[1], nodes[a].center[2]);
        while (!stack.empty()) {
            const uint32_t i = stack.back().first;
            stack.pop_back();
            const CompactNode& n = nodes[i];
            if (!n.is_active()) {
                stack.push_back({i + 1, a}), stack.push_back({n.first, a});
                continue;
            }
            for (uint32_t k = n.first; k < n.first + n.count; ++k)
                ASSERT_LE((t.sphere_center(n, k) - ca).norm() + n.ss_radius, nodes[a].bv_radius) << "node " << a;
        }
    }
}

} // namespace spt::bending
