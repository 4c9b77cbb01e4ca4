// The limiter's triangle tree: its float boxes prune only what the exact triangle tests reject,
// at every scale and distance from the origin.
#include "meshgen.hpp"
#include "geometry/triangle_bvh.hpp"
#include <gtest/gtest.h>
#include <random>

using namespace spt;
using detail::BallSegmentProbe;
using detail::TriangleBvh;

namespace {

// The answer with no tree: every triangle tested.
bool touches_one_by_one(const TriangleBvh& bvh, const TriangleMesh& mesh, const BallSegmentProbe& p) {
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
        if (bvh.triangle_within(t, p.centre, p.d2) || bvh.triangle_crossed(t, p.start, p.dir, p.skip, p.end))
            return true;
    return false;
}

TriangleMesh moved(const TriangleMesh& m, double scale, const Eigen::Vector3d& offset) {
    TriangleMesh out = m;
    for (auto& p : out.positions) p = scale * p + offset;
    return out;
}

// Probes near the surface, as the limiter makes them (a ball under a vertex, a segment from
// it), and some anywhere in the mesh's box; a quarter graze a triangle to within a rounding.
std::vector<BallSegmentProbe> probes_near(const TriangleMesh& mesh, int count, uint32_t seed) {
    std::mt19937 rng(seed);
    const auto [lo, hi] = mesh.bounds();
    const double size = (hi - lo).norm();
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<BallSegmentProbe> out;
    for (int i = 0; i < count; ++i) {
        const auto vertex = uint32_t(rng() % mesh.positions.size());
        const Eigen::Vector3d& v = mesh.positions[vertex];
        const Eigen::Vector3d dir = Eigen::Vector3d(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized();
        const double r = size * std::pow(10.0, -3 + 2.5 * u(rng));
        BallSegmentProbe p;
        p.start = i % 5 == 0 ? Eigen::Vector3d(lo + u(rng) * (hi - lo)) : v;
        p.centre = p.start - r * dir;
        p.dir = p.centre - p.start;
        p.d2 = r * r * u(rng);
        p.skip = i % 3 == 0 ? 0.0 : 1e-6;
        p.end = i % 7 == 0 ? 0.0 : u(rng);
        // The limiter's vertex probes name their vertex, whose faces the walk then skips
        // (their crossings lie at the start, within the skip): the answer must not change.
        if (i % 5 != 0 && p.skip > 0 && i % 2 == 0) p.start_vertex = vertex;
        if (i % 4 == 1) {
            // Radius set to a triangle's exact distance, give or take a rounding.
            const auto& t = mesh.triangles[rng() % mesh.triangles.size()];
            const Eigen::Vector3d q = detail::closest_on_triangle(p.centre, mesh.positions[t[0]], mesh.positions[t[1]],
                                                                  mesh.positions[t[2]]);
            const double d2 = (q - p.centre).squaredNorm();
            p.d2 = std::nextafter(d2, i % 8 == 1 ? 0.0 : INFINITY);
        }
        out.push_back(p);
    }
    return out;
}

void expect_same_answers(const TriangleMesh& mesh, int probes, uint32_t seed) {
    const TriangleBvh bvh(mesh);
    int met = 0;
    for (const BallSegmentProbe& p : probes_near(mesh, probes, seed)) {
        const bool want = touches_one_by_one(bvh, mesh, p);
        ASSERT_EQ(bvh.touches(p), want) << "centre " << p.centre.transpose() << " d2 " << p.d2;
        met += want;
    }
    // Both answers occur, or the comparison would prove little.
    EXPECT_GT(met, probes / 20);
    EXPECT_LT(met, probes - probes / 20);
}

} // namespace

TEST(TriangleBvh, ProbesAgreeWithEveryTriangleTestedAtEveryScaleAndOffset) {
    const TriangleMesh torus = meshgen::prepare(meshgen::torus(1.0, 0.35, 40, 30), "torus").mesh;
    for (double scale : {1e-4, 1.0, 1e4})
        for (double offset : {0.0, 1e3, 1e6}) {
            SCOPED_TRACE(testing::Message() << "scale " << scale << " offset " << offset);
            expect_same_answers(moved(torus, scale, Eigen::Vector3d(offset, -offset / 3, offset / 7)), 600, 11);
        }
}

TEST(TriangleBvh, BallGrazingAnOuterVertexFindsItAtEveryScaleAndOffset) {
    // A vertex extreme along an axis is its boxes' face there, so a ball that reaches it
    // along that axis reaches the boxes by no margin at all: any loss in the float boxes
    // shows. One ulp more than the distance touches, the exact distance does not (strict <).
    const TriangleMesh base = meshgen::prepare(meshgen::icosphere(1.0, 3), "sphere").mesh;
    for (double scale : {1e-4, 1.0, 1e4})
        for (double offset : {0.0, 1e3, 1e6}) {
            const TriangleMesh mesh = moved(base, scale, Eigen::Vector3d(offset, offset / 3, -offset));
            const TriangleBvh bvh(mesh);
            for (int axis = 0; axis < 6; ++axis) {
                const int k = axis % 3;
                const double sign = axis < 3 ? 1 : -1;
                uint32_t extreme = 0;
                for (uint32_t v = 0; v < mesh.positions.size(); ++v)
                    if (sign * mesh.positions[v][k] > sign * mesh.positions[extreme][k]) extreme = v;
                for (double gap : {1e-3, 0.3, 3.0}) {
                    BallSegmentProbe p{mesh.positions[extreme], 0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0, 0};
                    p.centre[k] += sign * gap * scale;
                    const double d2 = (p.centre - mesh.positions[extreme]).squaredNorm();
                    SCOPED_TRACE(testing::Message() << "scale " << scale << " offset " << offset << " axis " << axis
                                                    << " gap " << gap);
                    p.d2 = std::nextafter(d2, INFINITY);
                    EXPECT_TRUE(bvh.touches(p));
                    EXPECT_EQ(bvh.touches(p), touches_one_by_one(bvh, mesh, p));
                    p.d2 = d2;
                    EXPECT_EQ(bvh.touches(p), touches_one_by_one(bvh, mesh, p));
                }
            }
        }
}

TEST(TriangleBvh, ProbesAgreeOnATriangleSoup) {
    // Overlapping triangles of every size and direction: boxes overlap everywhere.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    TriangleMesh soup;
    for (uint32_t i = 0; i < 400; ++i) {
        const Eigen::Vector3d c(u(rng), u(rng), u(rng));
        const double s = std::pow(10.0, -2 + 2 * std::abs(u(rng)));
        for (int k = 0; k < 3; ++k) soup.positions.push_back(c + s * Eigen::Vector3d(u(rng), u(rng), u(rng)));
        soup.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    }
    expect_same_answers(soup, 2000, 3);
}

TEST(TriangleBvh, CoordinatesBeyondTheFloatRangeStillFindEveryTriangle) {
    // Relative to the mesh's centre the boxes would overflow a float: every box is met and
    // the double tests alone decide.
    const TriangleMesh torus = meshgen::prepare(meshgen::torus(1.0, 0.35, 12, 10), "torus").mesh;
    expect_same_answers(moved(torus, 1e45, Eigen::Vector3d::Zero()), 300, 17);
}

TEST(TriangleBvh, SingleTriangleAndEmptyMesh) {
    TriangleMesh one;
    one.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    one.triangles = {{0, 1, 2}};
    const TriangleBvh bvh(one);
    EXPECT_TRUE(bvh.touches({{0.2, 0.2, 0.5}, 0.26, {0.2, 0.2, 0.5}, {0, 0, 1}, 0, 0}));
    EXPECT_FALSE(bvh.touches({{0.2, 0.2, 0.5}, 0.24, {0.2, 0.2, 0.5}, {0, 0, 1}, 0, 0}));
    EXPECT_TRUE(bvh.touches({{0.2, 0.2, 0.5}, 0, {0.2, 0.2, 0.5}, {0, 0, -1}, 0, 1}));
    EXPECT_FALSE(bvh.touches({{0.2, 0.2, 0.5}, 0, {0.2, 0.2, 0.5}, {0, 0, -1}, 0, 0.4}));
    const TriangleMesh none;
    EXPECT_FALSE(TriangleBvh(none).touches({{0, 0, 0}, 1, {0, 0, 0}, {1, 0, 0}, 0, 1}));
}
