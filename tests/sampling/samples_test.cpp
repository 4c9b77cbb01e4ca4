// Samples: stored encodings, radius limits on thin parts, corners and open sheets, face coverage.
#include "meshgen.hpp"
#include "spt/samples.hpp"
#include "test_support.hpp"
#include "mesh/shapes.hpp"
#include "sampling/encoding.hpp"
#include "sampling/surface_samples.hpp"
#include "spt/convert.hpp"
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <random>

using namespace spt;

TEST(Samples, OctahedralNormalRoundTripIsWithinATenthOfAMilliradian) {
    std::mt19937 rng(7);
    std::normal_distribution<float> g;
    double worst = 0;
    for (int i = 0; i < 100000; ++i) {
        const Eigen::Vector3f n = Eigen::Vector3f(g(rng), g(rng), g(rng)).normalized();
        const Eigen::Vector3d d = decode_normal(encode_normal(n)).cast<double>();
        // The angle from the cross product: acos near 1 would measure float noise instead.
        worst = std::max(worst, std::atan2(n.cast<double>().cross(d).norm(), n.cast<double>().dot(d)));
    }
    EXPECT_LT(worst, 1e-4);
    for (const Eigen::Vector3f& axis : std::vector<Eigen::Vector3f>{Eigen::Vector3f::UnitX(), -Eigen::Vector3f::UnitZ()})
        EXPECT_LT((decode_normal(encode_normal(axis)) - axis).norm(), 1e-6f);
}

TEST(Samples, SnappedNormalSurvivesEncodingUnchanged) {
    SampleSet s;
    s.add({0, 0, 0}, Eigen::Vector3f(0.3f, -0.5f, 0.8f).normalized(), 0, 1);
    EXPECT_EQ(encode_normal(s.normals[0]), encode_normal(decode_normal(encode_normal(s.normals[0]))));
    EXPECT_EQ(decode_normal(encode_normal(s.normals[0])), s.normals[0]);
}

TEST(Samples, SphereTouchesTheSurfaceFromInside) {
    SampleSet s;
    s.add({1, 2, 3}, {0, 0, 1}, 0, 1);
    EXPECT_EQ(s.sphere_center(0, 0.5f), Eigen::Vector3f(1, 2, 2.5f));
}

TEST(Samples, LengthsStoreAsBfloat16CapsRoundedDown) {
    for (float v : {0.0f, 1e-9f, 0.1f, 3.14159f, 1e30f}) {
        EXPECT_LE(decode_length(encode_length(v, true)), v);
        EXPECT_NEAR(decode_length(encode_length(v, false)), v, v * 0.004f);
        EXPECT_NEAR(decode_length(encode_length(v, true)), v, v * 0.008f);
    }
    EXPECT_TRUE(std::isinf(decode_length(encode_length(INFINITY, true))));
}

TEST(RadiusLimiter, ThinPlateCapsRadiusAtHalfItsThicknessPlusAllowance) {
    const ImportedMesh m = meshgen::prepare(meshgen::box(2, 2, 0.1, 8), "plate");
    const double allowance = 0.01;
    const RadiusLimiter limiter(m.mesh, allowance);
    const float r = limiter.limit(Eigen::Vector3d(0.1, 0.2, 0.05), {0, 0, 1}, 1.0f, false);
    EXPECT_NEAR(r, (0.1 + allowance) / 2, 0.01 * 0.055 + 1e-4);
}

TEST(RadiusLimiter, FlatInteriorKeepsTheRequestedRadius) {
    const ImportedMesh m = meshgen::prepare(meshgen::box(2, 2, 2, 8), "cube");
    const RadiusLimiter limiter(m.mesh, 0.001);
    EXPECT_EQ(limiter.limit(Eigen::Vector3d(0, 0, 1), {0, 0, 1}, 0.5f, false), 0.5f);
}

TEST(RadiusLimiter, CubeCornerProtrudesAtMostTheAllowance) {
    // A sphere tangent at a corner along the diagonal pokes out of all three faces by
    // r (1 - 1/sqrt 3); the cap keeps that within the allowance.
    const ImportedMesh m = meshgen::prepare(meshgen::box(2, 2, 2, 1), "cube");
    const double allowance = 0.01;
    const RadiusLimiter limiter(m.mesh, allowance);
    const Eigen::Vector3f corner(1, 1, 1), n = corner.normalized();
    const float r = limiter.limit(corner.cast<double>(), n, 1.0f, false);
    EXPECT_NEAR(r * (1 - 1 / std::sqrt(3.0)), allowance, allowance * 0.02);
}

TEST(RadiusLimiter, SphereThroughAThinRodIsCaughtFromOutside) {
    // Far larger than the rod: the centre passes through and lies outside the body.
    const ImportedMesh m = meshgen::prepare(meshgen::cylinder(0.05, 2.0, 24), "rod");
    const RadiusLimiter limiter(m.mesh, 0.005);
    const float r = limiter.limit(Eigen::Vector3d(0.05, 0, 1.0), {1, 0, 0}, 1.0f, false);
    EXPECT_LT(r, 0.06f);
    EXPECT_GT(r, 0.04f);
}

TEST(RadiusLimiter, SphereOnAnEdgeOfAThinBarWhoseCentreLeavesByTheEndIsCaught) {
    // A bar thinner than the allowance, sampled where its underside meets its end. The sphere's
    // centre rises in the end face's plane, and a rounded normal tips it a hair out of the bar
    // (regr01.obj's beams: spheres of 348 units on a lip 1 unit thick). Started at the sample,
    // the segment to the centre then leaves the bar at its start and crosses no face, and the end
    // face is too small to come near the centre: the whole radius passed. Started a little inside
    // the sample's face, the segment crosses the top.
    const double thickness = 0.004, allowance = 0.01;
    const ImportedMesh m = meshgen::prepare(meshgen::box(2, 0.3, thickness, 4), "bar");
    const RadiusLimiter limiter(m.mesh, allowance);
    const Eigen::Vector3f tipped = Eigen::Vector3f(-1e-7f, 0, -1).normalized(); // -n leans out of the end x = 1
    for (double y : {-0.15, -0.075, 0.0, 0.0375, 0.15}) {
        const Eigen::Vector3d p(1.0, y, -thickness / 2), inside_face(0.5, 0.0, -thickness / 2);
        EXPECT_LE(limiter.limit(p, tipped, 1.0f, false, ~0u, &inside_face), allowance * 1.01) << "y " << y;
    }
}

TEST(RadiusLimiter, SegmentThroughTheEdgeTwoBackTrianglesShareIsCaught) {
    // A wall 9 units thick (FCL's env.obj: 995.5 <= x <= 1004.5), its two large faces split along
    // opposite diagonals. A face sample on the line where the front face's bisection meets the
    // back face's diagonal sends its segment exactly through the back triangles' shared edge,
    // which rounding put just outside both: spheres of 1,672 units passed the allowance of
    // 22.5, and `spheres` agreed with `exact` on 365 of 600 FCL-style poses.
    const double x0 = 995.5, x1 = 1004.5, y0 = -2987.5, y1 = 2987.5, z0 = 2012.5, z1 = 2987.5;
    std::vector<Eigen::Vector3d> v;
    for (double x : {x0, x1})
        for (double y : {y0, y1})
            for (double z : {z0, z1}) v.emplace_back(x, y, z);
    auto at = [](int ix, int iy, int iz) { return uint32_t(4 * ix + 2 * iy + iz); };
    const std::vector<Triangle> t = {
        {at(1, 0, 1), at(1, 0, 0), at(1, 1, 1)}, {at(1, 1, 1), at(1, 0, 0), at(1, 1, 0)}, // front, x = x1
        {at(0, 0, 0), at(0, 0, 1), at(0, 1, 0)}, {at(0, 1, 0), at(0, 0, 1), at(0, 1, 1)}, // back, x = x0
        {at(0, 0, 0), at(1, 0, 0), at(0, 0, 1)}, {at(0, 0, 1), at(1, 0, 0), at(1, 0, 1)}, // y = y0
        {at(0, 1, 0), at(0, 1, 1), at(1, 1, 0)}, {at(1, 1, 0), at(0, 1, 1), at(1, 1, 1)}, // y = y1
        {at(0, 0, 0), at(0, 1, 0), at(1, 0, 0)}, {at(1, 0, 0), at(0, 1, 0), at(1, 1, 0)}, // z = z0
        {at(0, 0, 1), at(1, 0, 1), at(0, 1, 1)}, {at(1, 0, 1), at(1, 1, 1), at(0, 1, 1)}, // z = z1
    };
    const ImportedMesh m = prepare_mesh("wall", v, t);
    ASSERT_TRUE(m.report.closed);
    const double allowance = 22.5;
    const RadiusLimiter limiter(m.mesh, allowance);
    const Eigen::Vector3d a(x1, y0, z1), b(x1, y1, z0), inside_face = (a + Eigen::Vector3d(x1, y0, z0) + Eigen::Vector3d(x1, y1, z1)) / 3;
    for (int k = 1; k < 64; ++k) {
        const Eigen::Vector3d p = a + (k / 64.0) * (b - a); // on the back diagonal's line, seen from the front
        // Tangent at the front with its centre past the back, a sphere pokes out of the back by 2r - 9.
        EXPECT_LE(limiter.limit(p, {1, 0, 0}, 1672.0f, false, ~0u, &inside_face), allowance * 1.01) << "k " << k;
    }
}

TEST(RadiusLimiter, NoSphereOfAClosedPartOfRegr01PokesOutOfTheModelsBox) {
    // assimp's OBJ/regr01.obj, a building of thin beams and lips with flat closed trims. A sphere
    // tangent at a corner of a face of a closed part lies within the model's box grown by twice
    // the allowance (a sphere at the allowance's floor may poke out that far, by design). The
    // ends of its beams gave spheres of 348 units whose centres sat 300 units above the model,
    // and its flat trims (closed parts of no volume, now sampled as sheets) spheres of 181 units
    // 200 units beside it. At 8 times the allowance, sliver faces (two corners 0.01 apart) sent
    // spheres of 171 units out of the box: their centre's way left the solid at once.
    const ImportedMesh m = import_mesh(test::assimp_models() + "/OBJ/regr01.obj");
    const TriangleMesh& mesh = m.mesh;
    EXPECT_GE(m.report.flat_closed_parts, 1u);
    size_t tested = 0;
    for (const double share : {kDefaultProtrusion, 8 * kDefaultProtrusion}) {
        const double allowance = share * mesh.diagonal();
        const RadiusLimiter limiter(mesh, allowance);
        Eigen::AlignedBox3d box;
        for (const Eigen::Vector3d& v : mesh.positions) box.extend(v);
        box.min().array() -= 2 * allowance, box.max().array() += 2 * allowance;
        for (uint32_t f = 0; f < mesh.triangles.size(); ++f) {
            if (mesh.on_open_part[f] || mesh.copies_earlier_face(f)) continue;
            const std::optional<FaceFrame> frame = face_frame(mesh, f); // as a face sample asks the limiter
            if (!frame) continue;
            const auto& t = mesh.triangles[f];
            const Eigen::Vector3f n = frame->normal;
            for (const Eigen::Vector3d& p : {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]}) {
                const float r = limiter.limit(p, n, 1000.0f, false, ~0u, &frame->centroid);
                const Eigen::Vector3d centre = p - double(r) * n.cast<double>(), reach = Eigen::Vector3d::Constant(r);
                ++tested;
                EXPECT_TRUE(box.contains(centre - reach) && box.contains(centre + reach))
                    << "allowance " << allowance << ", face " << f << " corner " << p.transpose() << ": radius " << r
                    << ", centre " << centre.transpose();
            }
        }
    }
    EXPECT_GT(tested, 2000u);
}

namespace {
// Generalised winding number of `faces` around q (solid angles summed over 4 pi): about 1 inside
// a closed part, 2 where two overlap, about 0 outside; the test's own, independent of the core's.
double winding(const TriangleMesh& m, const std::vector<uint32_t>& faces, const Eigen::Vector3d& q) {
    double sum = 0;
    for (uint32_t f : faces) {
        const auto& t = m.triangles[f];
        const Eigen::Vector3d a = m.positions[t[0]] - q, b = m.positions[t[1]] - q, c = m.positions[t[2]] - q;
        const double la = a.norm(), lb = b.norm(), lc = c.norm();
        sum += 2 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
    }
    return sum / (4 * M_PI);
}
} // namespace

TEST(RadiusLimiter, Regr01sNeedlesAndTheVerticesTheyFoldKeepTheirCentresInTheSolid) {
    // regr01's walls hold needles: faces 10^-5 wide lying in a wall's plane, some wound against
    // their neighbours. A needle's normal and a vertex normal averaged over folded faces tell
    // nothing of where the solid is: spheres of 12 units (9.5 allowances) stood beside a wall on
    // a needle, and a vertex's sphere poked out by 3.5 allowances. A sphere larger than the
    // allowance whose centre lies outside the solid pokes out by more than it.
    const ImportedMesh m = import_mesh(test::assimp_models() + "/OBJ/regr01.obj");
    const TriangleMesh& mesh = m.mesh;
    ConvertStats stats;
    const SptDocument doc = make_document(mesh, {}, &stats);
    ASSERT_GT(stats.automatic_tolerance, 0);
    const double allowance = stats.automatic_tolerance / 8;
    std::vector<uint32_t> closed;
    std::vector<uint8_t> needle(mesh.triangles.size(), 0);
    for (uint32_t f = 0; f < mesh.triangles.size(); ++f) {
        if (mesh.on_open_part[f] || mesh.copies_earlier_face(f)) continue;
        closed.push_back(f);
        const std::optional<FaceFrame> frame = face_frame(mesh, f);
        needle[f] = frame && frame->width < allowance;
    }
    const SampleSet& s = doc.samples;
    size_t needles = 0, vertices = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s.is_two_sided(i) || (s.is_face_sample(i) && !needle[s.source_index(i)])) continue;
        needles += s.is_face_sample(i);
        // A sphere within the allowance pokes out by at most twice it, as anywhere (the floor).
        if (!(s.max_radius[i] > 1.01 * allowance)) continue;
        if (!s.is_face_sample(i) && vertices++ % 3 != 0) continue; // a third of the vertices
        const Eigen::Vector3d centre = s.points[i].cast<double>() + s.origin - double(s.max_radius[i]) * s.normals[i].cast<double>();
        EXPECT_GE(std::abs(winding(mesh, closed, centre)), 0.5)
            << "sample " << i << (s.is_face_sample(i) ? " (needle face " : " (vertex ") << s.source_index(i)
            << "): radius " << s.max_radius[i] << ", allowance " << allowance;
    }
    EXPECT_GT(vertices, 500u);
    EXPECT_GT(needles, 100u);
}

TEST(Samples, VerticesWithoutNormalAreLeftOut) {
    auto raw = meshgen::box(1, 1, 1, 1);
    raw.positions.push_back({9, 9, 9});
    const ImportedMesh m = meshgen::prepare(raw, "stray");
    const SampleSet s = test::vertex_samples(m.mesh);
    EXPECT_EQ(s.size(), 8u);
    for (size_t i = 0; i < s.size(); ++i) {
        EXPECT_FALSE(s.is_face_sample(i));
        EXPECT_TRUE(m.mesh.normal_valid[s.source_index(i)]);
        EXPECT_NEAR(s.spacing[i], (1.0 + 1.0 + std::sqrt(2.0)) / 3.0 * 1.0, 0.2);
    }
}

TEST(Samples, FaceGapFormulaIsExactForAFlatFace) {
    const double r = 0.7, eps = 0.01;
    const double h = max_face_sample_gap(r, eps);
    EXPECT_NEAR(std::sqrt(h * h + r * r) - r, eps, 1e-12);
}

namespace {

// Largest distance from `points` random points of face f to the nearest sample on f.
double farthest_from_own_samples(const TriangleMesh& mesh, const SampleSet& s, uint32_t f, int points, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    const auto& t = mesh.triangles[f];
    double worst = 0;
    for (int k = 0; k < points; ++k) {
        double a = u(rng), b = u(rng);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        const Eigen::Vector3d p = mesh.positions[t[0]] + a * (mesh.positions[t[1]] - mesh.positions[t[0]]) +
                                  b * (mesh.positions[t[2]] - mesh.positions[t[0]]);
        double nearest = INFINITY;
        for (size_t i = 0; i < s.size(); ++i)
            if (s.source_index(i) == f) nearest = std::min(nearest, (s.position(i) - p).norm());
        worst = std::max(worst, nearest);
    }
    return worst;
}

} // namespace

TEST(Samples, FaceSamplesCoverEveryPointOfTheirTriangle) {
    const ImportedMesh m = meshgen::prepare(meshgen::box(3, 1, 0.5, 1), "slab");
    SampleSet s;
    const RadiusLimiter limiter(m.mesh, 0.01);
    RadiusRule fixed;
    fixed.fixed = 0.2f;
    const double eps = 0.02, gap = max_face_sample_gap(0.2, eps);
    std::vector<uint32_t> tris(m.mesh.triangles.size());
    for (uint32_t f = 0; f < tris.size(); ++f) tris[f] = f, add_face_samples(s, limiter, f, eps, fixed, 1.0f);
    std::mt19937 rng(3);
    for (uint32_t f = 0; f < tris.size(); ++f)
        EXPECT_LE(farthest_from_own_samples(m.mesh, s, f, 200, rng), gap * (1 + 1e-5)) << "face " << f;
}

TEST(Samples, TwoSidedFaceSamplesHoldEveryPointOfTheirTriangle) {
    // An open sheet of long thin and right triangles: every point of a face lies inside a
    // two-sided sphere of that face, within kTwoSidedCoverage of its radius.
    std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {3, 0, 0}, {3, 0.4, 0}, {0, 0.4, 0}, {1.5, 2, 0.3}};
    const ImportedMesh m = prepare_mesh("sheet", p, {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}});
    SampleSet s;
    const double r = 0.2;
    const RadiusLimiter limiter(m.mesh, 0.01, r);
    RadiusRule fixed;
    fixed.fixed = float(r);
    for (uint32_t f = 0; f < m.mesh.triangles.size(); ++f) add_face_samples(s, limiter, f, 0.05, fixed, 0.5f);
    std::mt19937 rng(5);
    for (uint32_t f = 0; f < m.mesh.triangles.size(); ++f)
        EXPECT_LE(farthest_from_own_samples(m.mesh, s, f, 400, rng), kTwoSidedCoverage * r * (1 + 1e-5)) << "face " << f;
    for (size_t i = 0; i < s.size(); ++i) EXPECT_TRUE(s.is_two_sided(i));
}

TEST(RadiusLimiter, OpenSheetSpheresAreTwoSidedOnALadderUpToTheirCap) {
    // Centred on the sheet, a sphere pokes out of either side by its radius: the cap, or the
    // rung of the ladder cap * 2^(-k/2) at or below the radius asked for.
    const TriangleMesh sheet = make_sheet(2, 4);
    const double allowance = 0.01, cap = 0.02;
    const RadiusLimiter limiter(sheet, allowance, cap);
    EXPECT_TRUE(limiter.on_open_part(0));
    EXPECT_TRUE(limiter.face_on_open_part(0));
    EXPECT_NEAR(limiter.limit(Eigen::Vector3d(0.1, 0.2, 0), {0, 0, 1}, 1.0f, true), cap, 1e-8);
    EXPECT_NEAR(limiter.limit(Eigen::Vector3d(0.1, 0.2, 0), {0, 0, 1}, 0.015f, true), cap / std::sqrt(2.0), 1e-8);
    EXPECT_NEAR(limiter.limit(Eigen::Vector3d(0.1, 0.2, 0), {0, 0, 1}, 0.0101f, true), cap / 2, 1e-8);
    EXPECT_NEAR(RadiusLimiter(sheet, allowance).limit(Eigen::Vector3d(0.1, 0.2, 0), {0, 0, 1}, 1.0f, true), allowance, 1e-8);
}

TEST(Samples, EverySampleOfAnOpenPartIsTwoSidedAndCentredOnTheSurface) {
    const TriangleMesh sheet = make_sheet(2, 4);
    const SampleSet s = test::vertex_samples(sheet);
    ASSERT_GT(s.size(), 0u);
    for (size_t i = 0; i < s.size(); ++i) {
        EXPECT_TRUE(s.is_two_sided(i));
        EXPECT_EQ(s.sphere_center(i, 0.3f), s.points[i]);
        EXPECT_LT(s.source_index(i), sheet.positions.size());
    }
}

TEST(RadiusLimiter, OpenBoxInventsNoSolidButAClosedCubeBesideItKeepsItsRadii) {
    // A box without its top face, and a closed cube elsewhere in the same mesh: the open
    // box's inside is not a solid (its spheres stay within the allowance, even where walls
    // hide its back), the cube's is.
    auto raw = meshgen::box(2, 2, 2, 1);
    auto cube = meshgen::box(1, 1, 1, 1);
    std::vector<Eigen::Vector3d> p = raw.positions;
    std::vector<spt::Triangle> t;
    for (const auto& tri : raw.triangles) {
        bool top = true;
        for (uint32_t v : tri) top = top && raw.positions[v].z() > 0.99;
        if (!top) t.push_back(tri);
    }
    const uint32_t base = uint32_t(p.size());
    for (const auto& q : cube.positions) p.push_back(q + Eigen::Vector3d(5, 0, 0));
    for (auto tri : cube.triangles) t.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
    const ImportedMesh m = spt::prepare_mesh("cup and cube", std::move(p), std::move(t));
    const double allowance = 0.01;
    const RadiusLimiter limiter(m.mesh, allowance);
    // Find a vertex of each part (the import may reorder vertices).
    uint32_t cup_vertex = 0, cube_vertex = 0;
    for (uint32_t v = 0; v < m.mesh.positions.size(); ++v)
        (m.mesh.positions[v].x() > 3 ? cube_vertex : cup_vertex) = v;
    EXPECT_TRUE(limiter.on_open_part(cup_vertex));
    EXPECT_FALSE(limiter.on_open_part(cube_vertex));
    // The cup's floor, seen from inside (normal +z into the cup): a sphere below it would lie
    // outside the cup; a side wall's back is enclosed by the other walls, and still capped.
    EXPECT_NEAR(limiter.limit(Eigen::Vector3d(0.2, 0.1, -1), {0, 0, -1}, 0.5f, limiter.on_open_part(cup_vertex)),
                allowance, 1e-6);
    EXPECT_NEAR(limiter.limit(Eigen::Vector3d(1, 0.1, 0), {1, 0, 0}, 0.5f, limiter.on_open_part(cup_vertex)), allowance,
                1e-6);
    EXPECT_NEAR(limiter.limit(Eigen::Vector3d(5.5, 0.1, 0), {1, 0, 0}, 0.3f, limiter.on_open_part(cube_vertex)), 0.3f,
                0.3f * 0.011);
}
