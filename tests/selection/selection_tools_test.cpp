// Lasso, brush, linked, invert, grow and shrink in core against answers computed from positions
// and the mesh alone; their recipe strokes through .spt version 5 and replayed on a changed mesh.
#include "mesh/shapes.hpp"
#include "base/parallel.hpp"
#include "spt/error.hpp"
#include "spt/recipe.hpp"
#include "spt/selection.hpp"
#include "spt/spt_file.hpp"
#include "spt_reseal.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <cstring>
#include <functional>
#include <set>

using namespace spt;

namespace {

// Orthographic view down -Z: object x, y in [-4, 4] fill a 400x400 framebuffer, window x = (x + 4) * 50.
ViewProjection tools_view() {
    ViewProjection v;
    v.view(2, 3) = -10;
    v.projection = Eigen::Matrix4f::Identity();
    v.projection(0, 0) = v.projection(1, 1) = 0.25f;
    v.projection(2, 2) = -0.05f;
    v.width = v.height = 400;
    return v;
}

Eigen::Vector2d tools_window(const SampleSet& s, uint32_t i) {
    const Eigen::Vector3d p = s.position(i);
    return {(p.x() + 4) * 50, (p.y() + 4) * 50};
}

// Two tori apart along x (centres -1.6 and +1.6): two mesh parts.
TriangleMesh two_tori(int nu, int nv, double wobble) {
    const TriangleMesh a = make_torus(1.0, 0.3, nu, nv);
    std::vector<Eigen::Vector3d> positions;
    std::vector<Triangle> triangles;
    for (double cx : {-1.6, 1.6}) {
        const uint32_t base = uint32_t(positions.size());
        for (Eigen::Vector3d p : a.positions) {
            p.x() += cx;
            p.z() += wobble * std::sin(7 * p.x());
            positions.push_back(p);
        }
        for (Triangle t : a.triangles) triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    return prepare_mesh("two.obj", positions, triangles).mesh;
}

std::vector<uint32_t> tools_where(const SampleSet& s, const std::function<bool(uint32_t)>& in) {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < s.size(); ++i)
        if (in(i)) out.push_back(i);
    return out;
}

RecipeStroke lasso(std::vector<Eigen::Vector2f> polygon, SelectionMode mode = SelectionMode::Replace) {
    RecipeStroke s{tools_view(), {}, mode, false};
    s.kind = StrokeKind::Lasso;
    s.points = std::move(polygon);
    return s;
}

RecipeStroke brush(std::vector<Eigen::Vector2f> path, float radius, SelectionMode mode = SelectionMode::Replace) {
    RecipeStroke s{tools_view(), {}, mode, false};
    s.kind = StrokeKind::Brush;
    s.points = std::move(path);
    s.radius = radius;
    return s;
}

RecipeStroke operation(StrokeKind kind) {
    RecipeStroke s;
    s.kind = kind;
    return s;
}

RecipeStroke linked(const Eigen::Vector3d& pick, SelectionMode mode = SelectionMode::Replace) {
    RecipeStroke s{tools_view(), {}, mode, false};
    s.kind = StrokeKind::Linked;
    s.pick = pick;
    return s;
}

struct ToolsDoc {
    SptDocument doc;
    TriangleMesh mesh;
};

ToolsDoc tools_doc(int nu, int nv, double wobble) {
    ToolsDoc d;
    d.mesh = two_tori(nu, nv, wobble);
    d.doc.samples = test::vertex_samples(d.mesh);
    d.doc.mesh = {"two.obj", uint32_t(d.mesh.positions.size()), uint32_t(d.mesh.triangles.size()),
                  d.mesh.content_hash(), d.mesh.diagonal()};
    d.doc.trees.push_back(unsplit_tree("t", d.doc.samples));
    return d;
}

// The vertices of `mesh` joined to v by an edge.
std::set<uint32_t> ring(const TriangleMesh& mesh, uint32_t v) {
    std::set<uint32_t> out;
    for (const Triangle& t : mesh.triangles)
        for (int c = 0; c < 3; ++c)
            if (t[c] == v) out.insert({t[(c + 1) % 3], t[(c + 2) % 3]});
    return out;
}

} // namespace

TEST(SelectionTools, LassoSelectsThePointsInsideATriangleAndAConcavePolygon) {
    const ToolsDoc d = tools_doc(40, 16, 0);
    const SampleSet& s = d.doc.samples;
    const SamplingTree& t = d.doc.trees.front();
    // Right triangle (0, 0), (300, 0), (0, 295): inside when x / 300 + y / 295 < 1.
    const std::vector<Eigen::Vector2f> tri{{0, 0}, {300, 0}, {0, 295}};
    const auto in_tri = tools_where(s, [&](uint32_t i) {
        const Eigen::Vector2d w = tools_window(s, i);
        return w.x() >= 0 && w.y() >= 0 && w.x() / 300 + w.y() / 295 < 1;
    });
    ASSERT_GT(in_tri.size(), 20u);
    EXPECT_EQ(samples_in_polygon(s, t, root_id(), tools_view(), tri), in_tri);
    // A "U" open upwards, drawn clockwise: the notch x in (150, 250), y > 150 is outside.
    const std::vector<Eigen::Vector2f> u{{100, 100}, {100, 300}, {150, 300}, {150, 150},
                                         {250, 150}, {250, 300}, {300, 300}, {300, 100}};
    const auto in_u = tools_where(s, [&](uint32_t i) {
        const Eigen::Vector2d w = tools_window(s, i);
        const bool box = w.x() > 100 && w.x() < 300 && w.y() > 100 && w.y() < 300;
        const bool notch = w.x() > 150 && w.x() < 250 && w.y() > 150;
        return box && !notch;
    });
    ASSERT_GT(in_u.size(), 20u);
    EXPECT_EQ(samples_in_polygon(s, t, root_id(), tools_view(), u), in_u);
    EXPECT_TRUE(samples_in_polygon(s, t, root_id(), tools_view(), {{0, 0}, {400, 400}}).empty()) << "two vertices";
    try {
        samples_in_polygon(s, t, root_id(), tools_view(), {{0, 0}, {NAN, 1}, {4, 4}});
        ADD_FAILURE() << "a NaN vertex was taken";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Usage);
        EXPECT_NE(std::string(e.what()).find("lasso point 1 is not finite"), std::string::npos) << e.what();
    }
}

TEST(SelectionTools, BrushSelectsThePointsWithinItsRadiusOfThePath) {
    const ToolsDoc d = tools_doc(40, 16, 0);
    const SampleSet& s = d.doc.samples;
    const SamplingTree& t = d.doc.trees.front();
    // A horizontal stroke from (50, 200) to (350, 200), radius 20: |y - 200| <= 20 between the
    // ends, within 20 of an end beyond them.
    const std::vector<Eigen::Vector2f> path{{50, 200}, {200, 200}, {350, 200}};
    const auto near = tools_where(s, [&](uint32_t i) {
        const Eigen::Vector2d w = tools_window(s, i);
        const double dx = w.x() < 50 ? 50 - w.x() : w.x() > 350 ? w.x() - 350 : 0;
        return dx * dx + (w.y() - 200) * (w.y() - 200) <= 400;
    });
    ASSERT_GT(near.size(), 20u);
    EXPECT_EQ(samples_in_brush(s, t, root_id(), tools_view(), path, 20), near);
    // One point: a circle.
    const auto circle = tools_where(s, [&](uint32_t i) { return (tools_window(s, i) - Eigen::Vector2d(70, 200)).norm() <= 30; });
    ASSERT_FALSE(circle.empty());
    EXPECT_EQ(samples_in_brush(s, t, root_id(), tools_view(), {{70, 200}}, 30), circle);
    EXPECT_THROW(samples_in_brush(s, t, root_id(), tools_view(), path, NAN), Error);
    EXPECT_THROW(samples_in_brush(s, t, root_id(), tools_view(), path, -1), Error);
}

TEST(SelectionTools, VisibleOnlyLassoAndBrushKeepTheNearFaceOfABox) {
    const TriangleMesh box = make_box({0.5, 0.5, 0.5}, 6);
    const SampleSet s = test::vertex_samples(box);
    const SamplingTree t("t", uint32_t(s.size()));
    const ViewProjection v = tools_view();
    // Window [180, 220]^2 is x, y in [-0.4, 0.4]: inside the front face z = 0.5.
    const std::vector<Eigen::Vector2f> square{{180, 180}, {220, 180}, {220, 220}, {180, 220}};
    std::vector<uint32_t> front, both;
    for (uint32_t i = 0; i < s.size(); ++i) {
        const Eigen::Vector2d w = tools_window(s, i);
        if (w.x() <= 180 || w.x() >= 220 || w.y() <= 180 || w.y() >= 220) continue;
        both.push_back(i);
        if (s.position(i).z() > 0.49) front.push_back(i);
    }
    ASSERT_FALSE(front.empty());
    ASSERT_GT(both.size(), front.size());
    RecipeStroke stroke = lasso(square);
    EXPECT_EQ(samples_in_polygon(s, t, 1, v, square), both);
    stroke.visible_only = true;
    EXPECT_EQ(stroke_hits(s, t, 1, stroke, &box), front);
    // A brush of radius 24 about the centre covers the square's samples (corners 23.6 pixels out), not the edges at 25.
    RecipeStroke round = brush({{200, 200}}, 24);
    round.visible_only = true;
    const std::vector<uint32_t> hits = stroke_hits(s, t, 1, round, &box);
    for (uint32_t i : hits) EXPECT_GT(s.position(i).z(), 0.49);
    EXPECT_TRUE(std::includes(hits.begin(), hits.end(), front.begin(), front.end()));
}

TEST(SelectionTools, NeighboursAreTheSamplesOnTheVertexAndItsEdgeRing) {
    const ToolsDoc d = tools_doc(24, 10, 0);
    const SampleAdjacency adj(d.mesh, d.doc.samples);
    ASSERT_EQ(adj.size(), d.doc.samples.size());
    for (uint32_t s : {0u, 17u, 250u}) {
        const uint32_t v = d.doc.samples.source_index(s);
        std::vector<uint32_t> expected;
        for (uint32_t w : ring(d.mesh, v))
            for (uint32_t k = 0; k < d.doc.samples.size(); ++k)
                if (d.doc.samples.source_index(k) == w) expected.push_back(k);
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(sample_neighbours(adj, s), expected) << "sample " << s;
    }
}

TEST(SelectionTools, AFaceSampleNeighboursTheSamplesOfItsTrianglesCorners) {
    const TriangleMesh mesh = make_torus(1.0, 0.3, 12, 6);
    SampleSet s = test::vertex_samples(mesh);
    const Triangle& t0 = mesh.triangles[5];
    const Eigen::Vector3d c = (mesh.positions[t0[0]] + mesh.positions[t0[1]] + mesh.positions[t0[2]]) / 3;
    s.add(c.cast<float>(), {0, 0, 1}, 5u | kFaceSampleBit, 0.1f);
    const uint32_t face = uint32_t(s.size() - 1);
    const SampleAdjacency adj(mesh, s);
    const std::vector<uint32_t> n = adj.neighbours(face);
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::binary_search(n.begin(), n.end(), t0[k])) << "corner " << t0[k];
    const std::vector<uint32_t> back = adj.neighbours(t0[0]);
    EXPECT_TRUE(std::binary_search(back.begin(), back.end(), face));
    // Samples of another mesh are refused, not read past its arrays.
    SampleSet beyond = s;
    beyond.sources.back() = 100000u | kFaceSampleBit;
    EXPECT_THROW(SampleAdjacency(mesh, beyond), Error);
}

TEST(SelectionTools, LinkedGrowShrinkAndInvertOnTwoParts) {
    const ToolsDoc d = tools_doc(24, 10, 0);
    const SampleSet& s = d.doc.samples;
    SamplingTree t = d.doc.trees.front();
    const SampleAdjacency adj(d.mesh, s);
    const auto left = tools_where(s, [&](uint32_t i) { return s.position(i).x() < 0; });
    const auto right = tools_where(s, [&](uint32_t i) { return s.position(i).x() > 0; });
    ASSERT_EQ(left.size() + right.size(), s.size());
    EXPECT_EQ(linked_samples(adj, t, root_id(), left[7]), left);
    EXPECT_EQ(linked_samples(adj, t, root_id(), right[3]), right);
    EXPECT_EQ(invert_selection(t, root_id(), left), right);
    EXPECT_EQ(invert_selection(t, root_id(), {}), samples_below(t, root_id()));
    // Grow from one sample: it and its ring; shrink gives it back; shrinking it alone leaves nothing.
    const uint32_t seed = left[40];
    std::vector<uint32_t> ring1 = adj.neighbours(seed);
    ring1.push_back(seed);
    std::sort(ring1.begin(), ring1.end());
    const std::vector<uint32_t> grown = grow_selection(adj, t, root_id(), {seed});
    EXPECT_EQ(grown, ring1);
    EXPECT_EQ(shrink_selection(adj, t, root_id(), grown), std::vector<uint32_t>{seed});
    EXPECT_TRUE(shrink_selection(adj, t, root_id(), {seed}).empty());
    // Growing fills its part and never crosses to the other; a whole part does not shrink.
    std::vector<uint32_t> g{seed};
    for (int k = 0; k < 40; ++k) g = grow_selection(adj, t, root_id(), g);
    EXPECT_EQ(g, left);
    EXPECT_EQ(shrink_selection(adj, t, root_id(), left), left);
    // Below a child node only its samples count: split the left torus at y = 0.
    const auto low = tools_where(s, [&](uint32_t i) { return s.position(i).y() < 0; });
    ASSERT_TRUE(t.split(root_id(), low, s));
    std::vector<uint32_t> low_left;
    std::set_intersection(low.begin(), low.end(), left.begin(), left.end(), std::back_inserter(low_left));
    EXPECT_EQ(linked_samples(adj, t, 2, left[7]), low_left);
    // Within node 2 the cut at y = 0 is no boundary: the node's half-torus shrinks only there.
    const std::vector<uint32_t> shrunk = shrink_selection(adj, t, 2, low_left);
    EXPECT_EQ(shrunk, low_left);
}

TEST(SelectionTools, PickTakesTheNearestSampleInTheWindowAndNearestSampleInSpace) {
    const ToolsDoc d = tools_doc(24, 10, 0);
    const SampleSet& s = d.doc.samples;
    const SamplingTree& t = d.doc.trees.front();
    const uint32_t target = 123;
    const Eigen::Vector2d w = tools_window(s, target);
    const int64_t picked = pick_sample(s, t, root_id(), tools_view(), w.cast<float>(), 4);
    ASSERT_GE(picked, 0);
    EXPECT_LE((tools_window(s, uint32_t(picked)) - w).norm(), 1e-3);
    EXPECT_EQ(pick_sample(s, t, root_id(), tools_view(), {1, 1}, 4), -1) << "nothing within 4 pixels of a corner";
    EXPECT_EQ(nearest_sample(s, t, root_id(), s.position(target)), int64_t(target));
}

TEST(SelectionTools, StrokesCombineInOrderAsARecipeStepRecordsThem) {
    const ToolsDoc d = tools_doc(24, 10, 0);
    const SampleSet& s = d.doc.samples;
    const SamplingTree& t = d.doc.trees.front();
    const SampleAdjacency adj(d.mesh, s);
    const auto left = tools_where(s, [&](uint32_t i) { return s.position(i).x() < 0; });
    // Linked on the left torus, less a brush band, grown, inverted: what the functions give in turn.
    const RecipeStep step{root_id(),
                          {linked(s.position(left[3])), brush({{0, 200}, {400, 200}}, 10, SelectionMode::Subtract),
                           operation(StrokeKind::Grow), operation(StrokeKind::Invert)}};
    std::vector<uint32_t> expected = linked_samples(adj, t, root_id(), left[3]);
    expected = combine_selection(expected, samples_in_brush(s, t, root_id(), tools_view(), {{0, 200}, {400, 200}}, 10),
                                 SelectionMode::Subtract);
    expected = invert_selection(t, root_id(), grow_selection(adj, t, root_id(), expected));
    EXPECT_EQ(select_strokes(s, t, step, &d.mesh, &adj), expected);
    EXPECT_THROW(select_strokes(s, t, step, &d.mesh, nullptr), Error) << "linked without adjacency";
}

namespace {

// A tree split by every new kind: node 2 = the left torus (linked) grown and shrunk, node 3's
// lasso (node 6) and a brush band added, then node 7 split by the inverse of a lasso.
ToolsDoc tools_authored(int nu, int nv, double wobble) {
    ToolsDoc d = tools_doc(nu, nv, wobble);
    SamplingTree t = d.doc.trees.front();
    const SampleAdjacency adj(d.mesh, d.doc.samples);
    const std::vector<RecipeStep> steps{
        {1, {linked({-2.6, 0, 0}), operation(StrokeKind::Grow), operation(StrokeKind::Shrink)}},
        {3, {lasso({{250, 0}, {400, 0}, {400, 400}, {250, 400}}), brush({{200, 0}, {200, 400}}, 15, SelectionMode::Add)}},
        {7, {lasso({{0, 200}, {400, 200}, {400, 400}, {0, 400}}), operation(StrokeKind::Invert)}},
    };
    for (const RecipeStep& step : steps) {
        EXPECT_TRUE(t.split(step.node, select_strokes(d.doc.samples, t, step, &d.mesh, &adj), d.doc.samples));
        t.add_recipe_step(step);
    }
    d.doc.trees.front() = std::move(t);
    return d;
}

std::vector<uint8_t> tools_resealed(std::vector<uint8_t> bytes) {
    test::reseal(bytes);
    return bytes;
}

} // namespace

TEST(SelectionTools, Version5KeepsEveryStrokeKindByteForByte) {
    const ToolsDoc d = tools_authored(24, 10, 0);
    EXPECT_EQ(spt_version_for(d.doc), 5u);
    const std::vector<uint8_t> bytes = encode_spt(d.doc);
    uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 8, 4);
    EXPECT_EQ(version, 5u);
    const SptDocument back = decode_spt(bytes);
    const auto& a = d.doc.trees.front().recipe();
    const auto& b = back.trees.front().recipe();
    ASSERT_EQ(a.size(), b.size());
    for (size_t k = 0; k < a.size(); ++k) {
        ASSERT_EQ(a[k].strokes.size(), b[k].strokes.size());
        for (size_t j = 0; j < a[k].strokes.size(); ++j) {
            EXPECT_EQ(a[k].strokes[j].kind, b[k].strokes[j].kind);
            EXPECT_EQ(a[k].strokes[j].points, b[k].strokes[j].points);
            EXPECT_EQ(a[k].strokes[j].radius, b[k].strokes[j].radius);
            EXPECT_EQ(a[k].strokes[j].pick, b[k].strokes[j].pick);
            EXPECT_EQ(a[k].strokes[j].mode, b[k].strokes[j].mode);
        }
    }
    EXPECT_EQ(encode_spt(back), bytes);
    // The same document with rectangles only stays version 3.
    SptDocument rects = d.doc;
    std::vector<RecipeStep> steps{{1, {RecipeStroke{tools_view(), {0, 0, 200, 400}, SelectionMode::Replace, false}}}};
    rects.trees.front() = unsplit_tree("t", rects.samples);
    ASSERT_TRUE(rects.trees.front().split(1, select_strokes(rects.samples, rects.trees.front(), steps[0], &d.mesh),
                                          rects.samples));
    rects.trees.front().add_recipe_step(steps[0]);
    EXPECT_EQ(spt_version_for(rects), 3u);
}

TEST(SelectionTools, ABadVersion5StrokeIsRefusedNamingTheFileAndTheProblem) {
    const ToolsDoc d = tools_authored(24, 10, 0);
    const std::vector<uint8_t> good = encode_spt(d.doc);
    auto refused = [](const std::vector<uint8_t>& bytes, const std::string& why) {
        try {
            decode_spt(bytes, "tools.spt");
            ADD_FAILURE() << "read a file with " << why;
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::BadInput) << e.what();
            const std::string what = e.what();
            EXPECT_NE(what.find("tools.spt: byte "), std::string::npos) << what;
            EXPECT_NE(what.find(why), std::string::npos) << what;
        }
    };
    // Find the first lasso: its kind byte (1) follows the stroke's mode; its points follow the
    // rectangle. Strokes are located through a lasso's four vertices written as floats.
    const float first_x = 250;
    size_t at = 0;
    const uint32_t four_vertices = 4;
    for (size_t k = 8; k + 4 <= good.size(); ++k)
        if (std::memcmp(good.data() + k, &first_x, 4) == 0 && std::memcmp(good.data() + k - 4, &four_vertices, 4) == 0) {
            at = k;
            break;
        }
    ASSERT_GT(at, 0u);
    std::vector<uint8_t> nan_point = good;
    const float nan = NAN;
    std::memcpy(nan_point.data() + at, &nan, 4);
    refused(tools_resealed(nan_point), "recipe lasso point is not finite");
    std::vector<uint8_t> two_points = good;
    const uint32_t two = 2;
    std::memcpy(two_points.data() + at - 4, &two, 4);
    refused(tools_resealed(two_points), "recipe lasso has 2 points");
    std::vector<uint8_t> huge = good;
    const uint32_t many = 1u << 30;
    std::memcpy(huge.data() + at - 4, &many, 4);
    refused(tools_resealed(huge), "recipe lasso has 1073741824 points");
    // Its kind byte sits 4 + 4 + 16 bytes before the count (sizes, rectangle); an unknown kind.
    const size_t kind_at = at - 4 - 16 - 8 - 1;
    ASSERT_EQ(good[kind_at], 1u);
    std::vector<uint8_t> bad_kind = good;
    bad_kind[kind_at] = 9;
    refused(tools_resealed(bad_kind), "recipe stroke flags 0 0 0 9 are not valid");
    // The same bytes under a version 4 header: a kind there is refused, never read as a rectangle.
    std::vector<uint8_t> as_v4 = good;
    const uint32_t four = 4;
    std::memcpy(as_v4.data() + 8, &four, 4);
    refused(tools_resealed(as_v4), "are not valid");
    // A version 5 header on a file whose strokes are all rectangles: one encoding, version 3.
    // The linked stroke (kind 3, its pick 24 bytes) of the first step made a rectangle: cut its pick out.
    std::vector<uint8_t> no_new(good);
    for (size_t k = 0; k + 24 <= no_new.size(); ++k) {
        double pick[3];
        std::memcpy(pick, no_new.data() + k, 24);
        if (pick[0] == -2.6 && pick[1] == 0 && pick[2] == 0) {
            ASSERT_EQ(no_new[k - 16 - 8 - 1], 3u);
            no_new[k - 16 - 8 - 1] = 0;
            no_new.erase(no_new.begin() + long(k), no_new.begin() + long(k) + 24);
            break;
        }
    }
    ASSERT_EQ(no_new.size(), good.size() - 24);
    // Still other kinds later in the file: valid. Rewriting them all is the writer's rule, tested
    // by recipe_version_mismatch's message on a document of rectangles below.
    EXPECT_NO_THROW(decode_spt(tools_resealed(no_new)));
    EXPECT_EQ(encode_spt(decode_spt(tools_resealed(std::vector<uint8_t>(good)))), good);
}

TEST(SelectionTools, EveryNewStrokeKindReplaysOnAChangedMesh) {
    const ToolsDoc old = tools_authored(24, 10, 0);
    const ToolsDoc changed = tools_doc(37, 13, 0.02); // other vertices, other triangles
    const SampleSet& s = changed.doc.samples;
    ReplayReport report;
    const SamplingTree t = replay_recipe(old.doc.trees.front(), s, changed.mesh, &report);
    EXPECT_EQ(report.replayed, 3u);
    EXPECT_TRUE(report.skipped.empty()) << (report.skipped.empty() ? "" : report.skipped.front());
    EXPECT_EQ(t.validate(uint32_t(s.size())), "");
    EXPECT_EQ(t.recipe().size(), 3u);
    // Node 2: the left torus (grow then shrink of a whole part changes nothing).
    EXPECT_EQ(t.find(2)->samples, tools_where(s, [&](uint32_t i) { return s.position(i).x() < 0; }));
    // Node 6: the right torus's samples with window x >= 250 or within 15 pixels of x = 200.
    const auto six = tools_where(s, [&](uint32_t i) {
        const Eigen::Vector2d w = tools_window(s, i);
        return s.position(i).x() > 0 && (w.x() >= 250 || std::abs(w.x() - 200) <= 15);
    });
    ASSERT_NE(t.find(6), nullptr);
    EXPECT_EQ(t.find(6)->samples, six);
    // Node 14: node 7's samples below window y = 200 (the inverse of the upper lasso).
    ASSERT_NE(t.find(14), nullptr);
    for (uint32_t i : t.find(14)->samples) EXPECT_LE(tools_window(s, i).y(), 200.001);
    for (uint32_t i : t.find(15)->samples) EXPECT_GE(tools_window(s, i).y(), 199.999);
    // Replaying on the mesh it was made on gives the authored tree back, byte for byte.
    const SamplingTree same = replay_recipe(old.doc.trees.front(), old.doc.samples, old.mesh);
    SptDocument again = old.doc;
    again.trees.front() = same;
    EXPECT_EQ(encode_spt(again), encode_spt(old.doc));
}

TEST(SelectionTools, ThreadCountChangesNothingForLassoAndBrush) {
    // Lasso and brush filter their samples in the rectangle's chunks on the machine's threads: on
    // a mesh of several chunks the answer is the same, bit for bit, on one, two and three threads,
    // through and visible only, and the through lasso equals the even-odd rule sample by sample.
    const TriangleMesh torus = make_torus(2.4, 1.0, 400, 300); // 120,000 vertices
    const SampleSet s = test::vertex_samples(torus);
    const SamplingTree t("t", uint32_t(s.size()));
    const ViewProjection v = tools_view();
    const std::vector<Eigen::Vector2f> poly{{30.5f, 40.2f}, {370.1f, 60.7f}, {200.3f, 380.9f}, {190.2f, 150.4f}};
    RecipeStroke shapes[2] = {lasso(poly), brush({{40, 200}, {200, 260}, {360, 120}}, 35.5f)};
    for (RecipeStroke& stroke : shapes) {
        std::vector<uint32_t> through[3], visible[3];
        for (int n = 1; n <= 3; ++n) {
            const detail::PinnedThreads pin(n);
            stroke.visible_only = false;
            through[n - 1] = stroke_hits(s, t, 1, stroke, &torus);
            stroke.visible_only = true;
            visible[n - 1] = stroke_hits(s, t, 1, stroke, &torus);
        }
        ASSERT_GT(through[0].size(), 10000u);
        ASSERT_GT(through[0].size(), visible[0].size() + 1000);
        for (int n = 1; n < 3; ++n) {
            EXPECT_EQ(through[n], through[0]);
            EXPECT_EQ(visible[n], visible[0]);
        }
        if (stroke.kind != StrokeKind::Lasso) continue;
        std::vector<uint32_t> expected;
        for (uint32_t i = 0; i < s.size(); ++i) {
            const Eigen::Vector3f w = project_to_window(v, s.position(i));
            bool in = false;
            for (size_t a = 0, b = poly.size() - 1; a < poly.size(); b = a++)
                if ((poly[a].y() > w.y()) != (poly[b].y() > w.y()) &&
                    double(w.x()) < double(poly[b].x() - poly[a].x()) * double(w.y() - poly[a].y()) /
                                            double(poly[b].y() - poly[a].y()) + double(poly[a].x()))
                    in = !in;
            if (in) expected.push_back(i);
        }
        EXPECT_EQ(through[0], expected);
    }
}
