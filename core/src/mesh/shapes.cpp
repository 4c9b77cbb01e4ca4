// Meshes made in code: torus, box, sheet, bracket; scaling into the unit cube.
#include "mesh/shapes.hpp"
#include <cmath>

namespace spt {
namespace {

TriangleMesh finish(const char* name, std::vector<Eigen::Vector3d> p, std::vector<Triangle> t) {
    return prepare_mesh(name, std::move(p), std::move(t)).mesh;
}

// Ear clipping of a simple counter-clockwise polygon.
std::vector<Triangle> triangulate(const std::vector<Eigen::Vector2d>& poly) {
    std::vector<uint32_t> idx(poly.size());
    for (uint32_t i = 0; i < idx.size(); ++i) idx[i] = i;
    auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
        return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    };
    std::vector<Triangle> out;
    while (idx.size() > 3) {
        bool clipped = false;
        for (size_t k = 0; k < idx.size() && !clipped; ++k) {
            const uint32_t a = idx[(k + idx.size() - 1) % idx.size()], b = idx[k], c = idx[(k + 1) % idx.size()];
            if (cross(poly[a], poly[b], poly[c]) <= 0) continue;
            bool empty = true;
            for (uint32_t v : idx) {
                if (v == a || v == b || v == c) continue;
                if (cross(poly[a], poly[b], poly[v]) >= 0 && cross(poly[b], poly[c], poly[v]) >= 0 &&
                    cross(poly[c], poly[a], poly[v]) >= 0)
                    empty = false;
            }
            if (!empty) continue;
            out.push_back({a, b, c});
            idx.erase(idx.begin() + long(k));
            clipped = true;
        }
        if (!clipped) break; // not simple; leave the rest
    }
    if (idx.size() == 3) out.push_back({idx[0], idx[1], idx[2]});
    return out;
}

} // namespace

TriangleMesh make_torus(double ring, double tube, int nu, int nv) {
    std::vector<Eigen::Vector3d> p;
    std::vector<Triangle> t;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv;
            p.emplace_back((ring + tube * std::cos(v)) * std::cos(u), (ring + tube * std::cos(v)) * std::sin(u),
                           tube * std::sin(v));
        }
    auto id = [&](int i, int j) { return uint32_t(((i + nu) % nu) * nv + (j + nv) % nv); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return finish("torus", std::move(p), std::move(t));
}

TriangleMesh make_ball(double radius, int nu, int nv) {
    std::vector<Eigen::Vector3d> p{{0, 0, radius}, {0, 0, -radius}}; // the poles
    std::vector<Triangle> t;
    for (int j = 1; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const double u = 2 * kPi * i / nu, v = kPi * j / nv;
            p.emplace_back(radius * std::sin(v) * std::cos(u), radius * std::sin(v) * std::sin(u), radius * std::cos(v));
        }
    auto id = [&](int i, int j) { return uint32_t(2 + (j - 1) * nu + (i + nu) % nu); }; // ring j = 1 .. nv - 1
    for (int i = 0; i < nu; ++i) {
        t.push_back({0, id(i, 1), id(i + 1, 1)});
        t.push_back({1, id(i + 1, nv - 1), id(i, nv - 1)});
        for (int j = 1; j + 1 < nv; ++j) {
            t.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
            t.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
        }
    }
    return finish("ball", std::move(p), std::move(t));
}

TriangleMesh make_box(const Eigen::Vector3d& half, int n) {
    std::vector<Eigen::Vector3d> p;
    std::vector<Triangle> t;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = -1; side <= 1; side += 2) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const uint32_t base = uint32_t(p.size());
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) {
                    Eigen::Vector3d x;
                    x[axis] = side * half[axis];
                    x[u] = half[u] * (2.0 * i / n - 1);
                    x[v] = half[v] * (2.0 * j / n - 1);
                    p.push_back(x);
                }
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const uint32_t a = base + uint32_t(i * (n + 1) + j), b = a + uint32_t(n + 1);
                    if (side > 0) t.push_back({a, b, b + 1}), t.push_back({a, b + 1, a + 1});
                    else t.push_back({a, b + 1, b}), t.push_back({a, a + 1, b + 1});
                }
        }
    return finish("box", std::move(p), std::move(t));
}

TriangleMesh make_sheet(double size, int n) {
    std::vector<Eigen::Vector3d> p;
    std::vector<Triangle> t;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) p.emplace_back(size * (double(i) / n - 0.5), size * (double(j) / n - 0.5), 0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
            t.push_back({a, b, d}), t.push_back({a, d, c});
        }
    return finish("sheet", std::move(p), std::move(t));
}

TriangleMesh make_bracket() {
    std::vector<Eigen::Vector2d> poly = {{0, 0}, {6, 0}, {6, 0.8}, {2, 0.8}, {2, 3}};
    for (int k = 1; k < 12; ++k) { // rounded end, centre (1, 3), radius 1
        const double a = kPi * k / 12;
        poly.emplace_back(1 + std::cos(a), 3 + std::sin(a));
    }
    poly.emplace_back(0, 3);
    const double depth = 2.5;
    std::vector<Eigen::Vector3d> p;
    for (const auto& q : poly) p.emplace_back(q.x(), q.y(), 0);
    for (const auto& q : poly) p.emplace_back(q.x(), q.y(), depth);
    const uint32_t n = uint32_t(poly.size());
    std::vector<Triangle> t;
    for (const Triangle& c : triangulate(poly)) {
        t.push_back({c[0], c[2], c[1]});             // bottom faces -z
        t.push_back({c[0] + n, c[1] + n, c[2] + n}); // top faces +z
    }
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t a = k, b = (k + 1) % n;
        t.push_back({a, b, b + n});
        t.push_back({a, b + n, a + n});
    }
    return finish("bracket", std::move(p), std::move(t));
}

TriangleMesh scale_to_unit_cube(const TriangleMesh& mesh) {
    const auto [lo, hi] = mesh.bounds();
    const Eigen::Vector3d centre = (lo + hi) / 2;
    const double half = (hi - lo).maxCoeff() / 2;
    const double s = half > 0 ? 1.0 / half : 1.0;
    std::vector<Eigen::Vector3d> p(mesh.positions.size());
    for (size_t i = 0; i < p.size(); ++i) p[i] = (mesh.positions[i] - centre) * s;
    return prepare_mesh(mesh.name, std::move(p), mesh.triangles).mesh;
}

} // namespace spt
