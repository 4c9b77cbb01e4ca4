// Continuous detection: no contact skipped, time of impact never late.
#include "query_fixtures.hpp"
#include "spt/ccd.hpp"
#include <gtest/gtest.h>

namespace spt {
namespace {

TEST(Ccd, FastThinPlateCannotTunnelThroughAWall) {
    // Radii below the thickness and face samples so the sphere models are as thin as the boxes.
    ConvertOptions wall_opt, plate_opt;
    wall_opt.build.radius.fixed = 0.04f, wall_opt.tolerance = 0.004;
    plate_opt.build.radius.fixed = 0.025f, plate_opt.tolerance = 0.004;
    auto wall = test::make_object(make_box({0.05, 1, 1}, 8), wall_opt);
    auto plate = test::make_object(make_box({0.03, 0.3, 0.3}, 4), plate_opt);
    const Pose before = Pose::from(Eigen::Vector3d(-1, 0.1, 0), Eigen::Quaterniond::Identity());
    const Pose after = Pose::from(Eigen::Vector3d(1, -0.1, 0.05), Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ())));
    QueryScratch s;
    QueryOptions o;
    ASSERT_FALSE(collide_relative(wall->model, plate->model, before, o, s).collide);
    ASSERT_FALSE(collide_relative(wall->model, plate->model, after, o, s).collide) << "both steps miss the wall";
    const CcdResult r = first_contact(wall->model, plate->model, before, after, {}, s);
    ASSERT_TRUE(r.hit);
    // The plate's leading edge, 0.03 + 0.3 sin(0.4 t) ahead of its centre at -1 + 2t, meets x = -0.05 near t = 0.435.
    EXPECT_GT(r.toi, 0.38);
    EXPECT_LT(r.toi, 0.45);
    // Nothing touches before the time of impact; something does soon after it.
    for (int k = 0; k < 200; ++k)
        EXPECT_FALSE(collide_relative(wall->model, plate->model, interpolate(before, after, r.toi * k / 200.0), o, s).collide);
    bool later = false;
    for (int k = 1; k <= 100 && !later; ++k)
        later = collide_relative(wall->model, plate->model, interpolate(before, after, r.toi + 0.002 * k), o, s).collide;
    EXPECT_TRUE(later);
}

TEST(Ccd, RandomMotionsNeverReportContactAfterASampledCollision) {
    auto a = test::make_object(make_torus(1.0, 0.35, 20, 10));
    std::mt19937 rng(8);
    QueryScratch s;
    QueryOptions o;
    int hits = 0;
    for (int it = 0; it < 30; ++it) {
        const Pose p0 = test::random_pose(rng, 3.0), p1 = test::random_pose(rng, 3.0 - 2.5 * (it % 3) / 2.0);
        const CcdResult r = first_contact(a->model, a->model, p0, p1, {}, s);
        // Sampled static queries: the first sampled collision is never before the toi.
        double first_sampled = 2;
        for (int k = 0; k <= 400; ++k)
            if (collide_relative(a->model, a->model, interpolate(p0, p1, k / 400.0), o, s).collide) {
                first_sampled = k / 400.0;
                break;
            }
        if (first_sampled <= 1) {
            ASSERT_TRUE(r.hit) << it;
            EXPECT_LE(r.toi, first_sampled) << it;
            ++hits;
        }
        if (r.hit) {
            EXPECT_LT(r.toi, first_sampled + 0.01 + (first_sampled > 1 ? 1 : 0));
        }
    }
    EXPECT_GT(hits, 5);
}

TEST(Ccd, ZeroMotionIsAStaticQuery) {
    auto a = test::make_object(make_torus(1.0, 0.35, 20, 10));
    QueryScratch s;
    const Pose far = Pose::from(Eigen::Vector3d(4, 0, 0), Eigen::Quaterniond::Identity());
    EXPECT_FALSE(first_contact(a->model, a->model, far, far, {}, s).hit);
    const CcdResult r = first_contact(a->model, a->model, Pose{}, Pose{}, {}, s);
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(r.toi, 0);
}

} // namespace
} // namespace spt
