// Degenerate meshes: zero-area and needle triangles, duplicate faces, a single triangle,
// non-manifold fans, open sheets, unreferenced and duplicated vertices. Each is named in the
// import report, converts, and queries at every level and mode without a crash or a NaN.
#include "hard_support.hpp"
#include "spt/ccd.hpp"
#include "spt/response.hpp"
#include "mesh/hard_shapes.hpp"
#include "query/brute_force.hpp"
#include <cmath>
#include <gtest/gtest.h>

namespace spt {
namespace {

using V = Eigen::Vector3d;

struct Case {
    const char* name;
    ImportedMesh imported;
    const char* warning; // a word of the warning the report must hold
};

ImportedMesh raw(const char* name, std::vector<V> p, std::vector<Triangle> t) {
    return prepare_mesh(name, std::move(p), std::move(t));
}

std::vector<Case> cases() {
    const TriangleMesh box = make_box({0.5, 0.5, 0.5}, 2);
    std::vector<Case> out;
    {   // a box with a zero-area face along one of its edges (three collinear points)
        auto p = box.positions;
        auto t = box.triangles;
        const auto mid = uint32_t(p.size());
        p.push_back(0.5 * (box.positions[t[0][0]] + box.positions[t[0][1]]));
        t.push_back({t[0][0], t[0][1], mid});
        out.push_back({"zero-area face", raw("zero-area face", p, t), "degenerate"});
    }
    out.push_back({"needle", raw("needle", {V(0, 0, 0), V(1, 0, 0), V(0.5, 1e-8, 0), V(0.5, 0.5, 0.5)},
                                 {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}),
                   "needle"});
    {   // every face of a box twice, the second time wound the other way
        auto t = box.triangles;
        for (const auto& f : box.triangles) t.push_back({f[0], f[2], f[1]});
        out.push_back({"duplicate faces", raw("duplicate faces", box.positions, t), "duplicate"});
    }
    out.push_back({"single triangle", raw("single triangle", {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, {{0, 1, 2}}), "open"});
    out.push_back({"non-manifold fan", raw("fan", make_fan(5).positions, make_fan(5).triangles), "non-manifold"});
    out.push_back({"open sheet", raw("sheet", make_sheet(1.0, 4).positions, make_sheet(1.0, 4).triangles), "open"});
    {   // a box soup: every face its own vertices (welded by import), plus vertices no face uses
        std::vector<V> p;
        std::vector<Triangle> t;
        for (const auto& f : box.triangles) {
            const auto i = uint32_t(p.size());
            for (uint32_t v : f) p.push_back(box.positions[v]);
            t.push_back({i, i + 1, i + 2});
        }
        p.push_back(V(0.6, 0.6, 0.6)), p.push_back(V(-0.6, 0, 0.2));
        out.push_back({"unreferenced and duplicated vertices", raw("soup", p, t), "used by no face"});
    }
    return out;
}

bool finite(const QueryResult& r) {
    return std::isfinite(r.deepest.depth) && r.deepest.point.allFinite() && r.deepest.normal.allFinite();
}

TEST(DegenerateMeshes, EachIsNamedInTheImportReport) {
    for (const Case& c : cases()) {
        const ImportReport& r = c.imported.report;
        bool named = false;
        for (const std::string& w : r.warnings) named = named || w.find(c.warning) != std::string::npos;
        EXPECT_TRUE(named) << c.name << ": no warning with '" << c.warning << "'";
    }
    const auto all = cases();
    EXPECT_EQ(all[0].imported.report.degenerate_faces, 1u);
    EXPECT_EQ(all[1].imported.report.needle_faces, 1u);
    EXPECT_EQ(all[2].imported.report.duplicate_faces, all[2].imported.report.faces / 2);
    EXPECT_EQ(all[6].imported.report.unreferenced_vertices, 2u);
    EXPECT_EQ(all[6].imported.report.vertices, make_box({0.5, 0.5, 0.5}, 2).positions.size() + 2);
    EXPECT_FALSE(all[6].imported.report.fixes.empty()) << "welding is reported";
}

// Each converts, and at random poses against a box every level and mode answers with finite
// output, the exact level equals brute force over every triangle pair, backtrack and continuous
// detection return finite distances and times.
TEST(DegenerateMeshes, ConvertAndQueryAtEveryLevelWithoutNaN) {
    const auto box = hard::make_object(make_box({0.3, 0.2, 0.25}, 2));
    for (const Case& c : cases()) {
        const auto o = hard::make_object(c.imported.mesh);
        for (size_t i = 0; i < o->doc.samples.size(); ++i) {
            ASSERT_TRUE(o->doc.samples.position(i).allFinite()) << c.name;
            ASSERT_TRUE(std::isfinite(o->doc.samples.max_radius[i])) << c.name;
        }
        const double diag = c.imported.mesh.diagonal();
        const V centre = 0.5 * (c.imported.mesh.bounds().first + c.imported.mesh.bounds().second);
        std::mt19937 rng(41);
        std::uniform_real_distribution<double> u(-0.6 * diag, 0.6 * diag);
        QueryScratch s;
        int collide = 0;
        for (int k = 0; k < 8; ++k) {
            const Pose p{hard::random_rotation(rng), centre + V(u(rng), u(rng), u(rng))};
            for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact})
                for (QueryMode mode : {QueryMode::Any, QueryMode::All, QueryMode::Deepest}) {
                    QueryOptions q;
                    q.level = level, q.mode = mode;
                    const QueryResult r = collide_relative(o->model, box->model, p, q, s);
                    ASSERT_TRUE(finite(r)) << c.name << " level " << int(level);
                    // Triangle pairs are few; sphere pairs of the default conversion too many to pair off.
                    if (level == QueryLevel::Exact) {
                        EXPECT_EQ(r.collide, collide_brute_force(o->model, box->model, p, q, s).collide)
                            << c.name << " mode " << int(mode) << " pose " << k;
                    }
                    collide += level == QueryLevel::Exact && mode == QueryMode::Any && r.collide;
                    if (mode != QueryMode::Any) continue;
                    const BacktrackResult b =
                        backtrack_relative(o->model, box->model, p, hard::random_unit(rng), q, BacktrackRule::Exact, s);
                    ASSERT_TRUE(std::isfinite(b.distance) && b.distance >= 0) << c.name << " level " << int(level);
                }
            const Pose from{p.rotation, p.translation + 2 * diag * hard::random_unit(rng)};
            const CcdResult t = first_contact(o->model, box->model, from, p, {}, s);
            ASSERT_TRUE(std::isfinite(t.toi) && t.toi >= 0 && t.toi <= 1) << c.name;
        }
        EXPECT_GT(collide, 0) << c.name << ": no pose reached it";
    }
}

} // namespace
} // namespace spt

namespace spt {
namespace {

TEST(DegenerateMeshes, ABoxExportedWithEveryFaceTwiceIsTheClosedSolidBox) {
    // Every edge of such a box is used four times: counted as non-manifold, the box was an open
    // shell of two-sided spheres, 35 times the samples of the box and with no inside.
    const TriangleMesh box = make_box({0.5, 0.5, 0.5}, 2);
    const ImportedMesh once = prepare_mesh("once", box.positions, box.triangles);
    const auto single = hard::make_object(once.mesh);
    const TriangleMesh small_box = make_box({0.1, 0.1, 0.1}, 2);
    const auto small = hard::make_object(prepare_mesh("small", small_box.positions, small_box.triangles).mesh);
    for (bool reversed : {true, false}) {
        std::vector<Triangle> t = box.triangles;
        for (const Triangle& f : box.triangles) t.push_back(reversed ? Triangle{f[0], f[2], f[1]} : f);
        for (int threads : {1, 2}) {
            ImportOptions options;
            options.threads = threads;
            const ImportedMesh twice = prepare_mesh("twice", box.positions, t, options);
            const ImportReport& r = twice.report;
            const std::string what = std::string(reversed ? "reversed" : "same winding") + ", threads " + std::to_string(threads);
            EXPECT_EQ(r.duplicate_faces, box.triangles.size()) << what;
            EXPECT_TRUE(r.closed) << what;
            EXPECT_EQ(r.nonmanifold_edges, 0u) << what;
            EXPECT_EQ(r.components, 1u) << what;
            EXPECT_EQ(r.flipped_faces, 0u) << what;
            EXPECT_EQ(std::count(twice.mesh.on_open_part.begin(), twice.mesh.on_open_part.end(), 1), 0) << what;
            EXPECT_EQ(twice.mesh.triangles.size(), t.size()) << what << ": the file's faces are all kept";
            const auto doubled = hard::make_object(twice.mesh);
            ASSERT_EQ(doubled->doc.samples.size(), single->doc.samples.size()) << what;
            for (size_t i = 0; i < single->doc.samples.size(); ++i)
                ASSERT_EQ(doubled->doc.samples.position(i), single->doc.samples.position(i)) << what << " sample " << i;
            // A solid: a small box wholly inside collides at every level, as with the box itself.
            const Pose inside{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.1, -0.05, 0.08)};
            QueryScratch s;
            for (QueryLevel level : hard::kLevels) {
                QueryOptions q;
                q.level = level;
                EXPECT_TRUE(collide_relative(doubled->model, small->model, inside, q, s).collide)
                    << what << " level " << int(level);
            }
        }
    }
}

} // namespace
} // namespace spt
