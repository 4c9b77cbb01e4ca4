// Tolerance-driven sampling: measure the largest uncovered depth on real meshes.
#include "meshgen.hpp"
#include "spt/convert.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <random>
#include <cmath>
#include <map>
#include <unordered_map>

using namespace spt;

namespace {

struct Sphere {
    Eigen::Vector3d c;
    double r;
};

// Distance from a point to the union of spheres (0 inside one), exact up to a cap and above the
// cap beyond it. Spheres are grouped by radius, a power of two per group, each group in a hash
// grid whose cells are as wide as its largest reach (radius + cap): every sphere within the cap
// of p then has its centre in p's cell or a neighbour, and a cell holds only a few spheres.
class SphereGrid {
public:
    SphereGrid(std::vector<Sphere> spheres, double cap) : spheres_(std::move(spheres)), cap_(cap) {
        for (uint32_t i = 0; i < spheres_.size(); ++i) {
            const int level = std::max(-1000, std::ilogb(std::max(spheres_[i].r, 1e-300)));
            auto& g = levels_[level];
            g.cell = std::ldexp(2.0, level) + cap_;
            g.cells[key(g, spheres_[i].c)].push_back(i);
        }
    }
    double uncovered_depth(const Eigen::Vector3d& p) const {
        double best = INFINITY;
        for (const auto& [level, g] : levels_) {
            const auto k = cell_of(g, p);
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dz = -1; dz <= 1; ++dz) {
                        auto it = g.cells.find(pack(k[0] + dx, k[1] + dy, k[2] + dz));
                        if (it == g.cells.end()) continue;
                        for (uint32_t i : it->second) {
                            best = std::min(best, (p - spheres_[i].c).norm() - spheres_[i].r);
                            if (best <= 0) return 0;
                        }
                    }
        }
        return best;
    }

private:
    struct Level {
        double cell = 0;
        std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
    };
    static std::array<int64_t, 3> cell_of(const Level& g, const Eigen::Vector3d& p) {
        return {int64_t(std::floor(p.x() / g.cell)), int64_t(std::floor(p.y() / g.cell)), int64_t(std::floor(p.z() / g.cell))};
    }
    static uint64_t pack(int64_t x, int64_t y, int64_t z) {
        return (uint64_t(x & 0x1fffff) << 42) | (uint64_t(y & 0x1fffff) << 21) | uint64_t(z & 0x1fffff);
    }
    static uint64_t key(const Level& g, const Eigen::Vector3d& p) {
        const auto k = cell_of(g, p);
        return pack(k[0], k[1], k[2]);
    }
    std::vector<Sphere> spheres_;
    double cap_;
    std::map<int, Level> levels_;
};

// Largest uncovered depth over random points on every triangle, plus corners and edge midpoints:
// exact while it is at most `cap`, and some value above `cap` when the true depth is.
double largest_uncovered_depth(const TriangleMesh& mesh, const SptDocument& doc, int points_per_face, double cap) {
    std::vector<Sphere> spheres;
    for (const TreeNode* n : doc.trees[0].active_nodes())
        for (uint32_t i : n->samples)
            spheres.push_back({doc.samples.origin +
                                   doc.samples.sphere_center(i, n->ss_radius).cast<double>(),
                               double(n->ss_radius)});
    const SphereGrid grid(spheres, cap);
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
        for (const auto& p : pts) worst = std::max(worst, grid.uncovered_depth(p));
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
            // float storage of points and radii: allow rounding far below eps.
            // Each object keeps its gaps within half the tolerance (two objects meet).
            const double allowed = *o.tolerance / 2 + 1e-5 * diag;
            const double measured = largest_uncovered_depth(c.mesh, doc, 20, allowed);
            EXPECT_LE(measured, allowed) << "measured " << measured;
        }
    }
}

TEST(Tolerance, DefaultSamplesFacesWhereVerticesLeaveHoles) {
    const TriangleMesh mesh = import_mesh(test::project_meshes() + "/cad_part.stl").mesh;
    ConvertStats st;
    const SptDocument doc = make_document(mesh, {}, &st);
    EXPECT_DOUBLE_EQ(st.automatic_tolerance, kAutoTolerance * mesh.diagonal());
    EXPECT_GT(st.face_samples, 0u);
    const double allowed = kAutoTolerance * mesh.diagonal() / 2 + 1e-5 * mesh.diagonal();
    EXPECT_LE(largest_uncovered_depth(mesh, doc, 10, allowed), allowed);
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
    const double deep = 0.01 * mesh.diagonal();
    EXPECT_GT(largest_uncovered_depth(mesh, doc, 30, deep), deep);
}
