#include "spt/samples.hpp"
#include "triangle_bvh.hpp"
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <Eigen/Geometry>

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

uint16_t encode_length(float v, bool round_down) {
    if (!(v >= 0)) v = 0;
    if (std::isinf(v)) return 0x7f80;
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    if (!round_down) bits += 0x7fff + ((bits >> 16) & 1); // round half to even
    return uint16_t(std::min<uint32_t>(bits >> 16, 0x7f80));
}

float decode_length(uint16_t code) {
    const uint32_t bits = uint32_t(code) << 16;
    float v;
    std::memcpy(&v, &bits, 4);
    return v;
}

void SampleSet::add(const Eigen::Vector3f& p, const Eigen::Vector3f& n, uint32_t source, float s, float r_max) {
    points.push_back(p);
    normals.push_back(decode_normal(encode_normal(n)));
    sources.push_back(source);
    spacing.push_back(decode_length(encode_length(s, false)));
    max_radius.push_back(decode_length(encode_length(r_max, true)));
}

RadiusLimiter::RadiusLimiter(const TriangleMesh& mesh, double protrusion)
    : mesh_(mesh), bvh_(std::make_unique<detail::TriangleBvh>(mesh)), protrusion_(protrusion) {
    // A vertex is on an open part if one of its faces is (prepare_mesh found the parts).
    const size_t nv = mesh.positions.size();
    const bool known = mesh.on_open_part.size() == mesh.triangles.size();
    open_part_.assign(nv, known ? 0 : 1);
    for (size_t f = 0; known && f < mesh.triangles.size(); ++f)
        if (mesh.on_open_part[f])
            for (uint32_t v : mesh.triangles[f]) open_part_[v] = 1;
    ray_length_ = 4 * mesh.diagonal() + 1e-300; // from any point on the mesh to beyond it
}

bool RadiusLimiter::back_exposed(const Eigen::Vector3d& p, const Eigen::Vector3d& n, uint32_t vertex) const {
    if (vertex >= open_part_.size() || !open_part_[vertex]) return false;
    const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    const double c = std::sqrt(0.5);
    const Eigen::Vector3d dirs[] = {-n, c * (-n + t1), c * (-n - t1), c * (-n + t2), c * (-n - t2)};
    for (const auto& d : dirs)
        if (!bvh_->segment_hits(p, p + ray_length_ * d, 1e-9)) return true;
    return false;
}

RadiusLimiter::~RadiusLimiter() = default;

bool RadiusLimiter::protrudes(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double r) const {
    if (r <= protrusion_) return false;
    const Eigen::Vector3d c = p - r * n;
    // The tangent point p is at distance r; a surface nearer than r - allowance means the
    // sphere pokes out there by more than the allowance.
    if (bvh_->any_within(c, (r - protrusion_) * (r - protrusion_))) return true;
    // A centre beyond a wall thinner than the allowance passes the test above; the segment
    // from the tangent point to the centre then crosses the surface. The start is skipped
    // so the faces at p itself do not count.
    return bvh_->segment_hits(p, c, 1e-6);
}

float RadiusLimiter::limit(const Eigen::Vector3f& pf, const Eigen::Vector3f& nf, float r_max, uint32_t vertex) const {
    const Eigen::Vector3d p = pf.cast<double>(), n = nf.cast<double>();
    if (back_exposed(p, n, vertex)) r_max = std::min(r_max, float(protrusion_ / 2));
    // Protrusion grows with r (a centre that passes through a thin part counts as outside),
    // so the largest allowed radius is found by bisection.
    if (!protrudes(p, n, r_max)) return r_max;
    double lo = std::min<double>(protrusion_, r_max), hi = r_max;
    for (int i = 0; i < 20 && hi > lo * 1.01; ++i) {
        const double mid = (lo + hi) / 2;
        (protrudes(p, n, mid) ? hi : lo) = mid;
    }
    return float(lo);
}

SampleSet sample_vertices(const TriangleMesh& mesh, const RadiusLimiter& limiter, const RadiusRule& rule) {
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
    for (auto* v : {&s.spacing, &s.max_radius}) v->reserve(n);
    s.points.reserve(n), s.normals.reserve(n), s.sources.reserve(n);
    for (uint32_t v = 0; v < n; ++v) {
        if (!mesh.normal_valid[v] || edge_count[v] == 0) continue;
        const float spacing = float(edge_sum[v] / edge_count[v]);
        const Eigen::Vector3f p = mesh.positions[v].cast<float>();
        const Eigen::Vector3f nrm = decode_normal(encode_normal(mesh.normals[v].cast<float>()));
        s.add(p, nrm, v, spacing, limiter.limit(p, nrm, kRadiusSearchHeadroom * rule.for_sample(spacing, INFINITY), v));
    }
    return s;
}

double max_face_sample_gap(double radius, double eps) {
    // A point at in-plane distance h from a face sample is sqrt(h^2 + r^2) - r outside its sphere.
    return std::sqrt(eps * eps + 2.0 * radius * eps);
}

namespace {

// Adaptive sampling of one triangle on a dyadic barycentric grid: a sub-triangle is fine
// when every point of it is close enough to one of its corners for that corner's sphere.
struct FaceSampler {
    static constexpr int kLevels = 20; // finest grid: 2^-20 of the triangle
    static constexpr int64_t kGrid = int64_t(1) << kLevels;
    SampleSet& out;
    const RadiusLimiter& limiter;
    uint32_t face;
    Eigen::Vector3d a, b, c;
    Eigen::Vector3f normal;
    uint32_t corner_vertex; // any vertex of the face: it names the face's connected part
    float spacing;
    RadiusRule rule;
    float factor;
    double eps;
    std::map<std::pair<int64_t, int64_t>, float> radius_at; // assumed radius of each corner sample

    Eigen::Vector3d point(int64_t i, int64_t j) const {
        return a + (double(i) / kGrid) * (b - a) + (double(j) / kGrid) * (c - a);
    }
    float corner(int64_t i, int64_t j) {
        auto it = radius_at.find({i, j});
        if (it != radius_at.end()) return it->second;
        const Eigen::Vector3f p = point(i, j).cast<float>();
        const float cap = limiter.limit(p, normal, kRadiusSearchHeadroom * rule.for_sample(spacing, INFINITY), corner_vertex);
        out.add(p, normal, face | kFaceSampleBit, spacing, cap);
        const float r = factor * rule.for_sample(spacing, out.max_radius.back());
        radius_at[{i, j}] = r;
        return r;
    }
    // Longest-edge bisection follows the triangle's shape, so a long thin face is refined
    // along its length only.
    void refine(std::array<std::pair<int64_t, int64_t>, 3> v, int level) {
        float r = INFINITY;
        for (auto [i, j] : v) r = std::min(r, corner(i, j));
        const Eigen::Vector3d p[3] = {point(v[0].first, v[0].second), point(v[1].first, v[1].second),
                                      point(v[2].first, v[2].second)};
        int k = 0; // edge k runs from v[k] to v[k+1]
        double longest = 0;
        for (int e = 0; e < 3; ++e) {
            const double len = (p[(e + 1) % 3] - p[e]).norm();
            if (len > longest) longest = len, k = e;
        }
        // Every point of a triangle is within (longest edge)/sqrt(3) of a corner.
        const double rho = longest / std::sqrt(3.0);
        if (std::sqrt(rho * rho + double(r) * r) - r <= eps) return;
        const auto a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
        if (((a.first + b.first) | (a.second + b.second)) & 1) return; // finest grid reached
        const std::pair<int64_t, int64_t> m{(a.first + b.first) / 2, (a.second + b.second) / 2};
        refine({a, m, c}, level + 1);
        refine({m, b, c}, level + 1);
    }
};

} // namespace

void add_face_samples(SampleSet& samples, const RadiusLimiter& limiter, uint32_t face, double eps,
                      const RadiusRule& rule, float radius_factor) {
    const TriangleMesh& mesh = limiter.mesh();
    const auto& t = mesh.triangles[face];
    const Eigen::Vector3d a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const Eigen::Vector3d fn = (b - a).cross(c - a);
    if (!(fn.norm() > 0)) return;
    // Spacing stands for the mesh's own resolution (it sets default radii), not the grid's.
    const float spacing = float(((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3.0);
    FaceSampler fs{samples, limiter, face, a, b, c, fn.normalized().cast<float>(), t[0], spacing, rule, radius_factor, eps, {}};
    const int64_t g = FaceSampler::kGrid;
    fs.refine({std::pair<int64_t, int64_t>{0, 0}, {g, 0}, {0, g}}, 0);
}

} // namespace spt
