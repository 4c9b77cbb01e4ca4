// Linear blend skinning and morph targets on rigs made here (core/src/anim/pose.cpp).
#include "bending_bar.hpp"
#include "spt/animation.hpp"
#include "spt/error.hpp"
#include <gtest/gtest.h>

namespace spt {
namespace {

// Two nodes: "root" at the origin and "tip" one unit along x below it; one vertex at
// (1.5, 0, 0) in mesh space following root and tip by `w_tip`; bind = rest, so the inverse bind
// matrices undo the nodes' rest globals.
AnimatedMesh bar(double w_tip) {
    AnimatedMesh m;
    RigNode root, tip;
    root.name = "root";
    root.rest_local.setIdentity();
    root.rest_translation.setZero(), root.rest_rotation.setIdentity(), root.rest_scale.setOnes();
    tip = root;
    tip.name = "tip";
    tip.parent = 0;
    tip.rest_translation = Eigen::Vector3d(1, 0, 0);
    tip.rest_local(0, 3) = 1;
    m.rig.nodes = {root, tip};
    Eigen::Matrix4d undo_tip = Eigen::Matrix4d::Identity();
    undo_tip(0, 3) = -1;
    m.rig.bone_slots = {{0, Eigen::Matrix4d::Identity()}, {1, undo_tip}};
    m.rig.mesh_positions = {Eigen::Vector3d(1.5, 0, 0)};
    VertexInfluences in;
    in.slot = {0, 1, 0, 0};
    in.weight = {1 - w_tip, w_tip, 0, 0};
    m.rig.influences = {in};
    m.rig.skinned = true;
    m.imported.mesh.positions = m.rig.mesh_positions;
    m.imported.mesh.name = "bar";
    return m;
}


TEST(Skinning, TheRestPoseOfABindPoseRigIsTheMesh) {
    const AnimatedMesh m = bar(0.5);
    std::vector<Eigen::Vector3d> p;
    pose_vertices(m, nullptr, 0, p);
    EXPECT_TRUE(p[0].isApprox(Eigen::Vector3d(1.5, 0, 0), 1e-15));
}

TEST(Skinning, AVertexOnOneJointTurnsRigidlyWithIt) {
    const AnimatedMesh m = bar(1.0);
    const Clip c = bending::quarter_turn();
    std::vector<Eigen::Vector3d> p;
    pose_vertices(m, &c, 1.0, p);
    EXPECT_TRUE(p[0].isApprox(Eigen::Vector3d(1, 0.5, 0), 1e-12)); // half a unit past the tip, turned up
}

TEST(Skinning, BlendedWeightsAverageTheJointsTransformsLinearly) {
    const AnimatedMesh m = bar(0.25);
    const Clip c = bending::quarter_turn();
    std::vector<Eigen::Vector3d> p;
    pose_vertices(m, &c, 1.0, p);
    // 0.75 of the root's (1.5, 0, 0) and 0.25 of the tip's (1, 0.5, 0): linear blend, not a turn.
    EXPECT_TRUE(p[0].isApprox(Eigen::Vector3d(1.375, 0.125, 0), 1e-12));
}

TEST(Skinning, MorphTargetsApplyBeforeTheSkin) {
    AnimatedMesh m = bar(1.0);
    MorphTarget up;
    up.name = "up";
    up.vertices = {0};
    up.delta = {Eigen::Vector3d(0.5, 0, 0)};
    m.rig.morph_targets = {up};
    Clip c = bending::quarter_turn();
    MorphChannel mc;
    mc.first_target = 0, mc.target_count = 1;
    mc.weights.times = {0, 1};
    mc.weights.values = {{0.0}, {1.0}};
    c.morphs = {mc};
    std::vector<Eigen::Vector3d> p;
    pose_vertices(m, &c, 1.0, p);
    // Pushed to x = 2 in mesh space (one unit past the tip), then turned with the tip.
    EXPECT_TRUE(p[0].isApprox(Eigen::Vector3d(1, 1, 0), 1e-12));
}

TEST(Skinning, ADefaultMorphWeightHoldsWithoutAClip) {
    AnimatedMesh m = bar(0.0);
    MorphTarget t;
    t.vertices = {0};
    t.delta = {Eigen::Vector3d(0, 0, 2)};
    t.default_weight = 0.5;
    m.rig.morph_targets = {t};
    std::vector<Eigen::Vector3d> p;
    pose_vertices(m, nullptr, 0, p);
    EXPECT_TRUE(p[0].isApprox(Eigen::Vector3d(1.5, 0, 1), 1e-15));
}

TEST(Skinning, AClipIsFoundByNameOrIndexAndAMissingOneNamesThoseThereAre) {
    AnimatedMesh m = bar(1.0);
    m.clips = {bending::quarter_turn(), bending::quarter_turn()};
    m.clips[1].name = "walk";
    EXPECT_EQ(m.find_clip("walk"), 1u);
    EXPECT_EQ(m.find_clip("0"), 0u);
    try {
        m.find_clip("run");
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Usage);
        EXPECT_NE(std::string(e.what()).find("0 'bend', 1 'walk'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(m.find_clip("7"), Error);
}

} // namespace
} // namespace spt
