// Procedural meshes for the bundled resources, tests and benchmarks.
#include "meshgen.hpp"
#include "spt/error.hpp"
#include "mesh/shapes.hpp"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

namespace spt::meshgen {
namespace {

std::FILE* open_or_throw(const std::string& path, const char* mode) {
    std::FILE* f = std::fopen(path.c_str(), mode);
    if (!f) throw Error(ErrorKind::CannotWrite, path + ": cannot open for writing");
    return f;
}

} // namespace

void RawMesh::append(const RawMesh& o, const Eigen::Vector3d& offset) {
    const auto base = uint32_t(positions.size());
    for (const auto& p : o.positions) positions.push_back(p + offset);
    for (const auto& t : o.triangles) triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

namespace {

RawMesh raw(const TriangleMesh& m) { return {m.positions, m.triangles}; }

} // namespace

RawMesh torus(double R, double r, int nu, int nv) { return raw(make_torus(R, r, nu, nv)); }

RawMesh box(double sx, double sy, double sz, int n) { return raw(make_box({sx / 2, sy / 2, sz / 2}, n)); }

RawMesh uv_sphere(double r, int slices, int stacks) {
    RawMesh m;
    m.positions.emplace_back(0, 0, r); // north pole, then the rings, then the south pole
    for (int j = 1; j < stacks; ++j) {
        const double v = kPi * j / stacks;
        for (int i = 0; i < slices; ++i) {
            const double u = 2 * kPi * i / slices;
            m.positions.emplace_back(r * std::sin(v) * std::cos(u), r * std::sin(v) * std::sin(u), r * std::cos(v));
        }
    }
    m.positions.emplace_back(0, 0, -r);
    const auto south = uint32_t(m.positions.size() - 1);
    auto ring = [&](int j, int i) { return uint32_t(1 + (j - 1) * slices + (i + slices) % slices); };
    for (int i = 0; i < slices; ++i) {
        m.triangles.push_back({0, ring(1, i), ring(1, i + 1)});
        for (int j = 1; j + 1 < stacks; ++j) {
            m.triangles.push_back({ring(j, i), ring(j + 1, i), ring(j + 1, i + 1)});
            m.triangles.push_back({ring(j, i), ring(j + 1, i + 1), ring(j, i + 1)});
        }
        m.triangles.push_back({south, ring(stacks - 1, i + 1), ring(stacks - 1, i)});
    }
    return m;
}

RawMesh icosphere(double r, int level) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    RawMesh m;
    m.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            m.positions.push_back((m.positions[a] + m.positions[b]) / 2);
            return mid[key] = uint32_t(m.positions.size() - 1);
        };
        std::vector<Triangle> next;
        next.reserve(m.triangles.size() * 4);
        for (const auto& tr : m.triangles) {
            const uint32_t ab = midpoint(tr[0], tr[1]), bc = midpoint(tr[1], tr[2]), ca = midpoint(tr[2], tr[0]);
            next.push_back({tr[0], ab, ca});
            next.push_back({tr[1], bc, ab});
            next.push_back({tr[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        m.triangles = std::move(next);
    }
    for (auto& p : m.positions) p = p.normalized() * r;
    return m;
}

RawMesh cylinder(double r, double h, int seg) {
    RawMesh m;
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < seg; ++i) {
            const double a = 2 * kPi * i / seg;
            m.positions.emplace_back(r * std::cos(a), r * std::sin(a), k * h);
        }
    const auto bottom = uint32_t(m.positions.size());
    m.positions.emplace_back(0, 0, 0);
    m.positions.emplace_back(0, 0, h);
    const uint32_t top = bottom + 1, s = uint32_t(seg);
    for (uint32_t i = 0; i < s; ++i) {
        const uint32_t j = (i + 1) % s;
        m.triangles.push_back({i, j, s + j});
        m.triangles.push_back({i, s + j, s + i});
        m.triangles.push_back({bottom, j, i});
        m.triangles.push_back({top, s + i, s + j});
    }
    return m;
}

namespace {

// z-up construction to y-up (the convention of OBJ, glTF and the renderer): (x, y, z) -> (x, z, -y).
RawMesh y_up(RawMesh m) {
    for (auto& p : m.positions) p = Eigen::Vector3d(p.x(), p.z(), -p.y());
    return m;
}

} // namespace

RawMesh figure() {
    // Built z-up, parts stacked so they touch rather than overlap much; each a closed shell.
    RawMesh m;
    m.append(box(0.12, 0.26, 0.06, 3), {-0.11, -0.04, 0.03});  // left foot (toes towards +z once y-up)
    m.append(box(0.12, 0.26, 0.06, 3), {0.11, -0.04, 0.03});   // right foot
    m.append(cylinder(0.055, 0.80, 16), {-0.11, 0, 0.06});     // left leg
    m.append(cylinder(0.055, 0.80, 16), {0.11, 0, 0.06});      // right leg
    m.append(box(0.42, 0.22, 0.62, 4), {0, 0, 1.17});          // body
    m.append(cylinder(0.045, 0.60, 12), {-0.26, 0, 0.86});     // left arm
    m.append(cylinder(0.045, 0.60, 12), {0.26, 0, 0.86});      // right arm
    m.append(icosphere(0.13, 3), {0, 0, 1.61});                 // head
    return y_up(std::move(m));
}

RawMesh cad_part() {
    RawMesh m;
    m.append(box(2.0, 1.2, 0.2, 1), {0, 0, 0.1});              // plate: two triangles per face
    m.append(cylinder(0.22, 0.45, 48), {-0.55, 0, 0.2});       // bosses
    m.append(cylinder(0.22, 0.45, 48), {0.55, 0, 0.2});
    m.append(box(0.7, 0.12, 0.3, 1), {0, 0, 0.35});            // rib between them
    return y_up(std::move(m));
}

void write_obj(const RawMesh& m, const std::string& path) {
    std::FILE* f = open_or_throw(path, "w");
    std::fprintf(f, "# made by spt tools/meshgen\n");
    for (const auto& p : m.positions) std::fprintf(f, "v %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
    for (const auto& t : m.triangles) std::fprintf(f, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
    if (std::fclose(f) != 0) throw Error(ErrorKind::CannotWrite, path + ": write failed");
}

void write_stl(const RawMesh& m, const std::string& path) {
    std::FILE* f = open_or_throw(path, "wb");
    char header[80] = "binary STL made by spt tools/meshgen";
    std::fwrite(header, 1, 80, f);
    const auto n = uint32_t(m.triangles.size());
    std::fwrite(&n, 4, 1, f);
    for (const auto& t : m.triangles) {
        const Eigen::Vector3d &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
        const Eigen::Vector3f nrm = (b - a).cross(c - a).normalized().cast<float>();
        float v[12] = {nrm.x(), nrm.y(), nrm.z()};
        for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d) v[3 + 3 * k + d] = float(m.positions[t[k]][d]);
        const uint16_t attr = 0;
        std::fwrite(v, 4, 12, f);
        std::fwrite(&attr, 2, 1, f);
    }
    if (std::fclose(f) != 0) throw Error(ErrorKind::CannotWrite, path + ": write failed");
}

void write_ply(const RawMesh& m, const std::string& path) {
    std::FILE* f = open_or_throw(path, "wb");
    std::fprintf(f, "ply\nformat binary_little_endian 1.0\ncomment made by spt tools/meshgen\n"
                    "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face %zu\nproperty list uchar int vertex_indices\nend_header\n",
                 m.positions.size(), m.triangles.size());
    for (const auto& p : m.positions) {
        const float v[3] = {float(p.x()), float(p.y()), float(p.z())};
        std::fwrite(v, 4, 3, f);
    }
    for (const auto& t : m.triangles) {
        const uint8_t three = 3;
        const int32_t idx[3] = {int32_t(t[0]), int32_t(t[1]), int32_t(t[2])};
        std::fwrite(&three, 1, 1, f);
        std::fwrite(idx, 4, 3, f);
    }
    if (std::fclose(f) != 0) throw Error(ErrorKind::CannotWrite, path + ": write failed");
}

ImportedMesh prepare(const RawMesh& m, const std::string& name) { return prepare_mesh(name, m.positions, m.triangles); }

} // namespace spt::meshgen
