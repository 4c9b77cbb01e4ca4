// Lazy refit: a pose that fits the balls near the root and leaves each part below for the query
// that descends into it (core/src/anim/lazy_pose.cpp).
#include "anim/lazy_pose.hpp"
#include "bending_bar.hpp"
#include "query/pending_pose.hpp"
#include "spt/deforming_model.hpp"
#include "spt/error.hpp"
#include "spt/query.hpp"
#include "spt/response.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <thread>

namespace spt {
namespace {

using bending::bar;
using bending::open_bar;

// The closed bar, then the open tube (two-sided spheres, node discs).
std::vector<const bending::Bar*> bars() { return {&bar(), &open_bar()}; }

const Clip& bar_clip() { return bar().mesh->clips[0]; }

// Node by node, sphere by sphere: the same bits.
void expect_same_layout(const CompactTree& a, const CompactTree& b) {
    ASSERT_EQ(a.nodes().size(), b.nodes().size());
    ASSERT_EQ(a.node_disc() == nullptr, b.node_disc() == nullptr);
    if (a.node_disc()) {
        for (size_t k = 0; k < 4 * a.nodes().size(); ++k) ASSERT_EQ(a.node_disc()[k], b.node_disc()[k]) << "disc of node " << k / 4;
    }
    for (size_t i = 0; i < a.nodes().size(); ++i) {
        const CompactNode &na = a.nodes()[i], &nb = b.nodes()[i];
        for (int k = 0; k < 3; ++k) ASSERT_EQ(na.center[k], nb.center[k]) << "node " << i;
        ASSERT_EQ(na.bv_radius, nb.bv_radius) << "node " << i;
        if (!na.is_active()) continue;
        for (uint32_t k = na.first; k < na.first + na.count; ++k) {
            ASSERT_EQ(a.sphere_center(na, k), b.sphere_center(nb, k)) << "node " << i;
            ASSERT_EQ(a.nx()[k], b.nx()[k]);
            ASSERT_EQ(a.ny()[k], b.ny()[k]);
            ASSERT_EQ(a.nz()[k], b.nz()[k]);
        }
    }
}

// The bar in regions of at most 16 samples, so that a query leaves most of them unposed.
// (`triangles`: with the exact level's triangles, which a settle poses too.)
DeformingModel small_regions(bool triangles = true, const bending::Bar& b = bar()) {
    DeformingModel dm(b.doc, b.mesh, "", triangles);
    dm.set_lazy_region(16);
    return dm;
}

// A box of half-size 0.15 the queries move around the bar (with its triangles, for the exact level).
const CollisionModel& probe() {
    static const ImportedMesh mesh = meshgen::prepare(meshgen::box(0.3, 0.3, 0.3, 2), "probe.obj");
    static const SptDocument doc = make_document(mesh.mesh);
    static const CollisionModel m(doc, mesh.mesh);
    return m;
}

// A box of half-size 0.05, for poses wholly inside the bar (0.15 from its walls, so that the walk
// ends near the roots and containment answers).
const CollisionModel& small_probe() {
    static const ImportedMesh mesh = meshgen::prepare(meshgen::box(0.1, 0.1, 0.1, 1), "small.obj");
    static const SptDocument doc = make_document(mesh.mesh);
    static const CollisionModel m(doc, mesh.mesh);
    return m;
}

// Poses of the probe near the bar's surface at any bend: inside, touching and just apart.
std::vector<Pose> probe_poses(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> x(-1.3, 1.3), y(-1.3, 1.3), z(-0.5, 0.5);
    std::vector<Pose> poses;
    for (int i = 0; i < count; ++i) poses.push_back(Pose::from(Eigen::Vector3d(x(rng), y(rng), z(rng)), Eigen::Quaterniond::Identity()));
    return poses;
}

TEST(LazyPose, ASettledLazyPoseIsTheFullPoseBitForBit) {
    for (const bending::Bar* m : bars())
        for (bool tight : {false, true}) {
            DeformingModel lazy = small_regions(true, *m), full(m->doc, m->mesh);
            lazy.set_tight_refit(tight), full.set_tight_refit(tight);
            QueryScratch scratch;
            QueryOptions o;
            o.solids = false;
            for (double t : {0.35, 0.8, 0.1}) {
                lazy.pose_lazily(&m->mesh->clips[0], t);
                // Some parts posed by queries first, the rest by settle.
                for (const Pose& p : probe_poses(5, unsigned(t * 100))) collide_relative(lazy.model(), probe(), p, o, scratch);
                lazy.settle();
                full.pose(&m->mesh->clips[0], t);
                expect_same_layout(lazy.model().tree(), full.model().tree());
                EXPECT_EQ(lazy.model().extent(), full.model().extent());
                EXPECT_EQ(lazy.sample_points(), full.sample_points());
                EXPECT_EQ(lazy.vertex_normals(), full.vertex_normals());
            }
        }
}

// The clip at time t, or (t < 0) its pose at 0.6 shaken by up to a tenth of the bar's thickness
// at every vertex, with one face squeezed flat (its third corner on the line of the other two).
std::vector<Eigen::Vector3d> pose_at(const bending::Bar& m, double t) {
    std::vector<Eigen::Vector3d> v;
    pose_vertices(*m.mesh, &m.mesh->clips[0], t < 0 ? 0.6 : t, v);
    if (t >= 0) return v;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> shake(-0.01, 0.01);
    for (Eigen::Vector3d& p : v) p += Eigen::Vector3d(shake(rng), shake(rng), shake(rng));
    const Triangle& f = m.mesh->imported.mesh.triangles[m.mesh->imported.mesh.triangles.size() / 2];
    v[f[2]] = 0.3 * v[f[0]] + 0.7 * v[f[1]];
    return v;
}

// Every sphere of the full pose's tree `f` below each ball the lazy pose `lazy` fits at once (its
// covers and the nodes above them: PendingPose::loose) lies in that ball; the balls' slack (how
// much larger than their spheres need), summed, or NaN after a failure. `balls`: how many it checked.
double slack_near_root(const CollisionModel& lazy, const CompactTree& f, const std::string& what, size_t& balls) {
    const detail::PendingPose* pending = detail::pending_of(lazy);
    if (!pending) {
        ADD_FAILURE() << what << ": the model is not posed lazily";
        return std::numeric_limits<double>::quiet_NaN();
    }
    const CompactTree& l = lazy.tree();
    double slack = 0;
    balls = 0;
    for (uint32_t a = 0; a < l.nodes().size(); ++a) {
        if (!pending->loose(a)) continue;
        ++balls;
        const CompactNode& n = l.nodes()[a];
        const Eigen::Vector3f c(n.center[0], n.center[1], n.center[2]);
        float farthest = 0;
        std::vector<uint32_t> stack{a};
        while (!stack.empty()) {
            const uint32_t i = stack.back();
            stack.pop_back();
            const CompactNode& below = f.nodes()[i];
            if (!below.is_active()) {
                stack.push_back(i + 1), stack.push_back(below.first);
                continue;
            }
            for (uint32_t k = below.first; k < below.first + below.count; ++k) {
                const float reach = (f.sphere_center(below, k) - c).norm() + below.ss_radius;
                if (!(reach <= n.bv_radius)) {
                    ADD_FAILURE() << what << ": node " << a << " reaches " << reach << " past its ball " << n.bv_radius;
                    return std::numeric_limits<double>::quiet_NaN();
                }
                farthest = std::max(farthest, reach);
            }
        }
        slack += double(n.bv_radius - farthest);
    }
    return slack;
}

// Whether weights w lie in the hull of `corners` in (w_0, w_1) (a polygon, a segment or a point),
// within `tol`: in the corners' box, and on the inner side of every edge of their hull.
bool in_patch(const Eigen::Vector3d& w, std::vector<Eigen::Vector3d> corners, double tol) {
    Eigen::Vector2d lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
    for (const Eigen::Vector3d& c : corners) lo = lo.cwiseMin(c.head<2>()), hi = hi.cwiseMax(c.head<2>());
    if ((w.head<2>() - lo).minCoeff() < -tol || (hi - w.head<2>()).minCoeff() < -tol) return false;
    // The hull, counter-clockwise (Andrew's monotone chain).
    std::sort(corners.begin(), corners.end(), [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
    });
    auto turn = [](const Eigen::Vector3d& o, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    };
    std::vector<Eigen::Vector3d> hull;
    for (int pass = 0; pass < 2; ++pass) {
        const size_t start = hull.size();
        for (const Eigen::Vector3d& c : corners) {
            while (hull.size() >= start + 2 && turn(hull[hull.size() - 2], hull.back(), c) <= 0) hull.pop_back();
            hull.push_back(c);
        }
        hull.pop_back();
        std::reverse(corners.begin(), corners.end());
    }
    for (size_t k = 0; k < hull.size(); ++k) {
        const Eigen::Vector2d a = hull[k].head<2>(), e = hull[(k + 1) % hull.size()].head<2>() - a;
        if (e.norm() < 1e-12) continue;
        const Eigen::Vector2d d = w.head<2>() - a;
        if ((e.x() * d.y() - e.y() * d.x()) / e.norm() < -tol) return false;
    }
    return true;
}

TEST(LazyPose, APatchsCornersHoldItsSamplesAndNoMoreThanTheirWeightsRange) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    auto inside = [&] {
        double a = unit(rng), b = unit(rng);
        if (a + b > 1) a = 1 - a, b = 1 - b;
        return Eigen::Vector3d(a, b, 1 - a - b);
    };
    // Weights as a face's samples have them: anywhere, along an edge with one weight held at a
    // float's rounding off 0 (the bending bar's), in a corner, one sample, and the whole face.
    const double held[] = {0.0, -5.96046e-08, 2.98023e-08};
    for (int trial = 0; trial < 3000; ++trial) {
        std::vector<Eigen::Vector3d> w;
        const int kind = trial % 5, count = 1 + int(rng() % 12);
        for (int i = 0; i < count; ++i) {
            Eigen::Vector3d x = inside();
            if (kind == 1) { // along edge k: weight k held, the other two share the rest
                const int k = trial % 3; // every edge with every held value over 15 trials
                const double h = held[(trial / 15) % 3], t = unit(rng) * (1 - h);
                x[k] = h, x[(k + 1) % 3] = t, x[(k + 2) % 3] = 1 - h - t;
            } else if (kind == 2) { // near corner 0
                x = Eigen::Vector3d(1, 0, 0) + 0.1 * (x - Eigen::Vector3d(1, 0, 0));
            } else if (kind == 3 && i > 0) { // one sample, many times
                x = w[0];
            }
            w.push_back(x);
        }
        if (kind == 4) w.insert(w.end(), {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)});
        Eigen::Vector3d least = w[0], most = w[0];
        for (const Eigen::Vector3d& x : w) least = least.cwiseMin(x), most = most.cwiseMax(x);
        std::vector<Eigen::Vector3d> corners{Eigen::Vector3d::Constant(7)}; // appended after what is there
        uint8_t n = detail::patch_corners(least, most, corners);
        corners.erase(corners.begin());
        ASSERT_EQ(corners.size(), size_t(n));
        ASSERT_LE(n, 12);
        if (n == 0) { // the triangle of the least weights
            corners = {{1 - least[1] - least[2], least[1], least[2]},
                       {least[0], 1 - least[0] - least[2], least[2]},
                       {least[0], least[1], 1 - least[0] - least[1]}};
            n = 3;
        }
        // No larger than the weights' range (a billionth's slack).
        const double slack = 3e-9;
        for (const Eigen::Vector3d& c : corners) {
            EXPECT_NEAR(c.sum(), 1.0, 1e-12);
            for (int k = 0; k < 3; ++k) {
                EXPECT_GE(c[k], least[k] - slack) << "trial " << trial;
                EXPECT_LE(c[k], most[k] + slack) << "trial " << trial;
            }
        }
        for (const Eigen::Vector3d& x : w) ASSERT_TRUE(in_patch(x, corners, 1e-13)) << "trial " << trial << " kind " << kind;
        if (kind == 4) {
            EXPECT_EQ(n, 3); // the whole face: its three corners
        }
        if (kind == 1 && least[trial % 3] == most[trial % 3]) {
            EXPECT_LE(n, 6); // along an edge: a segment's two ends (each with its near twins)
        }
    }
}

TEST(LazyPose, TheBallsNearTheRootHoldEveryPosedSphereBelowThem) {
    for (const bending::Bar* m : bars()) {
        std::map<std::pair<double, int>, double> slack_without_normals;
        for (bool tight : {false, true}) { // covers from the vertices alone, or from the face normals too
            DeformingModel lazy = small_regions(true, *m), full(m->doc, m->mesh);
            lazy.set_tight_refit(tight);
            QueryScratch scratch;
            QueryOptions o;
            o.solids = false;
            for (double t : {0.0, 0.25, 0.6, 1.0, -1.0})
                for (int queries : {0, 6}) { // before any query, then after some posed parts and tightened balls
                    const std::vector<Eigen::Vector3d> v = pose_at(*m, t);
                    lazy.pose_lazily_on(v);
                    for (const Pose& p : probe_poses(queries, unsigned(t * 10 + 10))) collide_relative(lazy.model(), probe(), p, o, scratch);
                    full.pose_on(v);
                    const std::string what = "t " + std::to_string(t) + (tight ? " tight" : "");
                    size_t balls = 0;
                    const double slack = slack_near_root(lazy.model(), full.model().tree(), what, balls);
                    ASSERT_FALSE(std::isnan(slack));
                    ASSERT_GT(balls, 8u);
                    // Not a loose bound that holds anything: the balls stay within the bar's thickness.
                    // Face normals make the covers tighter: the slack falls by more than a third.
                    double& loose_slack = slack_without_normals[{t, queries}];
                    if (!tight) loose_slack = slack;
                    else EXPECT_LT(slack, 0.6 * loose_slack) << "t " << t << " queries " << queries;
                    lazy.settle();
                }
        }
    }
}

// A skinned figure (joints blending at hips, knees and shoulders; face and vertex samples at
// spt convert's defaults) in the default regions: the covers, loose and tight, hold every
// sphere at every frame of both clips, and the tight ones leave less than half the slack.
TEST(LazyPose, ASkinnedFiguresCoversHoldEverySphereAlongItsClips) {
    auto figure = std::make_shared<const AnimatedMesh>(
        import_animated_mesh(std::string(SPT_SOURCE_DIR) + "/resources/models/walking_figure.gltf"));
    const SptDocument doc = make_document(figure->imported.mesh);
    ASSERT_GE(figure->clips.size(), 2u);
    DeformingModel full(doc, figure, "", false);
    double slack[2] = {0, 0};
    for (bool tight : {false, true}) {
        DeformingModel lazy(doc, figure, "", false);
        lazy.set_tight_refit(tight);
        for (const Clip& clip : figure->clips)
            for (int k = 0; k <= 12; ++k) {
                const double t = clip.duration * k / 12;
                lazy.pose_lazily(&clip, t);
                full.pose(&clip, t);
                const std::string what = clip.name + " at " + std::to_string(t) + (tight ? " tight" : "");
                size_t balls = 0;
                const double s = slack_near_root(lazy.model(), full.model().tree(), what, balls);
                ASSERT_FALSE(std::isnan(s));
                ASSERT_GT(balls, 100u);
                slack[tight] += s;
            }
    }
    EXPECT_LT(slack[1], 0.5 * slack[0]);
}

TEST(LazyPose, QueriesAnswerAsOnTheFullPoseInEveryMode) {
    for (const bending::Bar* m : bars()) {
        // Without the triangles: a query with solids that finds no contact settles the model, and
        // refitting the triangle tree each time would only slow the test (no containment either way).
        DeformingModel lazy = small_regions(false, *m), full(m->doc, m->mesh, "", false);
        QueryScratch ls, fs;
        int collisions = 0;
        for (double t : {0.2, 0.9}) {
            full.pose(&m->mesh->clips[0], t);
            for (bool solids : {false, true})
                for (QueryMode mode : {QueryMode::Any, QueryMode::All, QueryMode::Deepest})
                    for (const Pose& p : probe_poses(10, unsigned(t * 10) + solids)) {
                        lazy.pose_lazily(&m->mesh->clips[0], t); // every query starts from an unposed tree
                        QueryOptions o;
                        o.solids = solids, o.mode = mode;
                        const QueryResult a = collide_relative(lazy.model(), probe(), p, o, ls);
                        const QueryResult b = collide_relative(full.model(), probe(), p, o, fs);
                        ASSERT_EQ(a.collide, b.collide) << "t " << t << " mode " << int(mode) << " solids " << solids;
                        collisions += a.collide;
                        if (mode == QueryMode::All) { // the same pairs, in any order: count, sum and xor of a mix
                            auto key = [](const std::vector<SpherePair>& v) {
                                uint64_t sum = 0, x = 0;
                                for (const SpherePair& p : v) {
                                    const uint64_t h = (uint64_t(p.a) << 32 | p.b) * 0x9e3779b97f4a7c15ull;
                                    sum += h, x ^= h;
                                }
                                return std::make_tuple(v.size(), sum, x);
                            };
                            ASSERT_EQ(key(ls.pairs()), key(fs.pairs()));
                        }
                        if (mode == QueryMode::Deepest && a.collide) {
                            ASSERT_EQ(a.deepest.depth, b.deepest.depth);
                        }
                    }
        }
        EXPECT_GT(collisions, 6); // the poses meet the bar often enough to mean something
    }
}

TEST(LazyPose, AQueryPosesOnlyThePartsItDescendsInto) {
    for (const bending::Bar* m : bars()) {
        DeformingModel lazy = small_regions(true, *m);
        lazy.pose_lazily(&m->mesh->clips[0], 0.5);
        QueryScratch scratch;
        QueryOptions o;
        o.solids = false;
        // Far beyond the bent tip: nothing below the root is read.
        const Pose far = Pose::from(Eigen::Vector3d(0, 3, 0), Eigen::Quaterniond::Identity());
        EXPECT_FALSE(collide_relative(lazy.model(), probe(), far, o, scratch).collide);
        // Over the bar's fixed left half (the tube's wall, not its open end), the tip's spheres
        // keep the previous pose (the bind).
        const Pose left = Pose::from(Eigen::Vector3d(-0.8, 0.3, 0), Eigen::Quaterniond::Identity());
        EXPECT_TRUE(collide_relative(lazy.model(), probe(), left, o, scratch).collide);
        const DeformingModel bind(m->doc, m->mesh);
        const CompactTree &l = lazy.model().tree(), &b = bind.model().tree();
        size_t unmoved = 0, moved = 0;
        for (const CompactNode& n : l.nodes()) {
            if (!n.is_active()) continue;
            const CompactNode& m = b.nodes()[&n - l.nodes().data()];
            for (uint32_t k = n.first; k < n.first + n.count; ++k)
                (l.sphere_center(n, k) == b.sphere_center(m, k) ? unmoved : moved)++;
        }
        EXPECT_GT(unmoved, moved); // most of the tree is as the bind pose left it
        lazy.settle();
        DeformingModel full(m->doc, m->mesh);
        full.pose(&m->mesh->clips[0], 0.5);
        expect_same_layout(lazy.model().tree(), full.model().tree());
    }
}

TEST(LazyPose, ACopyOrAnotherKindOfQueryPosesTheRestFirst) {
    DeformingModel lazy = small_regions(), full(bar().doc, bar().mesh);
    full.pose(&bar_clip(), 0.7);
    lazy.pose_lazily(&bar_clip(), 0.7);
    const DeformingModel copy = lazy; // the source is posed in full before it is copied
    expect_same_layout(copy.model().tree(), full.model().tree());
    expect_same_layout(lazy.model().tree(), full.model().tree());
    lazy.pose_lazily(&bar_clip(), 0.7);
    QueryScratch scratch;
    QueryOptions o;
    o.level = QueryLevel::Bounds;
    const Pose p = Pose::from(Eigen::Vector3d(0.3, 1.0, 0), Eigen::Quaterniond::Identity());
    const bool lazy_bounds = collide_relative(lazy.model(), probe(), p, o, scratch).collide;
    EXPECT_EQ(lazy_bounds, collide_relative(full.model(), probe(), p, o, scratch).collide);
    expect_same_layout(lazy.model().tree(), full.model().tree());
    lazy.pose_lazily(&bar_clip(), 0.7);
    const BacktrackResult a = backtrack_relative(lazy.model(), probe(), p, Eigen::Vector3d(0, -1, 0), {},
                                                 BacktrackRule::Exact, scratch);
    const BacktrackResult b = backtrack_relative(full.model(), probe(), p, Eigen::Vector3d(0, -1, 0), {},
                                                 BacktrackRule::Exact, scratch);
    EXPECT_EQ(a.distance, b.distance);
}

TEST(LazyPose, WithoutTrianglesAQueryWithSolidsLeavesTheRestUnposed) {
    // No triangles, no containment (as on a full pose): nothing to pose the rest for, so walks
    // with solids on several threads never settle the model under one another.
    DeformingModel lazy = small_regions(false), full(bar().doc, bar().mesh, "", false);
    lazy.pose_lazily(&bar_clip(), 0.5);
    full.pose(&bar_clip(), 0.5);
    EXPECT_FALSE(lazy.model().has_mesh());
    QueryScratch scratch;
    QueryOptions o; // solids on
    const Pose near = Pose::from(Eigen::Vector3d(-0.5, 0.45, 0), Eigen::Quaterniond::Identity()); // over the bar, apart
    const QueryResult r = collide_relative(lazy.model(), probe(), near, o, scratch);
    EXPECT_FALSE(r.collide);
    EXPECT_EQ(r.collide, collide_relative(full.model(), probe(), near, o, scratch).collide);
    size_t differ = 0;
    for (size_t i = 0; i < full.model().tree().nodes().size(); ++i)
        differ += lazy.model().tree().nodes()[i].bv_radius != full.model().tree().nodes()[i].bv_radius;
    EXPECT_GT(differ, 0u); // still pending: the balls near the root are the covers'
}

TEST(LazyPose, SeveralThreadsMayWalkOneLazilyPosedModel) {
    for (const bending::Bar* m : bars()) {
        DeformingModel lazy = small_regions(true, *m), full(m->doc, m->mesh);
        const std::vector<Pose> poses = probe_poses(24, 7);
        QueryOptions o;
        o.solids = false;
        for (double t : {0.3, 0.8}) {
            full.pose(&m->mesh->clips[0], t);
            lazy.pose_lazily(&m->mesh->clips[0], t);
            std::vector<int> answer(poses.size(), -1);
            // Each thread its own half, the other half's regions meanwhile; every third query at
            // the exact level (the first of those on either thread refits the triangles), in mode
            // deepest (whose contact walks the spheres).
            auto options = [&](size_t k) {
                QueryOptions q = o;
                if (k % 3 == 2) q.level = QueryLevel::Exact, q.mode = QueryMode::Deepest, q.solids = true;
                return q;
            };
            auto walk = [&](size_t first) {
                QueryScratch scratch;
                for (size_t k = first; k < poses.size(); k += 2)
                    answer[k] = collide_relative(lazy.model(), probe(), poses[k], options(k), scratch).collide;
            };
            std::thread a(walk, 0), b(walk, 1);
            a.join(), b.join();
            QueryScratch scratch;
            for (size_t k = 0; k < poses.size(); ++k)
                ASSERT_EQ(answer[k], int(collide_relative(full.model(), probe(), poses[k], options(k), scratch).collide)) << k;
            lazy.settle();
            expect_same_layout(lazy.model().tree(), full.model().tree());
        }
    }
}

TEST(LazyPose, ARefusedPoseLeavesThePendingOneWhole) {
    DeformingModel lazy = small_regions(), full(bar().doc, bar().mesh);
    lazy.pose_lazily(&bar_clip(), 0.4);
    std::vector<Eigen::Vector3d> v = bar().mesh->imported.mesh.positions;
    v.pop_back();
    EXPECT_THROW(lazy.pose_lazily_on(v), Error);
    v = bar().mesh->imported.mesh.positions;
    v[3].x() = NAN;
    EXPECT_THROW(lazy.pose_lazily_on(v), Error);
    EXPECT_THROW(lazy.pose_on(v), Error); // a full pose refused leaves the pending one too
    lazy.settle();
    full.pose(&bar_clip(), 0.4);
    expect_same_layout(lazy.model().tree(), full.model().tree());
}

TEST(LazyPose, AnOpenTubesFacesArePosedBeforeAnyWalkSoItsSpheresAnswerAsOnTheFullPose) {
    // Two-sided spheres are tested against the faces their samples lie on (with the triangles):
    // a lazy pose moves those corners at once, the triangle tree at the settle. Queries follow
    // one another, so later ones walk regions that earlier ones posed.
    const bending::Bar& tube = open_bar();
    ASSERT_TRUE(tube.doc.samples.size() > 0 && DeformingModel(tube.doc, tube.mesh).model().tree().two_sided());
    DeformingModel lazy = small_regions(true, tube), full(tube.doc, tube.mesh);
    const std::vector<Pose> poses = probe_poses(24, 7);
    QueryOptions o;
    o.solids = false;
    int collisions = 0;
    for (double t : {0.3, 0.8}) {
        full.pose(&tube.mesh->clips[0], t);
        lazy.pose_lazily(&tube.mesh->clips[0], t);
        QueryScratch ls, fs;
        for (QueryMode mode : {QueryMode::Any, QueryMode::Deepest})
            for (size_t k = 0; k < poses.size(); ++k) {
                o.mode = mode;
                const QueryResult a = collide_relative(lazy.model(), probe(), poses[k], o, ls);
                const QueryResult b = collide_relative(full.model(), probe(), poses[k], o, fs);
                ASSERT_EQ(a.collide, b.collide) << "t " << t << " pose " << k;
                if (mode == QueryMode::Deepest && a.collide) {
                    ASSERT_EQ(a.deepest.depth, b.deepest.depth);
                }
                collisions += a.collide;
            }
        lazy.settle();
        expect_same_layout(lazy.model().tree(), full.model().tree());
    }
    EXPECT_GT(collisions, 6);
}

TEST(LazyPose, ExactQueriesAndContainmentRefitTheTrianglesAloneAndAnswerAsOnTheFullPose) {
    for (const bending::Bar* m : bars()) {
        DeformingModel lazy = small_regions(true, *m), full(m->doc, m->mesh);
        QueryScratch ls, fs;
        int collisions = 0, contained = 0;
        for (double t : {0.2, 0.9}) {
            full.pose(&m->mesh->clips[0], t);
            // Random poses of the probe, and two of the small probe wholly inside the bar's fixed
            // half (contained in the closed bar; inside the open tube, which holds nothing, apart).
            std::vector<std::pair<const CollisionModel*, Pose>> poses;
            for (const Pose& p : probe_poses(10, unsigned(t * 10))) poses.push_back({&probe(), p});
            for (double x : {-0.6, -0.45})
                poses.push_back({&small_probe(), Pose::from(Eigen::Vector3d(x, 0, 0), Eigen::Quaterniond::Identity())});
            for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact})
            for (QueryMode mode : {QueryMode::Any, QueryMode::All, QueryMode::Deepest})
                for (bool solids : {false, true}) {
                    // (Spheres without solids, and in the other modes: QueriesAnswerAsOnTheFullPoseInEveryMode.)
                    if (level == QueryLevel::Spheres && (!solids || mode != QueryMode::Any)) continue;
                    lazy.pose_lazily(&m->mesh->clips[0], t);
                    for (const auto& [other, p] : poses) {
                        QueryOptions o;
                        o.level = level, o.solids = solids, o.mode = mode;
                        const QueryResult a = collide_relative(lazy.model(), *other, p, o, ls);
                        const QueryResult b = collide_relative(full.model(), *other, p, o, fs);
                        ASSERT_EQ(a.collide, b.collide) << "t " << t << " level " << int(level) << " mode " << int(mode) << " solids " << solids;
                        if (mode == QueryMode::All) {
                            ASSERT_EQ(ls.pairs().size(), fs.pairs().size());
                        }
                        if (mode == QueryMode::Deepest && a.collide) {
                            ASSERT_EQ(a.deepest.depth, b.deepest.depth);
                        }
                        collisions += a.collide;
                        contained += a.collide && other == &small_probe();
                    }
                }
            lazy.settle();
            expect_same_layout(lazy.model().tree(), full.model().tree());
        }
        EXPECT_GT(collisions, 20);
        if (m == &bar()) EXPECT_GT(contained, 0); // containment was asked and answered
        else EXPECT_EQ(contained, 0);             // an open tube holds nothing
        // Exact any and all leave every sampling sphere where the pose before left it (the bind
        // here), containment among them; deepest poses the parts its contact's walk reads.
        DeformingModel fresh = small_regions(true, *m);
        const DeformingModel bind(m->doc, m->mesh);
        fresh.pose_lazily(&m->mesh->clips[0], 0.6);
        std::vector<std::pair<const CollisionModel*, Pose>> poses;
        for (const Pose& p : probe_poses(10, 3)) poses.push_back({&probe(), p});
        poses.push_back({&small_probe(), Pose::from(Eigen::Vector3d(-0.6, 0, 0), Eigen::Quaterniond::Identity())});
        for (QueryMode mode : {QueryMode::Any, QueryMode::All})
            for (bool solids : {false, true})
                for (const auto& [other, p] : poses) {
                    QueryOptions o;
                    o.level = QueryLevel::Exact, o.solids = solids, o.mode = mode;
                    collide_relative(fresh.model(), *other, p, o, ls);
                }
        const CompactTree &l = fresh.model().tree(), &b = bind.model().tree();
        for (const CompactNode& n : l.nodes()) {
            if (!n.is_active()) continue;
            const CompactNode& q = b.nodes()[&n - l.nodes().data()];
            for (uint32_t k = n.first; k < n.first + n.count; ++k) ASSERT_EQ(l.sphere_center(n, k), b.sphere_center(q, k));
        }
    }
}

} // namespace
} // namespace spt
