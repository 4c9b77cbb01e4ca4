// Samples that follow a deforming mesh, bounds refit, queries on a pose (core/src/anim/
// deforming_model.cpp, core/src/tree/compact_refit.cpp).
#include "spt/convert.hpp"
#include "spt/deforming_model.hpp"
#include "spt/distance.hpp"
#include "spt/error.hpp"
#include "spt/ccd.hpp"
#include "spt/query.hpp"
#include "spt/response.hpp"
#include "bending_bar.hpp"
#include "meshgen.hpp"
#include "query/model_access.hpp"
#include <gtest/gtest.h>

namespace spt {
namespace {

using bending::bar;
using bending::expect_bounds_hold;


TEST(DeformingModel, TheBindPoseGivesTheDocumentsSpheresBitForBit) {
    DeformingModel dm(bar().doc, bar().mesh);
    const CollisionModel rigid(bar().doc, bar().mesh->imported.mesh);
    dm.pose(nullptr, 0);
    const CompactTree &a = dm.model().tree(), &b = rigid.tree();
    ASSERT_EQ(a.sphere_count(), b.sphere_count());
    for (size_t i = 0; i < a.nodes().size(); ++i) {
        const CompactNode &na = a.nodes()[i], &nb = b.nodes()[i];
        if (!na.is_active()) continue;
        for (uint32_t k = na.first; k < na.first + na.count; ++k) ASSERT_EQ(a.sphere_center(na, k), b.sphere_center(nb, k));
    }
}

TEST(DeformingModel, BoundsHoldTheirSpheresAtEveryPose) {
    DeformingModel dm(bar().doc, bar().mesh);
    for (double t : {0.0, 0.3, 0.7, 1.0}) {
        dm.pose(&bar().mesh->clips[0], t);
        expect_bounds_hold(dm.model().tree());
    }
}

TEST(DeformingModel, ARefitAfterManyPosesEqualsAFreshOneAtTheLastPose) {
    DeformingModel walked(bar().doc, bar().mesh), fresh(bar().doc, bar().mesh);
    for (double t : {0.9, 0.1, 0.55, 0.3}) walked.pose(&bar().mesh->clips[0], t);
    fresh.pose(&bar().mesh->clips[0], 0.3);
    const auto &a = walked.model().tree().nodes(), &b = fresh.model().tree().nodes();
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        for (int k = 0; k < 3; ++k) ASSERT_EQ(a[i].center[k], b[i].center[k]) << i;
        ASSERT_EQ(a[i].bv_radius, b[i].bv_radius) << i;
    }
    EXPECT_EQ(walked.model().extent(), fresh.model().extent());
}

TEST(DeformingModel, ATightRefitHoldsItsSpheresIsTighterAndIsTheSameAfterAnyPoses) {
    DeformingModel loose(bar().doc, bar().mesh), tight(bar().doc, bar().mesh), fresh(bar().doc, bar().mesh);
    tight.set_tight_refit(true), fresh.set_tight_refit(true);
    double loose_sum = 0, tight_sum = 0;
    for (double t : {0.9, 0.1, 0.55, 0.3}) {
        loose.pose(&bar().mesh->clips[0], t), tight.pose(&bar().mesh->clips[0], t);
        expect_bounds_hold(tight.model().tree());
        const auto &a = loose.model().tree().nodes(), &b = tight.model().tree().nodes();
        for (size_t i = 0; i < a.size(); ++i)
            if (!a[i].is_active()) loose_sum += a[i].bv_radius, tight_sum += b[i].bv_radius;
    }
    EXPECT_LT(tight_sum, loose_sum); // by 1.4%: a bar's children line up
    fresh.pose(&bar().mesh->clips[0], 0.3);
    const auto &a = tight.model().tree().nodes(), &b = fresh.model().tree().nodes();
    for (size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i].bv_radius, b[i].bv_radius) << i;
        for (int k = 0; k < 3; ++k) ASSERT_EQ(a[i].center[k], b[i].center[k]) << i;
    }
}

TEST(DeformingModel, ATightRefitSearchesOnlyNodesOfManySpheresAndKeepsTheMergedBallsBelow) {
    DeformingModel loose(bar().doc, bar().mesh), tight(bar().doc, bar().mesh);
    tight.set_tight_refit(true);
    loose.pose(&bar().mesh->clips[0], 0.8), tight.pose(&bar().mesh->clips[0], 0.8);
    const auto &a = loose.model().tree().nodes(), &b = tight.model().tree().nodes();
    std::vector<uint32_t> below(a.size());
    for (size_t i = a.size(); i-- > 0;) // children follow their parent
        below[i] = a[i].is_active() ? a[i].count : below[i + 1] + below[a[i].first];
    ASSERT_GE(below[0], 4 * CompactTree::kTightSearchFrom); // the search has nodes to work on
    // Above, a node's ball need not be smaller (the smallest ball around two searched children
    // can be larger than around two merged ones), but together they are.
    int searched = 0;
    double loose_sum = 0, tight_sum = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        if (below[i] < CompactTree::kTightSearchFrom) { // neither it nor any node below it is searched
            ASSERT_EQ(a[i].bv_radius, b[i].bv_radius) << i;
            for (int k = 0; k < 3; ++k) ASSERT_EQ(a[i].center[k], b[i].center[k]) << i;
            continue;
        }
        ++searched, loose_sum += a[i].bv_radius, tight_sum += b[i].bv_radius;
    }
    EXPECT_GT(searched, 0);
    EXPECT_LT(tight_sum, loose_sum);
    expect_bounds_hold(tight.model().tree());
}

TEST(DeformingModel, VertexSpheresSitBehindTheirPosedVertexAlongItsNormal) {
    DeformingModel dm(bar().doc, bar().mesh);
    dm.pose(&bar().mesh->clips[0], 1.0);
    const SampleSet& s = bar().doc.samples;
    const CompactTree& t = dm.model().tree();
    size_t checked = 0;
    for (const CompactNode& n : t.nodes()) {
        if (!n.is_active()) continue;
        for (uint32_t k = n.first; k < n.first + n.count; ++k) {
            const uint32_t i = t.sample_index()[k];
            if (s.is_face_sample(i)) continue;
            const Eigen::Vector3d v = dm.vertices()[s.source_index(i)] - s.origin;
            // The sphere touches the surface at its vertex: centre r away from it.
            EXPECT_NEAR((t.sphere_center(n, k).cast<double>() - v).norm(), n.ss_radius, 1e-3 * n.ss_radius + 1e-6);
            ++checked;
        }
    }
    EXPECT_GT(checked, 0u);
}

TEST(DeformingModel, FaceSamplesStayOnTheirPosedTriangle) {
    DeformingModel dm(bar().doc, bar().mesh);
    dm.pose(&bar().mesh->clips[0], 0.6);
    const SampleSet& s = bar().doc.samples;
    const CompactTree& t = dm.model().tree();
    const TriangleMesh& m = bar().mesh->imported.mesh;
    for (const CompactNode& n : t.nodes()) {
        if (!n.is_active()) continue;
        for (uint32_t k = n.first; k < n.first + n.count; ++k) {
            const uint32_t i = t.sample_index()[k];
            if (!s.is_face_sample(i)) continue;
            const Triangle& f = m.triangles[s.source_index(i)];
            const Eigen::Vector3d a = dm.vertices()[f[0]], b = dm.vertices()[f[1]], c = dm.vertices()[f[2]];
            const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
            // The surface point is r along the normal from the centre: on the triangle's plane.
            const Eigen::Vector3d p = t.sphere_center(n, k).cast<double>() + s.origin + double(n.ss_radius) * normal;
            EXPECT_NEAR((p - a).dot(normal), 0, 2e-3 * n.ss_radius + 1e-6);
        }
    }
}

// An obstacle above the bar's tip half: apart at rest, crossed by the tip's walls once it turns up.
TEST(DeformingModel, QueriesAtEveryLevelSeeTheDeformedPose) {
    const ImportedMesh box = meshgen::prepare(meshgen::box(0.6, 0.3, 0.6), "box.obj");
    const SptDocument box_doc = make_document(box.mesh);
    const CollisionModel obstacle(box_doc, box.mesh);
    DeformingModel dm(bar().doc, bar().mesh);
    const Pose at_rest_pose{Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero()};
    const Pose above{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0.8, 0)};
    QueryScratch scratch;
    for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact}) {
        QueryOptions o;
        o.level = level;
        dm.pose(nullptr, 0);
        if (level != QueryLevel::Bounds) {
            EXPECT_FALSE(collide(dm.model(), at_rest_pose, obstacle, above, o, scratch).collide);
        }
        dm.pose(&bar().mesh->clips[0], 1.0);
        EXPECT_TRUE(collide(dm.model(), at_rest_pose, obstacle, above, o, scratch).collide) << int(level);
        o.mode = QueryMode::Deepest;
        if (level != QueryLevel::Bounds) {
            EXPECT_GT(collide(dm.model(), at_rest_pose, obstacle, above, o, scratch).deepest.depth, 0.0) << int(level);
        }
    }
}

// The smallest gap between any sphere of `a` and any of `b` at `b_in_a` (every pair).
double every_sphere_pair_gap(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a) {
    double best = std::numeric_limits<double>::infinity();
    for (const CompactNode& na : a.tree().nodes()) {
        if (!na.is_active()) continue;
        for (uint32_t k = na.first; k < na.first + na.count; ++k) {
            const Eigen::Vector3d ca = a.tree().sphere_center(na, k).cast<double>() + a.origin();
            for (const CompactNode& nb : b.tree().nodes()) {
                if (!nb.is_active()) continue;
                for (uint32_t l = nb.first; l < nb.first + nb.count; ++l) {
                    const Eigen::Vector3d cb = b_in_a.apply(b.tree().sphere_center(nb, l).cast<double>() + b.origin());
                    best = std::min(best, (ca - cb).norm() - na.ss_radius - nb.ss_radius);
                }
            }
        }
    }
    return best;
}

// The distance's slabs are fitted to the bind pose's spheres: a pose (full or lazy) must not
// prune with them, or the bent bar's nearest spheres would be cut off.
TEST(DeformingModel, DistanceSeesTheDeformedPoseFullOrLazy) {
    const ImportedMesh box = meshgen::prepare(meshgen::box(0.6, 0.3, 0.6), "box.obj");
    ConvertOptions corners; // eight spheres: the brute force stays small
    corners.auto_tolerance = false;
    const SptDocument box_doc = make_document(box.mesh, corners);
    const CollisionModel obstacle(box_doc, box.mesh);
    DeformingModel dm(bar().doc, bar().mesh);
    const Pose above = Pose::from(Eigen::Vector3d(0, 1.4, 0), Eigen::Quaterniond::Identity());
    QueryScratch scratch;
    DistanceOptions spheres;
    const double at_rest = distance_relative(dm.model(), obstacle, above, spheres, scratch).distance;
    for (bool lazy : {false, true}) {
        if (lazy) dm.pose_lazily(&bar().mesh->clips[0], 1.0);
        else dm.pose(&bar().mesh->clips[0], 1.0);
        const DistanceResult d = distance_relative(dm.model(), obstacle, above, spheres, scratch);
        ASSERT_FALSE(d.collide);
        EXPECT_NEAR(d.distance, every_sphere_pair_gap(dm.model(), obstacle, above), 1e-5) << lazy;
        EXPECT_NE(d.distance, at_rest) << "the bend moves the bar's nearest spheres";
        EXPECT_EQ(detail::node_slab_of(dm.model()), nullptr);
        dm.pose(nullptr, 0);
    }
}

// The exact level's triangle tree is refit, not rebuilt: every triangle corner stays inside the
// box and the ball of every node above it, in the float the walk tests. The bind pose's triangle
// planes (the distance walk's bound of a leaf) are dropped, never left behind.
TEST(DeformingModel, TheTriangleTreeHoldsItsTrianglesAtEveryPose) {
    DeformingModel dm(bar().doc, bar().mesh);
    EXPECT_EQ(detail::exact_of(dm.model()).tri_plane.size(), 4 * detail::exact_of(dm.model()).triangles.size());
    for (double t : {0.25, 1.0}) {
        dm.pose(&bar().mesh->clips[0], t);
        const ExactData& e = detail::exact_of(dm.model());
        ASSERT_FALSE(e.tri_nodes.empty());
        EXPECT_TRUE(e.tri_plane.empty()) << t;
        for (size_t i = 0; i < e.tri_nodes.size(); ++i) {
            // The leaves below node i: the next nodes up to the end of its subtree.
            std::vector<size_t> stack{i};
            const Obb box = e.tri_nodes[i].box();
            const Eigen::Vector3f c(box.center[0], box.center[1], box.center[2]);
            while (!stack.empty()) {
                const TriangleNode& n = e.tri_nodes[stack.back()];
                const size_t at = stack.back();
                stack.pop_back();
                if (!n.is_leaf()) {
                    stack.push_back(at + 1), stack.push_back(n.first);
                    continue;
                }
                for (uint32_t k = n.first; k < n.first + n.count; ++k)
                    for (uint32_t v : e.triangles[e.tri_order[k]]) {
                        const Eigen::Vector3f p = e.positions[v].cast<float>();
                        ASSERT_LE((p - c).norm(), e.tri_nodes[i].radius * (1 + 1e-6f)) << "node " << i;
                        for (int a = 0; a < 3; ++a) {
                            const Eigen::Vector3f axis(box.axis[a][0], box.axis[a][1], box.axis[a][2]);
                            ASSERT_LE(std::abs(axis.dot(p - c)), box.half[a] * (1 + 1e-5f) + 1e-6f) << "node " << i;
                        }
                    }
            }
        }
    }
}

// A box wholly inside the bent tip, no surfaces meeting: found inside the posed closed triangles
// (the solid grids were made for the bind pose), at the sphere and exact levels alike.
TEST(DeformingModel, ContainmentIsFoundAtTheDeformedPose) {
    const ImportedMesh box = meshgen::prepare(meshgen::box(0.1, 0.1, 0.1), "small_box.obj");
    const SptDocument box_doc = make_document(box.mesh);
    const CollisionModel inside(box_doc, box.mesh);
    DeformingModel dm(bar().doc, bar().mesh);
    const Pose bar_pose{Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero()};
    const Pose in_tip{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0.7, 0)}; // where the tip stands up
    QueryScratch scratch;
    for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact}) {
        QueryOptions o;
        o.level = level;
        dm.pose(nullptr, 0);
        EXPECT_FALSE(collide(dm.model(), bar_pose, inside, in_tip, o, scratch).collide) << int(level);
        dm.pose(&bar().mesh->clips[0], 1.0);
        EXPECT_TRUE(collide(dm.model(), bar_pose, inside, in_tip, o, scratch).collide) << int(level);
        // And the other way round: the bar's pieces are not inside the box.
        EXPECT_TRUE(collide(inside, in_tip, dm.model(), bar_pose, o, scratch).collide) << int(level);
    }
}

// The box above the bar, moved down onto the bent tip: backtrack (exact rule) moves it back out,
// and continuous detection finds the contact within the motion, on the deformed pose.
TEST(DeformingModel, BacktrackAndContinuousDetectionSeeTheDeformedPose) {
    const ImportedMesh box = meshgen::prepare(meshgen::box(0.6, 0.3, 0.6), "box.obj");
    const SptDocument box_doc = make_document(box.mesh);
    const CollisionModel obstacle(box_doc, box.mesh);
    DeformingModel dm(bar().doc, bar().mesh);
    dm.pose(&bar().mesh->clips[0], 1.0); // the tip stands up to y = 1
    QueryScratch scratch;
    QueryOptions o;
    const Pose bar_pose{Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero()};
    const Pose into{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 0.9, 0)};
    ASSERT_TRUE(collide(dm.model(), bar_pose, obstacle, into, o, scratch).collide);
    const BacktrackResult back =
        backtrack(dm.model(), bar_pose, obstacle, into, Eigen::Vector3d(0, -1, 0), o, BacktrackRule::Exact, scratch);
    ASSERT_TRUE(back.converged);
    Pose out = into;
    out.translation.y() += back.distance;
    EXPECT_FALSE(collide(dm.model(), bar_pose, obstacle, out, o, scratch).collide);
    EXPECT_GT(out.translation.y(), 1.0); // above the bent tip, which the bind pose does not reach
    CcdOptions c;
    const Pose from{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0, 2, 0)};
    const CcdResult hit = first_contact(dm.model(), obstacle, from, into, c, scratch);
    ASSERT_TRUE(hit.hit);
    EXPECT_GT(hit.toi, 0.0);
    EXPECT_LT(hit.toi, 1.0);
}

TEST(DeformingModel, APoseIsTheSameOnAnyThreadCount) {
    DeformingModel one(bar().doc, bar().mesh), three(bar().doc, bar().mesh);
    three.set_threads(3);
    one.pose(&bar().mesh->clips[0], 0.6);
    three.pose(&bar().mesh->clips[0], 0.6);
    const CompactTree &a = one.model().tree(), &b = three.model().tree();
    for (size_t i = 0; i < a.nodes().size(); ++i) {
        const CompactNode &na = a.nodes()[i], &nb = b.nodes()[i];
        ASSERT_EQ(na.bv_radius, nb.bv_radius);
        for (int k = 0; k < 3; ++k) ASSERT_EQ(na.center[k], nb.center[k]);
        for (uint32_t k = na.first; na.is_active() && k < na.first + na.count; ++k)
            ASSERT_EQ(a.sphere_center(na, k), b.sphere_center(nb, k));
    }
}

TEST(DeformingModel, APoseOfTheWrongSizeOrNotFiniteIsRefused) {
    DeformingModel dm(bar().doc, bar().mesh);
    EXPECT_THROW(dm.pose_on({Eigen::Vector3d::Zero()}), Error);
    std::vector<Eigen::Vector3d> p = bar().mesh->imported.mesh.positions;
    p[3].x() = NAN;
    EXPECT_THROW(dm.pose_on(p), Error);
}

} // namespace
} // namespace spt

namespace spt {
namespace {

// A clip that turns the whole bar rigidly (the root) stretches nothing.
Clip rigid_turn() {
    Clip c;
    c.name = "turn", c.duration = 1;
    NodeChannel ch;
    ch.node = 0;
    ch.rotation.times = {0, 1};
    const Eigen::Quaterniond q(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitY()));
    ch.rotation.values = {Eigen::Vector4d(0, 0, 0, 1), Eigen::Vector4d(q.x(), q.y(), q.z(), q.w())};
    c.nodes = {ch};
    return c;
}

// The joints' ball holds every posed vertex and sampling sphere, at any time, without a pose.
TEST(PoseBound, TheJointsBallHoldsThePosedModel) {
    auto figure = std::make_shared<const AnimatedMesh>(
        import_animated_mesh(std::string(SPT_SOURCE_DIR) + "/resources/models/walking_figure.gltf"));
    ConvertOptions coarse;
    coarse.tolerance = 0.05;
    const SptDocument doc = make_document(figure->imported.mesh, coarse);
    struct Case {
        const SptDocument& doc;
        std::shared_ptr<const AnimatedMesh> mesh;
    };
    for (const Case& c : {Case{bar().doc, bar().mesh}, Case{doc, figure}}) {
        DeformingModel dm(c.doc, c.mesh);
        for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
            const auto [centre, radius] = dm.bound_at(&c.mesh->clips[0], t);
            dm.pose(&c.mesh->clips[0], t);
            for (const Eigen::Vector3d& v : dm.vertices()) ASSERT_LE((v - centre).norm(), radius) << t;
            const CompactTree& tree = dm.model().tree();
            for (const CompactNode& n : tree.nodes())
                for (uint32_t k = n.first; n.is_active() && k < n.first + n.count; ++k)
                    ASSERT_LE((dm.model().origin() + tree.sphere_center(n, k).cast<double>() - centre).norm() + n.ss_radius,
                              radius) << t;
            // And it is a bound, not the world: within twice the posed vertices' own ball.
            double far = 0;
            for (const Eigen::Vector3d& v : dm.vertices()) far = std::max(far, (v - centre).norm());
            EXPECT_LT(radius, 2 * far + 0.2) << t;
        }
    }
}

TEST(Stretch, ARigidMotionStretchesNothing) {
    const ClipStretch s = measure_stretch(*bar().mesh, rigid_turn());
    EXPECT_NEAR(s.largest, 1, 1e-12);
    EXPECT_NEAR(s.smallest, 1, 1e-12);
}

// Bending the bar by 90 degrees about its middle stretches the outer side of the blended part
// (linear blend skinning): more than a tenth, at the end of the bend, on one of its two joints.
TEST(Stretch, BendingStretchesTheBlendedPartAtTheBendsEnd) {
    const ClipStretch s = measure_stretch(*bar().mesh, bar().mesh->clips[0]);
    EXPECT_GT(s.largest, 1.1);
    EXPECT_LT(s.smallest, 1.0); // and compresses the inner side
    EXPECT_DOUBLE_EQ(s.time, 1.0);
    EXPECT_LE(std::abs(s.where.x()), 0.25 + 1e-9); // in the blended band
    EXPECT_TRUE(s.joint == "root" || s.joint == "tip") << s.joint;
    EXPECT_DOUBLE_EQ(s.gap_factor(), s.largest * s.largest);
}

TEST(Coverage, ARigidMotionOpensNoGap) {
    const DeformingModel dm(bar().doc, bar().mesh);
    const ClipCoverage c = dm.measure_coverage(rigid_turn(), 10);
    EXPECT_EQ(c.poses, 11);
    // Up to rounding: normals are stored snapped, so a turned sphere sits a few millionths off.
    const double diagonal = bar().mesh->imported.mesh.diagonal();
    EXPECT_NEAR(c.largest_gap, c.bind_gap, 1e-5 * diagonal);
    EXPECT_LT(c.largest_growth, 1e-5 * diagonal);
}

TEST(Coverage, BendingOpensGapsWhereItStretchesTheSameOnAnyThreadCount) {
    const DeformingModel dm(bar().doc, bar().mesh);
    const ClipCoverage one = dm.measure_coverage(bar().mesh->clips[0], 10, 1);
    const ClipCoverage two = dm.measure_coverage(bar().mesh->clips[0], 10, 2);
    EXPECT_GT(one.largest_growth, 0.0);
    EXPECT_LE(std::abs(one.growth_where.x()), 0.25 + 1e-9); // where the bar stretches
    EXPECT_EQ(one.largest_gap, two.largest_gap);
    EXPECT_EQ(one.largest_growth, two.largest_growth);
    EXPECT_EQ(one.growth_where, two.growth_where);
    // The model measured keeps its own pose.
    EXPECT_EQ(dm.vertices(), bar().mesh->imported.mesh.positions);
}

// The largest least gap over the report's points at `clip`'s `time` (bind pose without a clip),
// against every sphere: the report's walks, which end early and start at a leaf near the point,
// must give what this slow loop gives.
double largest_gap_by_every_sphere(const Clip* clip, double time) {
    DeformingModel dm(bar().doc, bar().mesh);
    dm.pose(clip, time);
    const CompactTree& tree = dm.model().tree();
    const TriangleMesh& m = bar().mesh->imported.mesh;
    double largest = 0;
    for (const Triangle& t : m.triangles)
        for (int i = 0; i <= 3; ++i)
            for (int j = 0; i + j <= 3; ++j) {
                const Eigen::Vector3d w(double(3 - i - j) / 3, double(i) / 3, double(j) / 3);
                const std::vector<Eigen::Vector3d>& v = dm.vertices();
                const Eigen::Vector3d p = w[0] * v[t[0]] + w[1] * v[t[1]] + w[2] * v[t[2]];
                const Eigen::Vector3f local = (p - dm.model().origin()).cast<float>();
                double least = INFINITY;
                for (const CompactNode& n : tree.nodes())
                    if (n.is_active())
                        for (uint32_t k = n.first; k < n.first + n.count; ++k)
                            least = std::min(least, double((local - tree.sphere_center(n, k)).norm()) - double(n.ss_radius));
                largest = std::max(largest, std::max(0.0, least));
            }
    return largest;
}

TEST(Coverage, TheLargestGapIsTheLeastOverEverySphereAtThePointFarthestOut) {
    const DeformingModel dm(bar().doc, bar().mesh);
    const Clip& bend = bar().mesh->clips[0];
    const ClipCoverage c = dm.measure_coverage(bend, 10, 2);
    EXPECT_EQ(c.bind_gap, largest_gap_by_every_sphere(nullptr, 0));
    EXPECT_EQ(c.largest_gap, largest_gap_by_every_sphere(&bend, c.time));
    // No other pose's gap is larger (a few of them: the slow loop takes a while at each).
    ASSERT_EQ(c.poses, 11);
    for (int k : {2, 5, 8}) EXPECT_LE(largest_gap_by_every_sphere(&bend, bend.duration * k / 10), c.largest_gap) << k;
}

} // namespace
} // namespace spt
