// Rectangle selection: through and visible-only against analytic answers, and the three modes.
#include "mesh/shapes.hpp"
#include "spt/selection.hpp"
#include "base/parallel.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <cstring>
#include <random>

using namespace spt;

namespace {

// Orthographic view of the X-Y plane looking down -Z: object x, y in [-1, 1] fill a
// 200x200 framebuffer, window x = (x + 1) * 100. Eye depth = 10 - z.
ViewProjection front_view() {
    ViewProjection v;
    v.view = Eigen::Matrix4f::Identity();
    v.view(2, 3) = -10;
    v.projection = Eigen::Matrix4f::Identity();
    v.projection(2, 2) = -0.1f;
    v.width = v.height = 200;
    return v;
}

SampleSet grid_samples(int n) {
    SampleSet s;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            s.add({-0.95f + 1.9f * float(i) / float(n - 1), -0.95f + 1.9f * float(j) / float(n - 1), 0}, {0, 0, 1},
                  uint32_t(i * n + j), 0.1f);
    return s;
}

} // namespace

TEST(Selection, ThroughSelectsExactlyThePointsInsideTheRectangle) {
    const SampleSet s = grid_samples(21);
    SamplingTree t("t", uint32_t(s.size()));
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0, 200);
    for (int k = 0; k < 50; ++k) {
        const PixelRect r{u(rng), u(rng), u(rng), u(rng)};
        std::vector<uint32_t> expected;
        for (uint32_t i = 0; i < s.size(); ++i) {
            // Inverse of the view: object x in [x0/100 - 1, x1/100 - 1].
            const double x = (s.points[i].x() + 1.0) * 100.0, y = (s.points[i].y() + 1.0) * 100.0;
            if (x >= std::min(r.x0, r.x1) && x <= std::max(r.x0, r.x1) && y >= std::min(r.y0, r.y1) &&
                y <= std::max(r.y0, r.y1))
                expected.push_back(i);
        }
        // Points exactly on a border may round either way in float; the rectangles are random.
        EXPECT_EQ(samples_in_rect(s, t, 1, front_view(), r), expected) << k;
    }
}

TEST(Selection, FarFromTheOriginSelectsWhatTheSameGridSelectsAtTheOrigin) {
    // The same grid 10^6 away (a local origin there, as imported meshes far out have) seen by
    // the same view moved with it: the same window points, so the same samples, rect by rect.
    // Rounding object coordinates to float before the view's translation (1/16 of a unit at
    // 10^6, six pixels here) would move them.
    const SampleSet near = grid_samples(41);
    SampleSet far = near;
    far.origin = {1e6, -2e6, 5e5};
    SamplingTree t("t", uint32_t(near.size()));
    ViewProjection moved = front_view();
    moved.view(0, 3) = -1e6f, moved.view(1, 3) = 2e6f, moved.view(2, 3) = -5e5f - 10.0f; // exact in float
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0, 200);
    size_t selected = 0;
    for (int k = 0; k < 50; ++k) {
        const PixelRect r{u(rng), u(rng), u(rng), u(rng)};
        const std::vector<uint32_t> expected = samples_in_rect(near, t, 1, front_view(), r);
        EXPECT_EQ(samples_in_rect(far, t, 1, moved, r), expected) << k;
        selected += expected.size();
    }
    EXPECT_GT(selected, 1000u);
}

TEST(Selection, VisibleOnlyComparesWithTheFarthestOfTheNinePixelsAroundASample) {
    // A hand-made depth map with holes (+infinity) and samples over it and past its edges,
    // against the rule read pixel by pixel.
    ViewProjection v = front_view();
    v.width = 30, v.height = 20;
    DepthMap depth;
    depth.width = 30, depth.height = 20;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0, 1);
    for (int i = 0; i < 600; ++i) depth.depth.push_back(u(rng) < 0.1f ? INFINITY : 8.5f + 2.0f * u(rng));
    SampleSet s;
    for (uint32_t i = 0; i < 3000; ++i)
        s.add({2.4f * u(rng) - 1.2f, 2.4f * u(rng) - 1.2f, 2.0f * u(rng) - 1.0f}, {0, 0, 1}, i, 0.1f);
    SamplingTree t("t", uint32_t(s.size()));
    const float tolerance = 0.05f;
    size_t visible = 0, hidden = 0;
    for (const PixelRect r : {PixelRect{-5, -5, 35, 25}, PixelRect{0.5f, 0.5f, 29.5f, 19.5f}, PixelRect{12.3f, 3.7f, 4.1f, 17.2f},
                              PixelRect{28.2f, 18.9f, 40, 30}}) {
        std::vector<uint32_t> expected;
        for (uint32_t i = 0; i < s.size(); ++i) {
            const Eigen::Vector3f w = project_to_window(v, s.position(i));
            if (w.x() < std::min(r.x0, r.x1) || w.x() > std::max(r.x0, r.x1) || w.y() < std::min(r.y0, r.y1) ||
                w.y() > std::max(r.y0, r.y1))
                continue;
            const int px = int(std::floor(w.x())), py = int(std::floor(w.y()));
            float farthest = -INFINITY;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) farthest = std::max(farthest, depth.at(px + dx, py + dy));
            if (w.z() <= farthest + tolerance) expected.push_back(i);
            else ++hidden;
        }
        visible += expected.size();
        EXPECT_EQ(visible_samples_in_rect(s, t, 1, v, r, depth, tolerance), expected);
    }
    EXPECT_GT(visible, 100u);
    EXPECT_GT(hidden, 100u);
}

TEST(Selection, OnlyTheCurrentNodesSamplesAndTheLocalOriginCount) {
    SampleSet s = grid_samples(5);
    s.origin = {0.5, 0, 0}; // every point moves right by half a unit: 50 pixels
    SamplingTree t("t", uint32_t(s.size()));
    ASSERT_TRUE(t.split(1, {0, 1, 2, 3, 4}, s)); // the column at local x = -0.95
    const PixelRect all{0, 0, 200, 200};
    EXPECT_EQ(samples_in_rect(s, t, 2, front_view(), all), (std::vector<uint32_t>{0, 1, 2, 3, 4}));
    // Object x of the column is -0.45: window x 55; a rectangle left of it holds nothing.
    EXPECT_TRUE(samples_in_rect(s, t, 1, front_view(), {0, 0, 54, 200}).empty());
    EXPECT_EQ(samples_in_rect(s, t, 1, front_view(), {54, 0, 56, 200}).size(), 5u);
    EXPECT_EQ(samples_below(t, 3).size(), 20u);
    EXPECT_TRUE(samples_below(t, 7).empty());
}

TEST(Selection, PerspectiveIgnoresPointsBehindTheEye) {
    SampleSet s;
    s.add({0, 0, -5}, {0, 0, 1}, 0, 0.1f); // in front of an eye at the origin looking down -Z
    s.add({0, 0, 5}, {0, 0, 1}, 1, 0.1f);  // behind it: would project mirrored to the same pixel
    SamplingTree t("t", 2);
    ViewProjection v;
    v.perspective = true;
    const float n = 0.1f, f = 100;
    v.projection = Eigen::Matrix4f::Zero();
    v.projection(0, 0) = v.projection(1, 1) = 1;
    v.projection(2, 2) = -(f + n) / (f - n);
    v.projection(2, 3) = -2 * f * n / (f - n);
    v.projection(3, 2) = -1;
    v.width = v.height = 100;
    EXPECT_EQ(samples_in_rect(s, t, 1, v, {40, 40, 60, 60}), (std::vector<uint32_t>{0}));
}

TEST(Selection, VisibleOnlyKeepsTheNearFaceOfABox) {
    const TriangleMesh box = make_box({0.5, 0.5, 0.5}, 6);
    const SampleSet s = test::vertex_samples(box);
    SamplingTree t("t", uint32_t(s.size()));
    const ViewProjection v = front_view();
    const DepthMap depth = render_depth(box, v);
    // The box's front face z = 0.5 covers window [50, 150]^2 at eye depth 9.5.
    EXPECT_NEAR(depth.at(100, 100), 9.5f, 1e-4f);
    EXPECT_EQ(depth.at(10, 10), INFINITY);
    const PixelRect inner{60, 60, 140, 140};
    std::vector<uint32_t> front, both;
    for (uint32_t i = 0; i < s.size(); ++i) {
        const Eigen::Vector3d p = s.position(i);
        const double x = (p.x() + 1) * 100, y = (p.y() + 1) * 100;
        if (x < 60 || x > 140 || y < 60 || y > 140) continue;
        both.push_back(i);
        if (p.z() > 0.49) front.push_back(i);
    }
    ASSERT_FALSE(front.empty());
    ASSERT_GT(both.size(), front.size());
    EXPECT_EQ(samples_in_rect(s, t, 1, v, inner), both);
    EXPECT_EQ(visible_samples_in_rect(s, t, 1, v, inner, depth, 0.01f), front);
}

TEST(Selection, DepthMapOfAWindowEqualsTheFullMapWhereTheSelectionReadsIt) {
    const TriangleMesh torus = make_torus(0.6, 0.25, 40, 24);
    const SampleSet s = test::vertex_samples(torus);
    SamplingTree t("t", uint32_t(s.size()));
    const ViewProjection v = front_view();
    const DepthMap full = render_depth(torus, v);
    // Reversed and fractional corners, and one rectangle reaching past the view's edges.
    for (const PixelRect r : {PixelRect{130.6f, 120.2f, 41.3f, 60.9f}, PixelRect{-20, 150.5f, 90.5f, 260}}) {
        const DepthMap part = render_depth(torus, v, r);
        const int x0 = int(std::floor(std::min(r.x0, r.x1))) - 1, x1 = int(std::floor(std::max(r.x0, r.x1))) + 1;
        const int y0 = int(std::floor(std::min(r.y0, r.y1))) - 1, y1 = int(std::floor(std::max(r.y0, r.y1))) + 1;
        size_t covered = 0;
        for (int y = 0; y < v.height; ++y)
            for (int x = 0; x < v.width; ++x) {
                const bool read = x >= x0 && x <= x1 && y >= y0 && y <= y1;
                EXPECT_EQ(part.at(x, y), read ? full.at(x, y) : INFINITY) << x << ", " << y;
                covered += read && std::isfinite(full.at(x, y));
            }
        EXPECT_GT(covered, 100u);
        EXPECT_EQ(visible_samples_in_rect(s, t, 1, v, r, part, 0.01f), visible_samples_in_rect(s, t, 1, v, r, full, 0.01f));
    }
}

TEST(Selection, ThreadCountChangesNothingOnAMeshOfManyChunks) {
    // Through, visible only and the depth map split their samples, vertices and triangles
    // among threads in chunks: on a mesh of several chunks each gives the same answer, bit for
    // bit, on one, two and three threads, in an orthographic and a perspective view.
    const TriangleMesh torus = make_torus(0.6, 0.25, 400, 300); // 120,000 vertices, 240,000 triangles
    const SampleSet s = test::vertex_samples(torus);
    SamplingTree t("t", uint32_t(s.size()));
    ViewProjection persp = front_view();
    persp.perspective = true;
    persp.projection = Eigen::Matrix4f::Zero();
    persp.projection(0, 0) = persp.projection(1, 1) = 4;
    persp.projection(2, 2) = -1.02f, persp.projection(2, 3) = -0.2f, persp.projection(3, 2) = -1;
    for (const ViewProjection& v : {front_view(), persp}) {
        const PixelRect r{30.5f, 20.2f, 150.7f, 170.1f};
        std::vector<uint32_t> through[3], visible[3];
        std::vector<float> depth[3];
        for (int n = 1; n <= 3; ++n) {
            const detail::PinnedThreads pin(n);
            through[n - 1] = samples_in_rect(s, t, 1, v, r);
            const DepthMap map = render_depth(torus, v, r);
            depth[n - 1] = map.depth;
            visible[n - 1] = visible_samples_in_rect(s, t, 1, v, r, map, 0.01f);
        }
        ASSERT_GT(through[0].size(), 20000u);
        ASSERT_GT(through[0].size(), visible[0].size() + 1000);
        // Against the rule applied sample by sample, and the window's depths against the
        // whole view's (drawn over other pixel ranges, so merged at other offsets).
        std::vector<uint32_t> expected;
        for (uint32_t i = 0; i < s.size(); ++i) {
            const Eigen::Vector3f w = project_to_window(v, s.position(i));
            if ((!v.perspective || w.z() > 0) && w.x() >= r.x0 && w.x() <= r.x1 && w.y() >= r.y0 && w.y() <= r.y1)
                expected.push_back(i);
        }
        EXPECT_EQ(through[0], expected);
        const DepthMap whole = render_depth(torus, v);
        size_t covered = 0;
        for (int y = 20; y <= 171; ++y)
            for (int x = 29; x <= 151; ++x) {
                const float d = depth[0][size_t(y) * size_t(v.width) + size_t(x)];
                EXPECT_EQ(d, whole.at(x, y)) << x << ", " << y;
                covered += std::isfinite(d);
            }
        EXPECT_GT(covered, 2000u);
        for (int n = 1; n < 3; ++n) {
            EXPECT_EQ(through[n], through[0]);
            EXPECT_EQ(visible[n], visible[0]);
            EXPECT_EQ(0, std::memcmp(depth[n].data(), depth[0].data(), depth[0].size() * sizeof(float)));
        }
    }
}

TEST(Selection, ModesReplaceAddSubtract) {
    const std::vector<uint32_t> cur{1, 3, 5}, hits{3, 4};
    EXPECT_EQ(combine_selection(cur, hits, SelectionMode::Replace), hits);
    EXPECT_EQ(combine_selection(cur, hits, SelectionMode::Add), (std::vector<uint32_t>{1, 3, 4, 5}));
    EXPECT_EQ(combine_selection(cur, hits, SelectionMode::Subtract), (std::vector<uint32_t>{1, 5}));
}
