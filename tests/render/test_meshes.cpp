// Test meshes made in code (box figure, torus) and plain OBJ / binary PLY writers.
#include "test_meshes.hpp"
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace spt::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Appends an axis-aligned box with each face divided into cells of about `cell`.
void add_box(std::vector<Eigen::Vector3d>& pos, std::vector<Triangle>& tris, const Eigen::Vector3d& c,
             const Eigen::Vector3d& half, double cell) {
    for (int axis = 0; axis < 3; ++axis)
        for (int side : {-1, 1}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const int nu = std::max(1, int(std::ceil(2 * half[u] / cell)));
            const int nv = std::max(1, int(std::ceil(2 * half[v] / cell)));
            const uint32_t base = uint32_t(pos.size());
            for (int j = 0; j <= nv; ++j)
                for (int i = 0; i <= nu; ++i) {
                    Eigen::Vector3d p = c;
                    p[axis] += side * half[axis];
                    p[u] += half[u] * (2.0 * i / nu - 1.0);
                    p[v] += half[v] * (2.0 * j / nv - 1.0);
                    pos.push_back(p);
                }
            for (int j = 0; j < nv; ++j)
                for (int i = 0; i < nu; ++i) {
                    const uint32_t a = base + uint32_t(j * (nu + 1) + i), b = a + 1, d = a + uint32_t(nu + 1), e = d + 1;
                    // u x v = +axis, so this winding faces outward on the + side.
                    if (side > 0) tris.push_back({a, b, e}), tris.push_back({a, e, d});
                    else tris.push_back({a, e, b}), tris.push_back({a, d, e});
                }
        }
}

} // namespace

TriangleMesh torus(double R, double r, int nu, int nv) {
    std::vector<Eigen::Vector3d> pos;
    std::vector<Triangle> tris;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double a = 2 * kPi * i / nu, b = 2 * kPi * j / nv;
            pos.emplace_back((R + r * std::cos(b)) * std::cos(a), r * std::sin(b), (R + r * std::cos(b)) * std::sin(a));
        }
    auto at = [&](int i, int j) { return uint32_t(((i + nu) % nu) * nv + (j + nv) % nv); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            tris.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            tris.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    return prepare_mesh("torus", std::move(pos), std::move(tris)).mesh;
}

TriangleMesh box_figure() {
    std::vector<Eigen::Vector3d> pos;
    std::vector<Triangle> tris;
    const double cell = 0.1;
    add_box(pos, tris, {0, 1.0, 0}, {0.35, 0.45, 0.2}, cell);       // body
    add_box(pos, tris, {0, 1.72, 0}, {0.2, 0.2, 0.2}, cell);        // head
    add_box(pos, tris, {0, 1.72, 0.27}, {0.05, 0.05, 0.07}, cell);  // nose, towards +Z
    add_box(pos, tris, {0.17, 0.28, 0}, {0.12, 0.28, 0.12}, cell);  // legs
    add_box(pos, tris, {-0.17, 0.28, 0}, {0.12, 0.28, 0.12}, cell);
    add_box(pos, tris, {0.5, 1.6, 0}, {0.1, 0.35, 0.1}, cell);      // +X arm, raised
    add_box(pos, tris, {-0.47, 1.02, 0}, {0.1, 0.38, 0.1}, cell);   // -X arm, down
    return prepare_mesh("figure", std::move(pos), std::move(tris)).mesh;
}

void write_obj(const TriangleMesh& mesh, const std::string& path) {
    std::ofstream out(path);
    for (const auto& p : mesh.positions) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    if (!out) throw std::runtime_error("cannot write " + path);
}

void write_ply(const TriangleMesh& mesh, const std::string& path) {
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << mesh.positions.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << mesh.triangles.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto& p : mesh.positions) {
        const float v[3] = {float(p.x()), float(p.y()), float(p.z())};
        out.write(reinterpret_cast<const char*>(v), sizeof v);
    }
    for (const auto& t : mesh.triangles) {
        const unsigned char n = 3;
        const int32_t idx[3] = {int32_t(t[0]), int32_t(t[1]), int32_t(t[2])};
        out.write(reinterpret_cast<const char*>(&n), 1);
        out.write(reinterpret_cast<const char*>(idx), sizeof idx);
    }
    if (!out) throw std::runtime_error("cannot write " + path);
}

} // namespace spt::test
