// Welding: every vertex maps to the first vertex of its cluster, whatever the cells and the
// hash table's collisions, and nothing farther apart than the tolerance is merged.
#include "mesh/weld.hpp"
#include <gtest/gtest.h>
#include <random>

using namespace spt;

namespace {

// Clusters of copies within a quarter of the tolerance of their centre, centres at least
// five tolerances apart, shuffled: the right answer is the first copy of each cluster.
struct Clusters {
    std::vector<Eigen::Vector3d> positions;
    std::vector<uint32_t> cluster; // of each position
};

Clusters make_clusters(size_t count, double tolerance, const Eigen::Vector3d& offset, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    Clusters c;
    std::vector<Eigen::Vector3d> centres;
    // A grid with a spacing of 5 tolerances, jittered by less than one: neighbours land in
    // neighbouring cells, and many points lie near cell boundaries.
    const int side = int(std::cbrt(double(count))) + 1;
    for (size_t i = 0; i < count; ++i) {
        const Eigen::Vector3d g(double(i % side), double(i / side % side), double(i / side / side));
        centres.push_back(offset + tolerance * (5 * g + 0.9 * Eigen::Vector3d(u(rng), u(rng), u(rng))));
    }
    for (uint32_t k = 0; k < centres.size(); ++k)
        for (int copy = 0, n = 1 + int(rng() % 6); copy < n; ++copy) {
            c.positions.push_back(centres[k] + 0.25 * tolerance * Eigen::Vector3d(u(rng), u(rng), u(rng)) / std::sqrt(3.0));
            c.cluster.push_back(k);
        }
    std::vector<size_t> order(c.positions.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    Clusters shuffled;
    for (size_t i : order) shuffled.positions.push_back(c.positions[i]), shuffled.cluster.push_back(c.cluster[i]);
    return shuffled;
}

} // namespace

TEST(Weld, EveryCopyMapsToTheFirstOfItsClusterNearAndFarFromTheOrigin) {
    for (const Eigen::Vector3d& offset : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1e6, -3e5, 7e4)}) {
        const double tolerance = 1e-3;
        const Clusters c = make_clusters(20000, tolerance, offset, 9);
        std::vector<Eigen::Vector3d> welded;
        const std::vector<uint32_t> map = detail::weld_positions(c.positions, tolerance, welded);
        ASSERT_EQ(map.size(), c.positions.size());
        std::vector<int64_t> first_of(20000, -1); // welded index of each cluster
        for (size_t i = 0; i < map.size(); ++i) {
            int64_t& want = first_of[c.cluster[i]];
            if (want < 0) {
                want = int64_t(map[i]);
                ASSERT_EQ(welded[map[i]], c.positions[i]) << "a cluster's first copy is its representative";
            }
            ASSERT_EQ(int64_t(map[i]), want) << "position " << i;
        }
        EXPECT_EQ(welded.size(), 20000u);
    }
}

TEST(Weld, ZeroToleranceMergesExactCopiesOnly) {
    const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1e-9, 0, 0}, {0, 0, 0}, {1, 2, 3}, {1, 2, 3}};
    std::vector<Eigen::Vector3d> welded;
    EXPECT_EQ(detail::weld_positions(p, 0.0, welded), (std::vector<uint32_t>{0, 1, 0, 2, 2}));
    EXPECT_EQ(welded.size(), 3u);
}

TEST(Weld, PairsJustInsideTheToleranceMergeAndJustOutsideDoNot) {
    // Pairs along random directions, far apart from each other: the distance alone decides,
    // across every cell boundary the pair may straddle.
    std::mt19937 rng(4);
    std::normal_distribution<double> g;
    const double tolerance = 1e-4;
    for (double factor : {0.999, 1.001}) {
        std::vector<Eigen::Vector3d> p;
        for (int i = 0; i < 5000; ++i) {
            const Eigen::Vector3d a(0.01 * i, 0.37 * (i % 7), 0.1 * (i % 13));
            p.push_back(a);
            p.push_back(a + factor * tolerance * Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
        }
        std::vector<Eigen::Vector3d> welded;
        const std::vector<uint32_t> map = detail::weld_positions(p, tolerance, welded);
        for (size_t i = 0; i < p.size(); i += 2) {
            if (factor < 1)
                ASSERT_EQ(map[i + 1], map[i]) << "pair " << i / 2;
            else
                ASSERT_NE(map[i + 1], map[i]) << "pair " << i / 2;
        }
    }
}

TEST(Weld, ExactCopiesOfKeptVerticesMapToThemAmongNearCopiesAtCellBoundaries) {
    // A soup as STL gives it (every corner repeated), mixed with near copies, on a lattice of
    // the weld's cell size so that many points sit on cell boundaries. Checked by brute force:
    // each point maps to a kept vertex within the tolerance, an exact copy of a kept vertex to
    // that vertex, and kept vertices are more than the tolerance apart.
    std::mt19937 rng(12);
    std::uniform_int_distribution<int> lattice(0, 12);
    std::uniform_real_distribution<double> u(-1, 1);
    const double tolerance = 0.25;
    for (const Eigen::Vector3d& offset : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(-2e5, 1e5, 3e4)}) {
        std::vector<Eigen::Vector3d> p;
        for (int i = 0; i < 3000; ++i) {
            const Eigen::Vector3d base = offset + Eigen::Vector3d(lattice(rng), lattice(rng), lattice(rng));
            const Eigen::Vector3d jitter(u(rng), u(rng), u(rng));
            p.push_back(rng() % 2 ? base : base + 0.2 * tolerance * jitter);
            if (rng() % 3 == 0) p.push_back(p[size_t(rng() % p.size())]); // an exact copy of any earlier point
        }
        std::vector<Eigen::Vector3d> welded;
        const std::vector<uint32_t> map = detail::weld_positions(p, tolerance, welded);
        for (size_t i = 0; i < welded.size(); ++i)
            for (size_t j = i + 1; j < welded.size(); ++j)
                ASSERT_GT((welded[i] - welded[j]).squaredNorm(), tolerance * tolerance) << i << ", " << j;
        for (size_t i = 0; i < p.size(); ++i) {
            ASSERT_LE((welded[map[i]] - p[i]).squaredNorm(), tolerance * tolerance) << "point " << i;
            for (size_t k = 0; k < welded.size(); ++k)
                if (welded[k] == p[i]) {
                    ASSERT_EQ(map[i], k) << "point " << i;
                }
        }
    }
}

TEST(Weld, AFlagSetStopsItAtOnceAndAnUnsetOneChangesNothing) {
    const Clusters c = make_clusters(5000, 1e-3, Eigen::Vector3d::Zero(), 3);
    std::atomic<bool> cancel{true};
    std::vector<Eigen::Vector3d> welded;
    detail::weld_positions(c.positions, 1e-3, welded, &cancel);
    EXPECT_TRUE(welded.empty()) << "the weld went on after the flag was set";
    cancel = false;
    std::vector<Eigen::Vector3d> plain;
    EXPECT_EQ(detail::weld_positions(c.positions, 1e-3, welded, &cancel), detail::weld_positions(c.positions, 1e-3, plain));
    EXPECT_EQ(welded, plain);
}
