// Open and non-manifold meshes made in code (triangle soups, open sheets, open boxes, thin
// open tubes, non-manifold fans, a nearly closed soup with a gap): inside and outside are not
// defined, so no level invents a solid, and the default spheres agree with exact.
#include "hard_support.hpp"
#include "mesh/hard_shapes.hpp"
#include <cstdio>
#include <gtest/gtest.h>

namespace spt {
namespace {

using V = Eigen::Vector3d;

struct OpenSubject {
    const char* name;
    TriangleMesh mesh;
    bool crossing_sheets; // against itself, single sheets cross each other along lines
};

std::vector<OpenSubject> open_meshes() {
    return {{"open sheet", make_sheet(1.5, 6), true},
            {"open box", make_open_box({0.5, 0.5, 0.5}, 3), false},
            {"open tube (thin rod)", make_open_tube(0.03, 1.5, 12), false},
            {"non-manifold fan", make_fan(5), true},
            {"triangle soup", make_triangle_soup(60, 0.2, 3), true},
            {"gapped box", make_gapped_box(0.5, 0.02), false}};
}

// Every part is open, so every sampling sphere is two-sided: centred on the surface, its radius
// at most the protrusion allowance, so the model is a shell within the allowance of the surface
// on both sides, and holds no volume.
TEST(OpenMeshes, EverySphereOfAnOpenPartIsCentredOnTheSurfaceWithinTheAllowance) {
    for (const OpenSubject& subject : open_meshes()) {
        for (uint8_t open : subject.mesh.on_open_part) ASSERT_EQ(open, 1) << subject.name;
        const auto o = hard::make_object(subject.mesh);
        const double cap = kDefaultProtrusion * subject.mesh.diagonal();
        const CompactTree& t = o->model.tree();
        size_t off_surface = 0, one_sided = 0;
        for (const CompactNode& n : t.nodes()) {
            EXPECT_LE(n.ss_radius, cap * (1 + 1e-6)) << subject.name;
            for (uint32_t k = n.first; n.is_active() && k < n.first + n.count; ++k) {
                const uint32_t i = t.sample_index()[k];
                one_sided += !o->doc.samples.is_two_sided(i);
                off_surface += t.sphere_center(n, k) != o->doc.samples.points[i];
            }
        }
        EXPECT_EQ(one_sided, 0u) << subject.name;
        EXPECT_EQ(off_surface, 0u) << subject.name;
    }
}

// Random poses of `a` against `b` (translations uniform in a cube of a's diagonal around its
// centre, so that a good share collide): the fraction on which the default spheres agree with
// exact. Prints the figures docs/hard-cases.md quotes.
double random_pose_agreement(const hard::Object& a, const hard::Object& b, const char* name, const char* against,
                             int* false_negatives = nullptr) {
    const double diag = a.mesh.diagonal();
    const V centre = 0.5 * (a.mesh.bounds().first + a.mesh.bounds().second);
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> u(-0.5 * diag, 0.5 * diag);
    QueryScratch s;
    QueryOptions exact;
    exact.level = QueryLevel::Exact;
    int agree = 0, collide = 0, false_pos = 0;
    const int poses = 400;
    for (int k = 0; k < poses; ++k) {
        const Pose p{hard::random_rotation(rng), centre + V(u(rng), u(rng), u(rng))};
        const bool e = collide_relative(a.model, b.model, p, exact, s).collide;
        const bool sp = collide_relative(a.model, b.model, p, {}, s).collide;
        agree += e == sp, collide += e, false_pos += sp && !e;
    }
    std::printf("[ agreement ] %s against %s: %d of %d random poses (%.2f%%), %d collide, %d false contacts\n", name,
                against, agree, poses, 100.0 * agree / poses, collide, false_pos);
    EXPECT_GT(collide, poses / 20) << "too few contacts to measure: " << name;
    if (false_negatives) *false_negatives = poses - agree - false_pos;
    return double(agree) / poses;
}

TEST(OpenMeshes, DefaultSpheresAgreeWithExactAtRandomPosesAgainstAClosedBody) {
    const auto box = hard::make_object(make_box({0.4, 0.3, 0.2}, 3));
    for (const OpenSubject& subject : open_meshes()) {
        const auto o = hard::make_object(subject.mesh);
        EXPECT_GE(random_pose_agreement(*o, *box, subject.name, "a closed box"), 0.99) << subject.name;
    }
}

TEST(OpenMeshes, DefaultSpheresAgreeWithExactAtRandomPosesOfOpenShellsAgainstThemselves) {
    for (const OpenSubject& subject : open_meshes()) {
        if (subject.crossing_sheets) continue;
        const auto o = hard::make_object(subject.mesh);
        EXPECT_GE(random_pose_agreement(*o, *o, subject.name, "itself"), 0.99) << subject.name;
    }
}

// Two open surfaces that cross share a point, which lies inside a sphere of each (two-sided
// spheres hold every point of their faces), so those spheres overlap: no crossing is missed.
TEST(OpenMeshes, OpenSurfacesThatCrossAlwaysCollideAtTheSphereLevel) {
    for (const OpenSubject& subject : open_meshes()) {
        if (!subject.crossing_sheets) continue;
        const auto o = hard::make_object(subject.mesh);
        int false_negatives = -1;
        random_pose_agreement(*o, *o, subject.name, "itself", &false_negatives);
        EXPECT_EQ(false_negatives, 0) << subject.name;
    }
}

// Open sheets against themselves at random poses: they cross along lines, and pass close
// without meeting. A two-sided sphere's ball pokes out of both sides of its face, so the
// sphere level tests a two-sided sphere as its disc and, with the mesh, as the face the disc
// lies on (docs/hard-cases.md): measured before that, sheet 99.5%, fan 98.25%, soup 88.5%.
TEST(OpenMeshes, DefaultSpheresAgreeWithExactWhereOpenSheetsCrossEachOther) {
    for (const OpenSubject& subject : open_meshes()) {
        if (!subject.crossing_sheets) continue;
        const auto o = hard::make_object(subject.mesh);
        EXPECT_GE(random_pose_agreement(*o, *o, subject.name, "itself"), 0.99) << subject.name;
    }
}

// A sheet standing on its edge just above another: the discs along the standing sheet's edge
// reach past the edge by up to their radius, into the other sheet, but the faces do not meet.
// With the mesh the sphere level asks the faces the discs stand for and agrees with exact; from
// a .spt alone (no faces) it keeps the discs' answer. Crossing, every model collides.
TEST(OpenMeshes, SheetStandingOnItsEdgeJustAboveAnotherCollidesOnlyWhereTheFacesMeet) {
    const auto sheet = hard::make_object(make_sheet(1.0, 6));
    float r = 0;
    for (const CompactNode& n : sheet->model.tree().nodes()) r = std::max(r, n.ss_radius);
    ASSERT_GT(r, 0);
    const Eigen::Quaterniond upright(Eigen::AngleAxisd(0.5 * 3.141592653589793, V::UnitX()));
    QueryScratch s;
    QueryOptions exact;
    exact.level = QueryLevel::Exact;
    for (double scale : {1e-3, 1.0, 1e3}) {
        const auto a = hard::make_object(hard::transformed(sheet->mesh, scale, V(0, 0, 0)));
        const CollisionModel a_spt_only(a->doc);
        for (double gap : {0.5, 0.2, -0.2}) {
            const Pose p{upright, V(0.1, 0.05, 0.5 + gap * r) * scale};
            const bool meet = gap < 0;
            EXPECT_EQ(collide_relative(a->model, a->model, p, exact, s).collide, meet) << scale << " " << gap;
            EXPECT_EQ(collide_relative(a->model, a->model, p, {}, s).collide, meet) << scale << " " << gap;
            EXPECT_TRUE(collide_relative(a_spt_only, a_spt_only, p, {}, s).collide) << scale << " " << gap;
        }
    }
}

// An object wholly inside an open box, an open tube or a box with a slit does not collide
// at any level, solids or not: open parts enclose nothing, however nearly closed.
TEST(OpenMeshes, ObjectInsideAnOpenShellDoesNotCollide) {
    const auto cube = hard::make_object(make_box({0.1, 0.1, 0.1}, 2));
    const auto rod = hard::make_object(make_box({0.01, 0.01, 0.3}, 2));
    struct Case {
        const char* name;
        std::unique_ptr<hard::Object> shell;
        const hard::Object* inner;
        Pose pose;
    };
    Case cases[] = {
        {"open box", hard::make_object(make_open_box({0.5, 0.5, 0.5}, 3)), cube.get(), Pose{Eigen::Quaterniond::Identity(), V(0.1, -0.1, -0.1)}},
        {"gapped box", hard::make_object(make_gapped_box(0.5, 0.02)), cube.get(), Pose{Eigen::Quaterniond::Identity(), V(0, 0.1, 0)}},
        {"open tube", hard::make_object(make_open_tube(0.1, 1.5, 16)), rod.get(), Pose{Eigen::Quaterniond::Identity(), V(0.02, 0, 0.1)}},
    };
    QueryScratch s;
    for (const Case& c : cases)
        for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact})
            for (bool solids : {true, false}) {
                QueryOptions o;
                o.level = level;
                o.solids = solids;
                EXPECT_FALSE(collide_relative(c.shell->model, c.inner->model, c.pose, o, s).collide)
                    << c.name << " level " << int(level) << " solids " << solids;
                EXPECT_FALSE(collide_relative(c.inner->model, c.shell->model, c.pose.inverse(), o, s).collide)
                    << c.name << " swapped, level " << int(level) << " solids " << solids;
            }
}

} // namespace
} // namespace spt
