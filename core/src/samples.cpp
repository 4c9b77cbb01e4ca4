#include "spt/samples.hpp"
#include <algorithm>
#include <cmath>

namespace spt {
namespace {

float to_snorm16(float v) { return std::round(std::clamp(v, -1.0f, 1.0f) * 32767.0f); }

} // namespace

uint32_t encode_normal(const Eigen::Vector3f& n_in) {
    // Octahedral map: project onto |x|+|y|+|z| = 1, fold the lower half over.
    Eigen::Vector3f n = n_in;
    const float l1 = std::abs(n.x()) + std::abs(n.y()) + std::abs(n.z());
    if (!(l1 > 0)) n = Eigen::Vector3f(0, 0, 1);
    else n /= l1;
    float u = n.x(), v = n.y();
    if (n.z() < 0) {
        const float ou = u, ov = v;
        u = (1.0f - std::abs(ov)) * (ou >= 0 ? 1.0f : -1.0f);
        v = (1.0f - std::abs(ou)) * (ov >= 0 ? 1.0f : -1.0f);
    }
    const auto qu = uint16_t(int16_t(to_snorm16(u)));
    const auto qv = uint16_t(int16_t(to_snorm16(v)));
    return uint32_t(qu) | (uint32_t(qv) << 16);
}

Eigen::Vector3f decode_normal(uint32_t code) {
    const float u = std::max(-1.0f, float(int16_t(code & 0xffff)) / 32767.0f);
    const float v = std::max(-1.0f, float(int16_t(code >> 16)) / 32767.0f);
    Eigen::Vector3f n(u, v, 1.0f - std::abs(u) - std::abs(v));
    if (n.z() < 0) {
        const float ou = n.x(), ov = n.y();
        n.x() = (1.0f - std::abs(ov)) * (ou >= 0 ? 1.0f : -1.0f);
        n.y() = (1.0f - std::abs(ou)) * (ov >= 0 ? 1.0f : -1.0f);
    }
    return n.normalized();
}

void SampleSet::add(const Eigen::Vector3f& p, const Eigen::Vector3f& n, uint32_t source, float s) {
    points.push_back(p);
    normals.push_back(decode_normal(encode_normal(n)));
    sources.push_back(source);
    spacing.push_back(s);
}

SampleSet sample_vertices(const TriangleMesh& mesh) {
    const size_t n = mesh.positions.size();
    std::vector<double> edge_sum(n, 0);
    std::vector<uint32_t> edge_count(n, 0);
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            // Each interior edge is seen twice, once per face: the mean is unaffected.
            const uint32_t a = t[k], b = t[(k + 1) % 3];
            const double len = (mesh.positions[a] - mesh.positions[b]).norm();
            edge_sum[a] += len, edge_sum[b] += len;
            ++edge_count[a], ++edge_count[b];
        }
    SampleSet s;
    s.points.reserve(n), s.normals.reserve(n), s.sources.reserve(n), s.spacing.reserve(n);
    for (uint32_t v = 0; v < n; ++v) {
        if (!mesh.normal_valid[v] || edge_count[v] == 0) continue;
        s.add(mesh.positions[v].cast<float>(), mesh.normals[v].cast<float>(), v, float(edge_sum[v] / edge_count[v]));
    }
    return s;
}

double max_face_sample_gap(double radius, double eps) {
    // A point at in-plane distance h from a face sample is sqrt(h^2 + r^2) - r outside its sphere.
    return std::sqrt(eps * eps + 2.0 * radius * eps);
}

void add_face_samples(SampleSet& samples, const TriangleMesh& mesh, const std::vector<uint32_t>& triangles,
                      const std::vector<double>& max_gap) {
    for (size_t i = 0; i < triangles.size(); ++i) {
        const uint32_t f = triangles[i];
        const auto& t = mesh.triangles[f];
        const Eigen::Vector3d a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        const Eigen::Vector3d fn = (b - a).cross(c - a);
        if (!(fn.norm() > 0)) continue;
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        // Any point of a triangle is within longest_edge/sqrt(3) of a corner; a grid of m
        // divisions shrinks every sub-triangle by m.
        const double h = std::max(max_gap[i], 1e-12);
        const double m_real = std::ceil(longest / (std::sqrt(3.0) * h));
        const int m = int(std::clamp(m_real, 1.0, 4096.0));
        const Eigen::Vector3f normal = fn.normalized().cast<float>();
        // Spacing stands for the mesh's own resolution (it sets default radii), not the grid's.
        const float spacing = float(((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3.0);
        for (int i1 = 0; i1 <= m; ++i1)
            for (int i2 = 0; i1 + i2 <= m; ++i2) {
                const double u = double(i1) / m, v = double(i2) / m;
                const Eigen::Vector3d p = a + u * (b - a) + v * (c - a);
                samples.add(p.cast<float>(), normal, f | kFaceSampleBit, spacing);
            }
    }
}

} // namespace spt
