// Meshes with hard features made in code: thin parts, open and non-manifold surfaces, soups.
#include "mesh/hard_shapes.hpp"
#include "mesh/shapes.hpp"
#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace spt {
namespace {

// Raw triangles gathered from several parts, prepared (welded, wound) at the end.
struct Parts {
    std::vector<Eigen::Vector3d> p;
    std::vector<Triangle> t;
    void add(const TriangleMesh& m, const Eigen::Vector3d& shift, const Eigen::Matrix3d& turn = Eigen::Matrix3d::Identity()) {
        const auto base = uint32_t(p.size());
        for (const auto& q : m.positions) p.push_back(turn * (q + shift));
        for (const auto& tri : m.triangles) t.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
    }
    uint32_t vertex(const Eigen::Vector3d& q) {
        p.push_back(q);
        return uint32_t(p.size() - 1);
    }
    void quad(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, const Eigen::Vector3d& d) {
        const uint32_t i = vertex(a), j = vertex(b), k = vertex(c), l = vertex(d);
        t.push_back({i, j, k}), t.push_back({i, k, l});
    }
    TriangleMesh finish(const char* name) { return prepare_mesh(name, std::move(p), std::move(t)).mesh; }
};

} // namespace

TriangleMesh make_tetrahedron(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                              const Eigen::Vector3d& d) {
    return prepare_mesh("tetrahedron", {a, b, c, d}, {{{0, 1, 2}}, {{0, 3, 1}}, {{1, 3, 2}}, {{2, 3, 0}}}).mesh;
}

TriangleMesh make_wedge(double w, double h, double l) {
    std::vector<Eigen::Vector3d> p;
    for (double y : {-l, l}) {
        p.emplace_back(-w, y, 0);
        p.emplace_back(w, y, 0);
        p.emplace_back(0, y, h);
    }
    // Caps, then the three sides (base, two flanks) as quads; import winds them outward.
    std::vector<Triangle> t = {{0, 1, 2}, {3, 5, 4}};
    for (uint32_t k = 0; k < 3; ++k) {
        const uint32_t a = k, b = (k + 1) % 3;
        t.push_back({a, b + 3, b});
        t.push_back({a, a + 3, b + 3});
    }
    return prepare_mesh("wedge", std::move(p), std::move(t)).mesh;
}

TriangleMesh make_plate_with_fin() {
    Parts parts;
    parts.add(make_box({1, 1, 0.1}, 4), Eigen::Vector3d::Zero());
    parts.add(make_box({0.01, 0.8, 0.5}, 4), Eigen::Vector3d(0, 0, 0.55));
    return parts.finish("plate with fin");
}

TriangleMesh make_rotor(int blades, double thickness) {
    Parts parts;
    parts.add(make_box({0.15, 0.15, 0.15}, 2), Eigen::Vector3d::Zero());
    for (int k = 0; k < blades; ++k)
        parts.add(make_box({0.5, 0.1, 0.5 * thickness}, 2), Eigen::Vector3d(0.6, 0, 0),
                  Eigen::AngleAxisd(2 * kPi * k / blades, Eigen::Vector3d::UnitY()).toRotationMatrix());
    return parts.finish("rotor");
}

TriangleMesh make_body_with_ears() {
    Parts parts;
    parts.add(make_box({0.5, 0.5, 0.5}, 3), Eigen::Vector3d::Zero());
    for (double side : {-1.0, 1.0}) parts.add(make_box({0.25, 0.01, 0.2}, 3), Eigen::Vector3d(side * 0.7, 0, 0.1));
    return parts.finish("body with ears");
}

TriangleMesh make_open_box(const Eigen::Vector3d& half, int n) {
    const TriangleMesh closed = make_box(half, n);
    std::vector<Triangle> t;
    for (const auto& tri : closed.triangles) {
        bool top = true;
        for (uint32_t v : tri) top = top && closed.positions[v].z() > half.z() - 1e-9 * half.norm();
        if (!top) t.push_back(tri);
    }
    return prepare_mesh("open box", closed.positions, std::move(t)).mesh;
}

TriangleMesh make_open_tube(double r, double l, int segments) {
    std::vector<Eigen::Vector3d> p;
    std::vector<Triangle> t;
    for (int i = 0; i < segments; ++i) {
        const double a = 2 * kPi * i / segments;
        p.emplace_back(r * std::cos(a), r * std::sin(a), -l / 2);
        p.emplace_back(r * std::cos(a), r * std::sin(a), l / 2);
    }
    for (int i = 0; i < segments; ++i) {
        const auto a = uint32_t(2 * i), b = uint32_t(2 * ((i + 1) % segments));
        t.push_back({a, b, b + 1});
        t.push_back({a, b + 1, a + 1});
    }
    return prepare_mesh("open tube", std::move(p), std::move(t)).mesh;
}

TriangleMesh make_fan(int blades) {
    std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {0, 0, 1}};
    std::vector<Triangle> t;
    for (int k = 0; k < blades; ++k) {
        const double a = 2 * kPi * k / blades;
        const Eigen::Vector3d out(0.5 * std::cos(a), 0.5 * std::sin(a), 0);
        const auto i = uint32_t(p.size());
        p.push_back(out);
        p.push_back(out + Eigen::Vector3d::UnitZ());
        t.push_back({0, i, i + 1}); // the blade's triangle on the shared edge 0-1 is the other one
        t.push_back({0, i + 1, 1});
    }
    return prepare_mesh("fan", std::move(p), std::move(t)).mesh;
}

TriangleMesh make_triangle_soup(int count, double size, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1 + size, 1 - size);
    std::normal_distribution<double> n;
    std::vector<Eigen::Vector3d> p;
    std::vector<Triangle> t;
    // One draw a statement (z first, as the soups were made before): the order of a call's
    // arguments is the compiler's choice, and a seed must give the same soup from every build.
    auto draw = [&rng](auto& d) {
        const double z = d(rng), y = d(rng), x = d(rng);
        return Eigen::Vector3d(x, y, z);
    };
    for (int k = 0; k < count; ++k) {
        const Eigen::Vector3d c = draw(u);
        const auto i = uint32_t(p.size());
        for (int j = 0; j < 3; ++j) p.push_back(c + size * draw(n).normalized());
        t.push_back({i, i + 1, i + 2});
    }
    return prepare_mesh("triangle soup", std::move(p), std::move(t)).mesh;
}

TriangleMesh make_gapped_box(double half, double gap) {
    Parts parts;
    const double h = half, g = half - gap;
    using V = Eigen::Vector3d;
    parts.quad(V(-h, -h, -h), V(-h, h, -h), V(h, h, -h), V(h, -h, -h)); // bottom
    parts.quad(V(-h, -h, -h), V(h, -h, -h), V(h, -h, h), V(-h, -h, h));
    parts.quad(V(h, -h, -h), V(h, h, -h), V(h, h, h), V(h, -h, h));
    parts.quad(V(h, h, -h), V(-h, h, -h), V(-h, h, h), V(h, h, h));
    parts.quad(V(-h, h, -h), V(-h, -h, -h), V(-h, -h, h), V(-h, h, h));
    parts.quad(V(-g, -g, h), V(g, -g, h), V(g, g, h), V(-g, g, h)); // top, short of the sides by `gap`
    return parts.finish("gapped box");
}

} // namespace spt
