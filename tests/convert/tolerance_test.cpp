// Tolerance-driven sampling: measure the largest uncovered depth on real meshes.
#include "meshgen.hpp"
#include "spt/convert.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <random>
#include <unordered_map>

using namespace spt;

namespace {

struct Sphere {
    Eigen::Vector3d c;
    double r;
};

// Distance from p to the union of spheres (0 when inside one), found through a grid.
class SphereGrid {
public:
    SphereGrid(std::vector<Sphere> spheres, double cell) : spheres_(std::move(spheres)), cell_(cell) {
        for (uint32_t i = 0; i < spheres_.size(); ++i) grid_[key(spheres_[i].c)].push_back(i);
    }
    double uncovered_depth(const Eigen::Vector3d& p, int reach) const {
        double best = INFINITY;
        const auto k = cell_of(p);
        for (int dx = -reach; dx <= reach; ++dx)
            for (int dy = -reach; dy <= reach; ++dy)
                for (int dz = -reach; dz <= reach; ++dz) {
                    auto it = grid_.find(pack(k[0] + dx, k[1] + dy, k[2] + dz));
                    if (it == grid_.end()) continue;
                    for (uint32_t i : it->second)
                        best = std::min(best, (p - spheres_[i].c).norm() - spheres_[i].r);
                }
        return std::max(0.0, best);
    }

private:
    std::array<int64_t, 3> cell_of(const Eigen::Vector3d& p) const {
        return {int64_t(std::floor(p.x() / cell_)), int64_t(std::floor(p.y() / cell_)), int64_t(std::floor(p.z() / cell_))};
    }
    static uint64_t pack(int64_t x, int64_t y, int64_t z) {
        return (uint64_t(x & 0x1fffff) << 42) | (uint64_t(y & 0x1fffff) << 21) | uint64_t(z & 0x1fffff);
    }
    uint64_t key(const Eigen::Vector3d& p) const {
        const auto k = cell_of(p);
        return pack(k[0], k[1], k[2]);
    }
    std::vector<Sphere> spheres_;
    double cell_;
    std::unordered_map<uint64_t, std::vector<uint32_t>> grid_;
};

// Largest uncovered depth over random points on every triangle, plus corners and edge midpoints.
double largest_uncovered_depth(const TriangleMesh& mesh, const SptDocument& doc, int points_per_face) {
    std::vector<Sphere> spheres;
    double max_r = 0;
    for (const TreeNode* n : doc.trees[0].active_nodes())
        for (uint32_t i : n->samples) {
            spheres.push_back({doc.samples.origin +
                                   doc.samples.sphere_centre(i, n->ss_radius).cast<double>(),
                               double(n->ss_radius)});
            max_r = std::max(max_r, double(n->ss_radius));
        }
    const SphereGrid grid(spheres, 2 * max_r);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    double worst = 0;
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        std::vector<Eigen::Vector3d> pts{a, b, c, (a + b) / 2, (b + c) / 2, (c + a) / 2, (a + b + c) / 3};
        for (int k = 0; k < points_per_face; ++k) {
            double x = u(rng), y = u(rng);
            if (x + y > 1) x = 1 - x, y = 1 - y;
            pts.push_back(a + x * (b - a) + y * (c - a));
        }
        for (const auto& p : pts) worst = std::max(worst, grid.uncovered_depth(p, 2));
    }
    return worst;
}

} // namespace

TEST(Tolerance, LargestUncoveredDepthStaysWithinEpsilon) {
    struct Case {
        std::string name;
        TriangleMesh mesh;
    };
    std::vector<Case> cases;
    cases.push_back({"cad_part", import_mesh(test::project_meshes() + "/cad_part.stl").mesh});
    cases.push_back({"figure", import_mesh(test::project_meshes() + "/figure.obj").mesh});
    cases.push_back({"spider", import_mesh(test::assimp_models() + "/OBJ/spider.obj").mesh});
    for (const auto& c : cases) {
        const double diag = c.mesh.diagonal();
        for (double rel : {0.01, 0.003}) {
            SCOPED_TRACE(c.name + " eps " + std::to_string(rel) + " x diagonal");
            ConvertOptions o;
            o.tolerance = rel * diag;
            ConvertStats st;
            const SptDocument doc = make_document(c.mesh, o, &st);
            EXPECT_GT(st.face_samples, 0u);
            EXPECT_LE(st.worst_predicted_gap, *o.tolerance / 2 * (1 + 1e-6));
            const double measured = largest_uncovered_depth(c.mesh, doc, 20);
            // float storage of points and radii: allow rounding far below eps.
            // Each object keeps its gaps within half the tolerance (two objects meet).
            EXPECT_LE(measured, *o.tolerance / 2 + 1e-5 * diag) << "measured " << measured;
        }
    }
}

TEST(Tolerance, DefaultSamplesFacesWhereVerticesLeaveHoles) {
    const TriangleMesh mesh = import_mesh(test::project_meshes() + "/cad_part.stl").mesh;
    ConvertStats st;
    const SptDocument doc = make_document(mesh, {}, &st);
    EXPECT_DOUBLE_EQ(st.automatic_tolerance, kAutoTolerance * mesh.diagonal());
    EXPECT_GT(st.face_samples, 0u);
    EXPECT_LE(largest_uncovered_depth(mesh, doc, 10), kAutoTolerance * mesh.diagonal() / 2 + 1e-5 * mesh.diagonal());
}

TEST(Tolerance, FineMeshKeepsVertexSamplesOnly) {
    const ImportedMesh m = meshgen::prepare(meshgen::torus(1, 0.4, 200, 100), "fine torus");
    ConvertStats st;
    make_document(m.mesh, {}, &st);
    EXPECT_EQ(st.automatic_tolerance, 0);
    EXPECT_EQ(st.face_samples, 0u);
}

TEST(Tolerance, VerticesOnlyLeaveDeepGapsOnLargeFlatFaces) {
    // The reason tolerance sampling exists: two triangles per face of a slab.
    const TriangleMesh mesh = import_mesh(test::project_meshes() + "/cad_part.stl").mesh;
    ConvertOptions vertices_only;
    vertices_only.auto_tolerance = false;
    const SptDocument doc = make_document(mesh, vertices_only);
    EXPECT_GT(largest_uncovered_depth(mesh, doc, 30), 0.01 * mesh.diagonal());
}
