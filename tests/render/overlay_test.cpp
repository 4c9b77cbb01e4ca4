// Tree and collision overlays: sphere colours and ranges, bounding spheres, sphere pairs.
#include "spt/collision_model.hpp"
#include "spt/compact_tree.hpp"
#include "spt/convert.hpp"
#include "spt/query.hpp"
#include "spt/render/collision_overlay.hpp"
#include "spt/render/tree_overlay.hpp"
#include "test_meshes.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

using namespace spt;
using namespace spt::render;

namespace {

struct TreeFixture : ::testing::Test {
    TriangleMesh mesh = test::box_figure();
    SptDocument doc = make_document(mesh);
    const SamplingTree& tree = doc.trees.front();
    CompactTree compact{tree, doc.samples};
};

// Samples below a node, from the tree itself.
std::set<uint32_t> samples_below(const SamplingTree& tree, NodeId id) {
    std::set<uint32_t> out;
    const TreeNode* n = tree.find(id);
    if (!n) return out;
    if (n->active) return {n->samples.begin(), n->samples.end()};
    for (NodeId c : {left_child(id), right_child(id)}) {
        const auto s = samples_below(tree, c);
        out.insert(s.begin(), s.end());
    }
    return out;
}

TEST_F(TreeFixture, sampling_spheres_follow_the_compact_layout_and_levels) {
    ASSERT_GT(tree.depth(), 2);
    const auto spheres = sampling_spheres(compact, tree, ColorBy::Level);
    ASSERT_EQ(spheres.size(), compact.sphere_count());
    for (const TreeNode* n : tree.active_nodes()) {
        const SphereRange r = sphere_range(compact, tree, n->id);
        ASSERT_EQ(r.count, n->samples.size());
        const Color c = level_color(node_depth(n->id));
        for (uint32_t k = r.first; k < r.first + r.count; ++k) {
            EXPECT_EQ(spheres[k].sphere.radius, n->ss_radius);
            EXPECT_EQ(spheres[k].color.r, c.r);
            EXPECT_EQ(spheres[k].color.g, c.g);
        }
    }
}

TEST_F(TreeFixture, sphere_range_of_a_node_is_exactly_its_subtree) {
    for (const TreeNode* n : tree.nodes()) {
        const SphereRange r = sphere_range(compact, tree, n->id);
        std::set<uint32_t> in_range;
        for (uint32_t k = r.first; k < r.first + r.count; ++k) in_range.insert(compact.sample_index()[k]);
        EXPECT_EQ(in_range, samples_below(tree, n->id)) << "node " << n->id;
    }
    const SphereRange root = sphere_range(compact, tree, root_id());
    EXPECT_EQ(root.first, 0u);
    EXPECT_EQ(root.count, compact.sphere_count());
    EXPECT_EQ(sphere_range(compact, tree, NodeId(1) << 40).count, 0u);
}

TEST_F(TreeFixture, bounding_spheres_cover_the_requested_levels) {
    const Color red{1, 0, 0, 1};
    const auto one = bounding_spheres(tree, doc.samples.origin, root_id(), 0, red);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].sphere.radius, tree.find(root_id())->bv_radius);
    EXPECT_EQ(one[0].color.r, 1.0f);
    size_t expected = 0;
    for (const TreeNode* n : tree.nodes()) expected += node_depth(n->id) <= 2;
    EXPECT_EQ(bounding_spheres(tree, doc.samples.origin, root_id(), 2, red).size(), expected);
    // The local origin, then a pose, move the centres into the world.
    const Eigen::Affine3f pose(Eigen::Translation3f(0, 5, 0));
    EXPECT_NEAR(bounding_spheres(tree, doc.samples.origin, root_id(), 0, red, pose)[0].sphere.center.y(),
                tree.find(root_id())->center.y() + doc.samples.origin.y() + 5, 1e-5f);
    EXPECT_TRUE(bounding_spheres(tree, doc.samples.origin, NodeId(1) << 40, 1, red).empty());
}

TEST_F(TreeFixture, bounding_sphere_of_the_layout_is_the_trees_at_the_bind_pose_and_follows_a_refit) {
    const Color red{1, 0, 0, 1};
    for (const TreeNode* n : tree.nodes()) {
        const auto from_layout = bounding_sphere(compact, tree, n->id, red);
        const auto from_tree = bounding_spheres(tree, doc.samples.origin, n->id, 0, red);
        ASSERT_EQ(from_layout.size(), 1u);
        EXPECT_EQ(from_layout[0].sphere.center, from_tree[0].sphere.center) << "node " << n->id;
        EXPECT_EQ(from_layout[0].sphere.radius, from_tree[0].sphere.radius) << "node " << n->id;
        EXPECT_EQ(from_layout[0].color.r, 1.0f);
    }
    // Every sample moved by 2 in y: the layout's refit balls move with them.
    CompactTree still = compact, moved = compact;
    still.refit_bounds();
    std::vector<Eigen::Vector3f> points = doc.samples.points;
    for (Eigen::Vector3f& p : points) p.y() += 2;
    moved.follow_samples(points, doc.samples.normals);
    for (const TreeNode* n : tree.nodes()) {
        const WireSphere a = bounding_sphere(still, tree, n->id, red)[0], b = bounding_sphere(moved, tree, n->id, red)[0];
        EXPECT_NEAR(b.sphere.center.y(), a.sphere.center.y() + 2, 1e-4f) << "node " << n->id;
        EXPECT_NEAR(b.sphere.radius, a.sphere.radius, 1e-4f) << "node " << n->id;
    }
    EXPECT_TRUE(bounding_sphere(compact, tree, NodeId(1) << 40, red).empty());
}

TEST(TreeOverlay, RangesAndBallsOfADeepOneSidedTreeAreEachNodesOwn) {
    // Nodes are found in the layout by their path from the root (left child next, right child
    // at `first`): a chain 30 deep, with some left parts split too, checks every turn.
    SampleSet s;
    for (uint32_t i = 0; i < 120; ++i) s.add({float(i % 7), float(i / 7), float(i % 3)}, {0, 0, 1}, i, 0.2f);
    SamplingTree tree("deep", 120);
    tree.assign_radii(s, {});
    tree.compute_bounds(s, BoundsMethod::Tight);
    NodeId rest = root_id();
    for (uint32_t step = 0; step < 30; ++step) {
        const TreeNode& n = *tree.find(rest);
        ASSERT_TRUE(tree.split(rest, {n.samples[0], n.samples[1], n.samples[2]}, s));
        if (step % 4 == 1) {
            ASSERT_TRUE(tree.split(left_child(rest), {tree.find(left_child(rest))->samples[1]}, s));
        }
        rest = right_child(rest);
    }
    ASSERT_EQ(tree.validate(120), "");
    const CompactTree compact(tree, s);
    const Color red{1, 0, 0, 1};
    for (const TreeNode* n : tree.nodes()) {
        const SphereRange r = sphere_range(compact, tree, n->id);
        std::set<uint32_t> in_range;
        for (uint32_t k = r.first; k < r.first + r.count; ++k) in_range.insert(compact.sample_index()[k]);
        EXPECT_EQ(in_range, samples_below(tree, n->id)) << "node " << n->id;
        const auto ball = bounding_sphere(compact, tree, n->id, red);
        ASSERT_EQ(ball.size(), 1u);
        EXPECT_EQ(ball[0].sphere.radius, n->bv_radius) << "node " << n->id;
        EXPECT_EQ(ball[0].sphere.center, n->center) << "node " << n->id;
    }
    EXPECT_EQ(sphere_range(compact, tree, right_child(rest)).count, 0u);
    EXPECT_TRUE(bounding_sphere(compact, tree, left_child(rest), red).empty());
    // A layout of the tree as it was before another split: nothing for the nodes it lacks, and
    // never a range past its own spheres.
    SamplingTree edited = tree;
    ASSERT_TRUE(edited.split(rest, {edited.find(rest)->samples[0]}, s));
    for (const TreeNode* n : edited.nodes()) {
        const SphereRange r = sphere_range(compact, edited, n->id);
        EXPECT_LE(uint64_t(r.first) + r.count, compact.sphere_count()) << "node " << n->id;
    }
    EXPECT_EQ(sphere_range(compact, edited, left_child(rest)).count, 0u);
    EXPECT_EQ(sphere_range(compact, edited, rest).count, 0u);
    EXPECT_TRUE(bounding_sphere(compact, edited, right_child(rest), red).empty());
}

bool same_color(const Color& a, const Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }

TEST_F(TreeFixture, contacts_colour_each_sphere_by_its_samples_count) {
    std::vector<uint32_t> counts(doc.samples.size(), 0);
    for (size_t i = 0; i < counts.size(); i += 3) counts[i] = uint32_t(1 + i % 7);
    const HeatScale scale = heat_scale(counts);
    EXPECT_EQ(scale.low, 1u);
    EXPECT_EQ(scale.high, 7u);
    EXPECT_FALSE(scale.log);
    const auto spheres = sampling_spheres(compact, tree, ColorBy::Contacts, Eigen::Vector3d::Zero(), &counts);
    ASSERT_EQ(spheres.size(), compact.sphere_count());
    const uint32_t* sample = compact.sample_index();
    for (size_t k = 0; k < spheres.size(); ++k)
        EXPECT_TRUE(same_color(spheres[k].color, heat_color(scale, counts[sample[k]]))) << k;
    EXPECT_TRUE(same_color(heat_color(scale, 0), heat_zero_color()));
    // The ramp runs from dark to light: the largest count is brighter than the smallest.
    const Color lo = heat_color(scale, 1), hi = heat_color(scale, 7);
    EXPECT_GT(hi.r + hi.g + hi.b, lo.r + lo.g + lo.b + 1.0f);
    // No counts: every sphere grey.
    for (const SphereInstance& s : sampling_spheres(compact, tree, ColorBy::Contacts))
        EXPECT_TRUE(same_color(s.color, heat_zero_color()));
}

TEST(overlay, heat_scale_is_logarithmic_beyond_a_ratio_of_twenty_and_its_legend_counts_every_sample) {
    std::vector<uint32_t> counts = {0, 0, 0, 1, 1, 2, 5, 10, 40, 100, 100};
    const HeatScale scale = heat_scale(counts);
    EXPECT_TRUE(scale.log);
    // On a log scale 10 sits half way between 1 and 100; on a linear one it would be near the bottom.
    const Color mid = heat_color(scale, 10), lin_mid = heat_color(HeatScale{1, 100, false}, 50);
    EXPECT_NEAR(mid.g, lin_mid.g, 0.02f);
    EXPECT_FALSE(heat_scale({0, 3, 60}).log);
    EXPECT_TRUE(heat_scale({0, 3, 61}).log);
    const auto legend = heat_legend(scale, counts);
    ASSERT_GE(legend.size(), 3u);
    EXPECT_EQ(legend.front().from, 0u);
    EXPECT_EQ(legend.front().to, 0u);
    EXPECT_EQ(legend.front().samples, 3u);
    size_t total = 0;
    for (size_t i = 0; i < legend.size(); ++i) {
        total += legend[i].samples;
        if (i > 0) {
            EXPECT_EQ(legend[i].from, legend[i - 1].to + 1);
        }
    }
    EXPECT_EQ(total, counts.size());
    EXPECT_EQ(legend.back().to, 100u);
    // All zero: one row.
    EXPECT_EQ(heat_legend(heat_scale({0, 0}), {0, 0}).size(), 1u);
}

TEST(overlay, node_colours_are_stable_and_distinct) {
    EXPECT_EQ(node_color(5).r, node_color(5).r);
    int same = 0;
    for (NodeId id = 2; id < 64; ++id) same += node_color(id).r == node_color(id + 1).r && node_color(id).g == node_color(id + 1).g;
    EXPECT_EQ(same, 0);
    // The two children of every split in opposite hues: far apart in colour.
    for (NodeId id = 1; id < 64; ++id) {
        const Color a = node_color(2 * id), b = node_color(2 * id + 1);
        const float d = std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
        EXPECT_GT(d, 0.5f) << "children of node " << id << " look alike";
    }
    EXPECT_EQ(level_color(0).r, level_color(10).r);
    EXPECT_NE(level_color(0).r, level_color(1).r);
}

TEST(overlay, an_inner_node_keeps_its_childrens_colours_and_hidden_ranges_are_cut) {
    const SphereSetHandle set{7};
    // An active node: one flat highlight colour; an inner one: its spheres' own colours, undimmed.
    const auto leaf = highlighted_node(set, 100, {40, 20}, true);
    ASSERT_EQ(leaf.size(), 3u);
    EXPECT_TRUE(leaf.back().color.has_value());
    const auto inner = highlighted_node(set, 100, {40, 20}, true, true);
    ASSERT_EQ(inner.size(), 3u);
    EXPECT_FALSE(inner.back().color.has_value());
    EXPECT_EQ(inner.back().fade, 0.0f);
    // Items cut to the shown ranges: the dimmed [0, 40) and [60, 100) and the node [40, 60) less [30, 50).
    const auto cut = clip_to_ranges(leaf, {{0, 30}, {50, 50}});
    std::vector<std::pair<uint32_t, uint32_t>> ranges;
    for (const SphereItem& i : cut) ranges.emplace_back(i.first, i.count);
    EXPECT_EQ(ranges, (std::vector<std::pair<uint32_t, uint32_t>>{{0, 30}, {60, 40}, {50, 10}}));
}

TEST(overlay, sphere_pairs_by_brute_force) {
    const std::vector<Sphere> a = {{{0, 0, 0}, 1}, {{10, 0, 0}, 1}};
    const std::vector<Sphere> b = {{{1.5f, 0, 0}, 1}, {{0, 2, 0}, 1}, {{20, 0, 0}, 1}};
    const auto pairs = overlapping_pairs(a, b);
    ASSERT_EQ(pairs.size(), 1u); // {0,2,0} only touches: not a collision
    EXPECT_FLOAT_EQ(pairs[0].depth, 0.5f);
    EXPECT_TRUE(pairs[0].normal.isApprox(Eigen::Vector3f::UnitX()));
    EXPECT_TRUE(pairs[0].contact.isApprox(Eigen::Vector3f(0.75f, 0, 0)));
    const render::SpherePair same = make_sphere_pair({{1, 1, 1}, 1}, {{1, 1, 1}, 2});
    EXPECT_TRUE(same.normal.isApprox(Eigen::Vector3f::UnitY()));
    EXPECT_FLOAT_EQ(same.depth, 3.0f);
}

// The sweep keeps exactly the pairs, in the order, of testing every sphere of a against every
// sphere of b: spheres of many sizes, ties in x, one far out that reaches back, one with a NaN
// centre (overlaps nothing), one of infinite radius (overlaps every finite one) and one of
// negative radius.
TEST(overlay, sphere_pairs_are_those_of_pairing_off_every_sphere) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-4, 4), size(0.01f, 0.8f);
    auto spheres = [&](int n) {
        std::vector<Sphere> s;
        for (int k = 0; k < n; ++k) s.push_back({{u(rng), u(rng), u(rng)}, size(rng)});
        s.push_back({{s[3].center.x(), 0, 0}, 0.5f});     // the same x as another
        s.push_back({{1e7f, 0, 0}, 1e7f});                // reaches back to the others
        s.push_back({{NAN, 0, 0}, 1});
        s.push_back({{0, 0, 0}, std::numeric_limits<float>::infinity()});
        s.push_back({{1, 1, 1}, -0.9f}); // the pair test squares the sum of radii
        return s;
    };
    const std::vector<Sphere> a = spheres(300), b = spheres(400);
    std::vector<render::SpherePair> expected;
    for (const Sphere& x : a)
        for (const Sphere& y : b) {
            const float r = x.radius + y.radius;
            if ((y.center - x.center).squaredNorm() < r * r) expected.push_back(make_sphere_pair(x, y));
        }
    const auto pairs = overlapping_pairs(a, b);
    ASSERT_EQ(pairs.size(), expected.size());
    ASSERT_GT(pairs.size(), 300u);
    for (size_t k = 0; k < pairs.size(); ++k) {
        EXPECT_EQ(pairs[k].a.center, expected[k].a.center) << k;
        EXPECT_EQ(pairs[k].b.center, expected[k].b.center) << k;
        EXPECT_EQ(pairs[k].b.radius, expected[k].b.radius) << k;
    }
}

TEST_F(TreeFixture, world_spheres_apply_the_pose) {
    const Eigen::Affine3f pose(Eigen::Translation3f(1, 2, 3));
    const auto local = world_spheres(compact, Eigen::Affine3f::Identity());
    const auto moved = world_spheres(compact, pose);
    ASSERT_EQ(moved.size(), compact.sphere_count());
    for (size_t i = 0; i < moved.size(); i += 17) {
        EXPECT_TRUE(moved[i].center.isApprox(local[i].center + Eigen::Vector3f(1, 2, 3)));
        EXPECT_EQ(moved[i].radius, local[i].radius);
    }
}

// The path collision_overlay.hpp documents: a query's pairs index world_spheres().
// Brute force over the same world spheres (every 31st of A's, all of B's) is the
// independent reference.
TEST_F(TreeFixture, query_pairs_index_world_spheres) {
    const CollisionModel model(doc);
    const Eigen::Vector3d shift(0.5 * model.diagonal(), 0.1 * model.diagonal(), 0);
    const Pose pose_b = Pose::from(shift, Eigen::Quaterniond::Identity());
    QueryOptions options;
    options.level = QueryLevel::Spheres;
    options.mode = QueryMode::All;
    QueryScratch scratch;
    const QueryResult result = collide(model, Pose::identity(), model, pose_b, options, scratch);
    ASSERT_TRUE(result.collide);
    const auto world_a = world_spheres(model.tree(), Eigen::Affine3f::Identity());
    const auto world_b = world_spheres(model.tree(), Eigen::Affine3f(Eigen::Translation3f(shift.cast<float>())));

    // Float rounding may only move pairs that barely touch.
    const float eps = 1e-4f * float(model.diagonal());
    std::vector<std::pair<uint32_t, uint32_t>> found;
    for (const spt::SpherePair& p : scratch.pairs()) {
        ASSERT_LT(p.a, world_a.size());
        ASSERT_LT(p.b, world_b.size());
        const render::SpherePair drawn = make_sphere_pair(world_a[p.a], world_b[p.b]);
        EXPECT_NEAR(drawn.depth, p.depth, eps) << "pair " << p.a << ", " << p.b;
        found.emplace_back(p.a, p.b);
    }
    std::sort(found.begin(), found.end());
    size_t clear_overlaps = 0;
    for (uint32_t i = 0; i < world_a.size(); i += 31)
        for (uint32_t j = 0; j < world_b.size(); ++j) {
            const float reach = world_a[i].radius + world_b[j].radius - eps;
            if (reach <= 0 || (world_b[j].center - world_a[i].center).squaredNorm() >= reach * reach) continue;
            EXPECT_TRUE(std::binary_search(found.begin(), found.end(), std::make_pair(i, j)))
                << "pair " << i << ", " << j << " overlaps but the query missed it";
            ++clear_overlaps;
        }
    EXPECT_GT(clear_overlaps, 0u);
}

} // namespace
