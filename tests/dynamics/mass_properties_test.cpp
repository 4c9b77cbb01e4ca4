// Mass, centre of mass and inertia of closed meshes (mesh/mass_properties.cpp) and of a moving
// object (dynamics/rigid_mass.cpp).
#include "dynamics/rigid_mass.hpp"
#include "meshgen.hpp"
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include <gtest/gtest.h>

namespace {

using namespace spt;

TriangleMesh prepared(const meshgen::RawMesh& raw, const char* name) { return meshgen::prepare(raw, name).mesh; }

TEST(MassProperties, ABoxHasItsVolumeCentreAndInertia) {
    TriangleMesh box = prepared(meshgen::box(2, 1, 0.5, 3), "box");
    for (Eigen::Vector3d& p : box.positions) p += Eigen::Vector3d(10, -3, 7); // far from the origin
    const SolidMass m = mass_properties(box);
    EXPECT_NEAR(m.volume, 1.0, 1e-12);
    EXPECT_LT((m.centre - Eigen::Vector3d(10, -3, 7)).norm(), 1e-12);
    // A box a x b x c of mass 1: diag((b^2 + c^2) / 12, (a^2 + c^2) / 12, (a^2 + b^2) / 12).
    const Eigen::Vector3d expected((1 + 0.25) / 12, (4 + 0.25) / 12, (4 + 1) / 12.0);
    EXPECT_LT((m.inertia - Eigen::Matrix3d(expected.asDiagonal())).norm(), 1e-12);
}

TEST(MassProperties, AnIcosphereComesCloseToTheBallItApproximates) {
    const SolidMass m = mass_properties(prepared(meshgen::icosphere(1, 4), "ball"));
    const double ball = 4.0 / 3.0 * M_PI;
    EXPECT_NEAR(m.volume, ball, 0.01 * ball); // level 4 is within 1% of the ball
    EXPECT_LT(m.centre.norm(), 1e-9);
    const double i = 0.4 * m.volume; // 2/5 m r^2
    EXPECT_NEAR(m.inertia(0, 0), i, 0.02 * i);
    EXPECT_NEAR(m.inertia(1, 1), i, 0.02 * i);
    EXPECT_NEAR(m.inertia(0, 1), 0, 1e-9);
}

TEST(MassProperties, AMeshEnclosingNothingIsRefusedNamingIt) {
    TriangleMesh flat = prepared(meshgen::box(1, 1, 1), "flat");
    for (Eigen::Vector3d& p : flat.positions) p.y() = 0;
    try {
        mass_properties(flat);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("flat"), std::string::npos) << e.what();
    }
}

SceneObject object_of(const TriangleMesh& mesh, bool closed_mesh) {
    SceneObject o;
    o.name = "rock";
    o.motion = MotionKind::Velocity;
    o.model = std::make_shared<CollisionModel>(make_document(mesh, {}), mesh);
    if (closed_mesh) o.solid = std::make_shared<SolidMass>(mass_properties(mesh));
    return o;
}

TEST(RigidMass, DensityTimesVolumeAndPrincipalAxesAtTheCentreOfMass) {
    const TriangleMesh box = prepared(meshgen::box(2, 1, 0.5, 2), "box");
    SceneObject o = object_of(box, true);
    o.density = 3;
    const detail::RigidMass m = detail::rigid_mass(o, "s.json", 4);
    EXPECT_NEAR(m.mass, 3.0, 1e-12);
    EXPECT_LT(m.object_from_body.translation.norm(), 1e-12);
    // The principal moments are the box's, in some order of its axes.
    Eigen::Vector3d moments = m.principal_moments;
    std::sort(moments.data(), moments.data() + 3);
    EXPECT_NEAR(moments[0], 3 * (1 + 0.25) / 12, 1e-9);
    EXPECT_NEAR(moments[2], 3 * (4 + 1) / 12.0, 1e-9);
    o.mass = 6; // a given mass scales the same inertia
    EXPECT_NEAR(detail::rigid_mass(o, "s.json", 4).principal_moments.maxCoeff(), 6 * 5 / 12.0, 1e-9);
}

TEST(RigidMass, AnOpenModelWithoutMassIsRefusedNamingTheObject) {
    TriangleMesh open = prepared(meshgen::box(1, 1, 1, 2), "open");
    open.triangles.pop_back(); // a hole
    const SceneObject o = object_of(open, false);
    try {
        detail::rigid_mass(o, "scene.json", 2);
        FAIL();
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        EXPECT_NE(what.find("scene.json: at /objects/2: object 'rock'"), std::string::npos) << what;
        EXPECT_NE(what.find("'mass'"), std::string::npos) << what;
    }
}

TEST(RigidMass, AGivenMassWithoutAClosedMeshTakesTheBoxAroundItsSpheres) {
    SceneObject o = object_of(prepared(meshgen::box(2, 2, 2, 2), "cube"), false);
    o.mass = 2;
    const detail::RigidMass m = detail::rigid_mass(o, "s.json", 0);
    EXPECT_EQ(m.mass, 2);
    // About a cube of side 2 (the spheres poke out by their tolerance): 2 (4 + 4) / 12 and a little more.
    EXPECT_GT(m.principal_moments.minCoeff(), 2 * 8 / 12.0 * 0.99);
    EXPECT_LT(m.principal_moments.maxCoeff(), 2 * 8 / 12.0 * 1.1);
}

} // namespace
