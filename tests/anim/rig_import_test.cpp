// Reading skins, morph targets and clips through assimp (core/src/anim/rig_import.cpp), on
// assimp's own test models (Debian's assimp-testmodels) and the bundled skinned files.
#include "spt/animation.hpp"
#include "spt/error.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <fstream>

namespace spt {
namespace {

const std::string kModels = "/usr/share/assimp/models/";

double largest_move(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
    double d = 0;
    for (size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
    return d;
}

TEST(RigImport, AMeshWithoutAnimationHasAnEmptyRigAndNoClips) {
    const AnimatedMesh m = import_animated_mesh(kModels + "OBJ/box.obj");
    EXPECT_TRUE(m.clips.empty());
    EXPECT_FALSE(m.rig.skinned);
    std::vector<Eigen::Vector3d> p;
    pose_vertices(m, nullptr, 0, p);
    EXPECT_EQ(p, m.imported.mesh.positions);
}

// glTF's simple skin: its inverse bind matrices are not the inverse of the joints' rest globals,
// so at rest every vertex sits half a unit to -x of the mesh, as glTF's skinning formula says.
TEST(RigImport, GltfSkinFollowsTheFilesInverseBindMatrices) {
    const AnimatedMesh m = import_animated_mesh(kModels + "glTF2/simple_skin/simple_skin.gltf");
    ASSERT_TRUE(m.rig.skinned);
    EXPECT_EQ(m.rig.joint_count, 2u);
    ASSERT_EQ(m.clips.size(), 1u);
    EXPECT_DOUBLE_EQ(m.clips[0].duration, 5.5);
    EXPECT_EQ(m.clips[0].joints_animated, 1u);
    std::vector<Eigen::Vector3d> p;
    pose_vertices(m, nullptr, 0, p);
    for (size_t v = 0; v < p.size(); ++v)
        EXPECT_TRUE(p[v].isApprox(m.imported.mesh.positions[v] - Eigen::Vector3d(0.5, 0, 0), 1e-12)) << v;
}

// FBX: the clip's first frame is the pose the mesh was bound in, though the nodes' rest pose is not.
TEST(RigImport, FbxClipStartsAtTheBindPoseAndListsItsJoints) {
    const AnimatedMesh m = import_animated_mesh(kModels + "FBX/animation_with_skeleton.fbx");
    ASSERT_EQ(m.clips.size(), 1u);
    EXPECT_EQ(m.clips[0].name, "Armature|ArmatureAction");
    EXPECT_NEAR(m.clips[0].duration, 0.8333, 1e-3);
    EXPECT_EQ(m.clips[0].joints_animated, 13u);
    EXPECT_EQ(m.rig.joint_count, 13u);
    std::vector<Eigen::Vector3d> p;
    pose_vertices(m, &m.clips[0], 0, p);
    EXPECT_LT(largest_move(p, m.imported.mesh.positions), 1e-5 * m.imported.mesh.diagonal());
    pose_vertices(m, &m.clips[0], 0.4, p);
    EXPECT_GT(largest_move(p, m.imported.mesh.positions), 0.01 * m.imported.mesh.diagonal());
    // Its vertices have up to 5 joints: kept at 4, and said so.
    ASSERT_FALSE(m.imported.report.warnings.empty());
    EXPECT_NE(m.imported.report.warnings.back().find("more than 4 joints"), std::string::npos);
    for (const VertexInfluences& in : m.rig.influences)
        EXPECT_NEAR(in.weight[0] + in.weight[1] + in.weight[2] + in.weight[3], 1, 1e-12);
}

// Half-Life MDL as assimp 5.2.5 reads it: every bone a child of one node, its real parent only in
// mParent. Chained through their parents, the bones at rest give back the mesh, and the
// `reference` clip, which turns only the root bone, moves the whole mesh rigidly (read as
// siblings, its limbs came apart by 11.7 units on a 10.5 diagonal).
TEST(RigImport, MdlBonesChainThroughTheirParentsSoTheReferenceClipMovesTheMeshRigidly) {
    const AnimatedMesh m = import_animated_mesh(kModels + "MDL/MDL (HL1)/man.mdl");
    ASSERT_TRUE(m.rig.skinned);
    const std::vector<Eigen::Vector3d>& mesh = m.imported.mesh.positions;
    const double diagonal = m.imported.mesh.diagonal();
    std::vector<Eigen::Vector3d> p;
    pose_vertices(m, nullptr, 0, p);
    EXPECT_LT(largest_move(p, mesh), 1e-5 * diagonal);
    const Clip* reference = nullptr;
    for (const Clip& c : m.clips)
        if (c.name == "reference") reference = &c;
    ASSERT_NE(reference, nullptr);
    pose_vertices(m, reference, 0, p);
    Eigen::Matrix3Xd from(3, mesh.size()), to(3, mesh.size());
    for (size_t v = 0; v < mesh.size(); ++v) from.col(Eigen::Index(v)) = mesh[v], to.col(Eigen::Index(v)) = p[v];
    const Eigen::Matrix4d rigid = Eigen::umeyama(from, to, false);
    std::vector<Eigen::Vector3d> moved(mesh.size());
    for (size_t v = 0; v < mesh.size(); ++v) moved[v] = (rigid * mesh[v].homogeneous()).head<3>();
    EXPECT_LT(largest_move(p, moved), 1e-5 * diagonal);
    EXPECT_GT(largest_move(p, mesh), 0.1 * diagonal); // the clip does turn it
}

// Khronos' AnimatedMorphCube: two targets whose weights a clip drives.
TEST(RigImport, MorphTargetWeightsFromAClipMoveTheCube) {
    const AnimatedMesh m = import_animated_mesh(kModels + "glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf");
    ASSERT_EQ(m.rig.morph_targets.size(), 2u);
    ASSERT_EQ(m.clips.size(), 1u);
    ASSERT_EQ(m.clips[0].morphs.size(), 1u);
    const MorphChannel& mc = m.clips[0].morphs[0];
    std::vector<Eigen::Vector3d> p, expected = m.rig.mesh_positions;
    const double t = 1.3;
    std::vector<double> w(2);
    // The weights the clip gives at t, by hand: linear between the two keys around it.
    const auto& times = mc.weights.times;
    const size_t k = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    const double s = (t - times[k]) / (times[k + 1] - times[k]);
    for (int i = 0; i < 2; ++i) w[i] = (1 - s) * mc.weights.values[k][i] + s * mc.weights.values[k + 1][i];
    for (int i = 0; i < 2; ++i)
        for (size_t j = 0; j < m.rig.morph_targets[i].vertices.size(); ++j)
            expected[m.rig.morph_targets[i].vertices[j]] += w[i] * m.rig.morph_targets[i].delta[j];
    const Eigen::Affine3d node = pose_nodes(m.rig, &m.clips[0], t)[m.rig.bone_slots[0].node]; // holds the cube rigidly
    for (Eigen::Vector3d& e : expected) e = node * e;
    pose_vertices(m, &m.clips[0], t, p);
    EXPECT_LT(largest_move(p, expected), 1e-12);
    EXPECT_GT(largest_move(p, m.imported.mesh.positions), 0.1);
}

TEST(RigImport, AClipOfTheMeshIsNamedAndAMissingOneIsAUsageError) {
    const AnimatedMesh m = import_animated_mesh(kModels + "FBX/animation_with_skeleton.fbx");
    EXPECT_EQ(m.find_clip("Armature|ArmatureAction"), 0u);
    try {
        m.find_clip("walk");
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Usage);
        EXPECT_NE(std::string(e.what()).find("'Armature|ArmatureAction'"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace spt
