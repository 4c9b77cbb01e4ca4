// Extreme and degenerate values: any finite pose answers at once with finite output or is
// refused; huge, tiny and zero motions; meshes with absurd coordinates (docs/queries.md,
// "Extreme values").
#include "hard_support.hpp"
#include "spt/ccd.hpp"
#include "spt/error.hpp"
#include "spt/response.hpp"
#include "query/brute_force.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <functional>
#include <limits>

namespace spt {
namespace {

constexpr double kMax = std::numeric_limits<double>::max();
using hard::kLevels;
const QueryMode kModes[] = {QueryMode::Any, QueryMode::All, QueryMode::Deepest};

const hard::Object& torus() {
    static const auto o = hard::make_object(make_torus(1.0, 0.35, 24, 12));
    return *o;
}

ErrorKind kind_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.kind();
    }
    return ErrorKind(0);
}

// The torus pair near contact: B turned and 1.9 along x (the tubes overlap by about 0.1).
Pose near_contact() {
    return Pose{Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 1, 0).normalized())),
                Eigen::Vector3d(1.9, 0.2, 0.1)};
}

TEST(ExtremePoses, TranslationOfTheLargestDoubleReturnsPromptly) {
    const Eigen::Vector3d far[] = {{1e25, 0, 0}, {0, -1e200, 0}, {kMax, 0, 0}, {-kMax, kMax, -kMax}, {3, 4, kMax}};
    QueryScratch s;
    for (const Eigen::Vector3d& t : far)
        for (QueryLevel level : kLevels)
            for (QueryMode mode : kModes) {
                QueryOptions o;
                o.level = level, o.mode = mode;
                const QueryResult r = collide_relative(torus().model, torus().model, Pose{near_contact().rotation, t}, o, s);
                // Analytic: the tori are within 1.35 of their centres, so nothing meets; and
                // the answer takes one bound test, no walk.
                EXPECT_FALSE(r.collide) << t.transpose();
                EXPECT_EQ(r.counters.node_pairs, 0u) << t.transpose();
                EXPECT_EQ(r.counters.bound_tests, 1u) << t.transpose();
                EXPECT_TRUE(s.pairs().empty());
            }
}

TEST(ExtremePoses, WorldPosesAtOppositeEndsOfTheDoublesAreApart) {
    QueryScratch s;
    QueryOptions o;
    o.mode = QueryMode::Deepest;
    const Pose a{Eigen::Quaterniond::Identity(), Eigen::Vector3d(-kMax, 0, kMax)};
    const Pose b{near_contact().rotation, Eigen::Vector3d(kMax, 0, -kMax)}; // the difference overflows
    const QueryResult r = collide(torus().model, a, torus().model, b, o, s);
    EXPECT_FALSE(r.collide);
    EXPECT_EQ(r.counters.node_pairs, 0u);
    EXPECT_TRUE(r.deepest.point.allFinite());
}

TEST(ExtremePoses, JustOutsideAndInsideTheModelsReachAnswersAsTheBruteForceReference) {
    // Where the early answer in double hands over to the walk: the reference decides.
    QueryScratch s;
    const auto small = hard::make_object(make_torus(1.0, 0.35, 12, 6));
    for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres})
        for (double d : {2.0, 2.69, 2.7, 2.71, 3.0, 5.0}) {
            QueryOptions o;
            o.level = level;
            const Pose p{Eigen::Quaterniond::Identity(), Eigen::Vector3d(d, 0, 0)};
            EXPECT_EQ(collide_relative(small->model, small->model, p, o, s).collide,
                      collide_brute_force(small->model, small->model, p, o, s).collide)
                << "distance " << d << " level " << int(level);
        }
}

TEST(ExtremePoses, TinyHugeAndUnnormalisedQuaternionsAnswerAsTheirUnitQuaternion) {
    QueryScratch s;
    const Pose unit = near_contact();
    for (QueryLevel level : kLevels) {
        QueryOptions o;
        o.level = level, o.mode = level == QueryLevel::Exact ? QueryMode::Any : QueryMode::Deepest;
        const QueryResult want = collide_relative(torus().model, torus().model, unit, o, s);
        ASSERT_TRUE(want.collide);
        for (double k : {1e-300, 1e-200, 1e-20, 0.5, 3.0, 1e20, 1e200, 1e300}) {
            Pose p = unit;
            p.rotation.coeffs() *= k;
            const QueryResult got = collide_relative(torus().model, torus().model, p, o, s);
            EXPECT_EQ(got.collide, want.collide) << "scale " << k;
            EXPECT_NEAR(got.deepest.depth, want.deepest.depth, 1e-6) << "scale " << k;
            // Through collide() and backtrack() (world poses), too.
            const Pose a{p.rotation, Eigen::Vector3d(-1, 2, 3)};
            const Pose b = Pose{unit_quaternion(a.rotation), a.translation} * unit;
            const QueryResult world = collide(torus().model, a, torus().model, b, o, s);
            EXPECT_EQ(world.collide, want.collide) << "scale " << k;
        }
    }
}

TEST(ExtremePoses, ZeroOrNonFiniteQuaternionAndNonFiniteTranslationAreRefused) {
    QueryScratch s;
    const QueryOptions o;
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const Pose bad[] = {
        Pose{Eigen::Quaterniond(0, 0, 0, 0), Eigen::Vector3d::Zero()},
        Pose{Eigen::Quaterniond(nan, 0, 0, 0), Eigen::Vector3d::Zero()},
        Pose{Eigen::Quaterniond(1, inf, 0, 0), Eigen::Vector3d::Zero()},
        Pose{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, nan, 0)},
        Pose{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0, -inf)},
    };
    const Pose ok = near_contact();
    for (const Pose& p : bad) {
        EXPECT_EQ(kind_of([&] { collide_relative(torus().model, torus().model, p, o, s); }), ErrorKind::BadInput);
        EXPECT_EQ(kind_of([&] { collide(torus().model, p, torus().model, ok, o, s); }), ErrorKind::BadInput);
        EXPECT_EQ(kind_of([&] { first_contact(torus().model, torus().model, ok, p, {}, s); }), ErrorKind::BadInput);
    }
}

TEST(ExtremeMotion, HugeAndTinyMotionDirectionsBacktrackAsTheUnitDirection) {
    QueryScratch s;
    const Eigen::Vector3d unit = Eigen::Vector3d(-1, 0.3, 0.2).normalized();
    for (QueryLevel level : kLevels) {
        QueryOptions o;
        o.level = level;
        const BacktrackResult want =
            backtrack_relative(torus().model, torus().model, near_contact(), unit, o, BacktrackRule::Exact, s);
        ASSERT_GT(want.distance, 0);
        for (double k : {1e-300, 1e-200, 1e200, 1e300}) {
            const Eigen::Vector3d motion = unit * k;
            const BacktrackResult got =
                backtrack_relative(torus().model, torus().model, near_contact(), motion, o, BacktrackRule::Exact, s);
            EXPECT_TRUE(got.converged) << "scale " << k;
            EXPECT_NEAR(got.distance, want.distance, 1e-9 * torus().model.diagonal()) << "scale " << k;
        }
        // The largest double on every axis: a direction like (1, 1, 1).
        const Eigen::Vector3d ones = Eigen::Vector3d::Constant(kMax);
        const BacktrackResult big =
            backtrack_relative(torus().model, torus().model, near_contact(), ones, o, BacktrackRule::Exact, s);
        const BacktrackResult one = backtrack_relative(torus().model, torus().model, near_contact(),
                                                       Eigen::Vector3d::Ones(), o, BacktrackRule::Exact, s);
        EXPECT_TRUE(std::isfinite(big.distance));
        EXPECT_NEAR(big.distance, one.distance, 1e-9 * torus().model.diagonal());
    }
}

TEST(ExtremeMotion, ZeroMotionBacktracksNothingWithoutAQuery) {
    QueryScratch s;
    const BacktrackResult r = backtrack_relative(torus().model, torus().model, near_contact(), Eigen::Vector3d::Zero(),
                                                 {}, BacktrackRule::Exact, s);
    EXPECT_EQ(r.distance, 0);
    EXPECT_EQ(r.queries, 0);
}

TEST(ExtremeCcd, MotionAcrossTheWholeRangeOfDoublesHitsNoLaterThanHalfway) {
    // B flies from one end of the doubles to the other through A: the true first contact is
    // within 1.35 / 2e300 of t = 0.5 (below the rounding of 0.5), so toi <= 0.5 and finite.
    QueryScratch s;
    for (double end : {1e300, kMax}) {
        const Pose b0{Eigen::Quaterniond::Identity(), Eigen::Vector3d(-end, 0, 0)};
        const Pose b1{Eigen::Quaterniond::Identity(), Eigen::Vector3d(end, 0, 0)};
        const CcdResult r = first_contact(torus().model, torus().model, b0, b1, {}, s);
        EXPECT_TRUE(r.hit) << end;
        EXPECT_TRUE(std::isfinite(r.toi)) << end;
        EXPECT_LE(r.toi, 0.5) << end;
        EXPECT_GE(r.toi, 0.0) << end;
        EXPECT_LE(r.queries, 100000) << end;
    }
}

TEST(ExtremeCcd, MotionFarAcrossTheWorldPastTheObjectNeverHits) {
    QueryScratch s;
    const Pose b0{Eigen::Quaterniond::Identity(), Eigen::Vector3d(-1e300, 1e300, 0)};
    const Pose b1{Eigen::Quaterniond(Eigen::AngleAxisd(3.0, Eigen::Vector3d::UnitZ())), Eigen::Vector3d(1e300, 1e300, 0)};
    const CcdResult r = first_contact(torus().model, torus().model, b0, b1, {}, s);
    EXPECT_FALSE(r.hit);
    EXPECT_EQ(r.toi, 1.0);
}

TEST(ExtremeCcd, FarMotionStartingBesideTheObjectIsRuledOutWithinTheBudget) {
    // Found by the query fuzz target: B starts 8 from A and flies 1e272 away while
    // sinking to y = 0.5. It comes within reach of A (2.7) only where |x| > 1e271, so it
    // never touches; the rounding allowance once grew with the far end (1e257 at t = 0)
    // and spent the whole query budget on a false hit near t = 0.
    QueryScratch s;
    const Pose b0{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 8, 0)};
    const Pose b1{Eigen::Quaterniond(0, 1, 0, 0), Eigen::Vector3d(-1.01944e272, 0.5, 0)};
    const CcdResult r = first_contact(torus().model, torus().model, b0, b1, {}, s);
    EXPECT_FALSE(r.hit);
    EXPECT_LT(r.queries, 1000);
}

TEST(ExtremeCcd, ZeroMotionIsOneStaticQuery) {
    QueryScratch s;
    const Pose apart{Eigen::Quaterniond::Identity(), Eigen::Vector3d(5, 0, 0)};
    const CcdResult r = first_contact(torus().model, torus().model, apart, apart, {}, s);
    EXPECT_FALSE(r.hit);
    EXPECT_EQ(r.queries, 1);
}

// A box whose every face has vertices of its own (an unindexed export), moved by `offset`.
std::pair<std::vector<Eigen::Vector3d>, std::vector<Triangle>> unwelded_box(double half, const Eigen::Vector3d& offset) {
    const TriangleMesh box = make_box(Eigen::Vector3d::Ones(), 1);
    std::vector<Eigen::Vector3d> p;
    std::vector<Triangle> t;
    for (const Triangle& tri : box.triangles) {
        const uint32_t base = uint32_t(p.size());
        for (uint32_t v : tri) p.push_back(half * box.positions[v] + offset);
        t.push_back({base, base + 1, base + 2});
    }
    return {p, t};
}

TEST(ExtremeMeshes, CoordinatesBeyond1e16AreRefused) {
    for (double x : {1.0000001e16, 1e30, 3e38, kMax}) {
        const auto mesh = unwelded_box(1, Eigen::Vector3d(x, 0, 0));
        EXPECT_EQ(kind_of([&] { prepare_mesh("far.obj", mesh.first, mesh.second); }), ErrorKind::BadInput) << x;
    }
}

TEST(ExtremeMeshes, SubnormalAndTinyMeshesAreRefused) {
    for (double half : {4.9e-324, 1e-310, 1e-200, 1e-17}) {
        const auto mesh = unwelded_box(half, Eigen::Vector3d::Zero());
        EXPECT_EQ(kind_of([&] { prepare_mesh("tiny.obj", mesh.first, mesh.second); }), ErrorKind::BadInput) << half;
    }
}

TEST(ExtremeMeshes, FarOutMeshWeldsAsAtTheOriginWithoutCellIndexOverflow) {
    // At 9e15 the weld tolerance (1e-6 of the diagonal) makes cell indices beyond int64;
    // the welder widens its cells instead. Integer coordinates are exact in double there.
    const auto [p0, t0] = unwelded_box(8, Eigen::Vector3d::Zero());
    const auto [p1, t1] = unwelded_box(8, Eigen::Vector3d(9e15, -9e15, 9e15));
    const ImportedMesh at_origin = prepare_mesh("box.obj", p0, t0);
    const ImportedMesh far = prepare_mesh("box.obj", p1, t1);
    EXPECT_EQ(at_origin.mesh.positions.size(), 8u);
    EXPECT_EQ(far.mesh.positions.size(), 8u);
    EXPECT_EQ(far.report.welded, at_origin.report.welded);
    EXPECT_EQ(far.mesh.triangles, at_origin.mesh.triangles);
    EXPECT_TRUE(far.report.closed);
}

} // namespace
} // namespace spt
