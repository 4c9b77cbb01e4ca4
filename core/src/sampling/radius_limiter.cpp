// Caps sampling-sphere radii so that no sphere pokes out of the mesh by more than an allowance.
#include "sampling/radius_limiter.hpp"
#include "sampling/encoding.hpp"
#include "sampling/surface_samples.hpp"
#include "spt/error.hpp"
#include "geometry/triangle_bvh.hpp"
#include "geometry/vertex_faces.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace spt {
namespace {

// How far the segment test starts from an edge sample towards its face's inside point, as a
// share of the way: far above the rounding of coordinates, and (on a face not far smaller than
// the allowance) above the drift that a normal's rounding gives the segment over the two
// allowances searched; small enough to stay on the sample's face.
constexpr double kInsideFaceStep = 1e-3;

} // namespace

RadiusLimiter::RadiusLimiter(const TriangleMesh& mesh, double protrusion, double two_sided_radius)
    : mesh_(mesh), bvh_(std::make_unique<detail::TriangleBvh>(mesh)), protrusion_(protrusion),
      two_sided_radius_(two_sided_radius > 0 ? two_sided_radius : protrusion) {
    const auto [lo, hi] = mesh.bounds();
    reach_ = Eigen::AlignedBox3d(lo.array() - protrusion, hi.array() + protrusion);
    // A vertex is on an open part if one of its faces is (prepare_mesh found the parts).
    const size_t nv = mesh.positions.size();
    const bool known = mesh.on_open_part.size() == mesh.triangles.size();
    open_part_.assign(nv, known ? 0 : 1);
    for (size_t f = 0; known && f < mesh.triangles.size(); ++f)
        if (mesh.on_open_part[f])
            for (uint32_t v : mesh.triangles[f]) open_part_[v] = 1;
    // The faces that make the solid around each vertex.
    fan_ = detail::vertex_faces(nv, mesh.triangles, [&](uint32_t f) {
        return known && !mesh.on_open_part[f] && !mesh.copies_earlier_face(f);
    });
}

bool RadiusLimiter::enters_solid(uint32_t v, const Eigen::Vector3d& n) const {
    if (v + 1 >= fan_.start.size() || fan_.start[v] == fan_.start[v + 1]) return true; // nothing to tell by
    const Eigen::Vector3d& p = mesh_.positions[v];
    // A step far below every edge at v: the faces around it then look, from there, as the
    // infinite cone they span at v, whose signed solid angle is in (0, 4 pi) inside and in
    // (-4 pi, 0) outside (faces wound counter-clockwise seen from outside).
    double shortest = std::numeric_limits<double>::infinity();
    for (uint32_t k = fan_.start[v]; k < fan_.start[v + 1]; ++k)
        for (uint32_t w : mesh_.triangles[fan_.faces[k]])
            if (w != v) shortest = std::min(shortest, (mesh_.positions[w] - p).norm());
    if (!(shortest > 0) || !std::isfinite(shortest)) return true;
    const Eigen::Vector3d q = p - 1e-4 * shortest * n;
    double angle = 0;
    for (uint32_t k = fan_.start[v]; k < fan_.start[v + 1]; ++k) {
        const Triangle& t = mesh_.triangles[fan_.faces[k]];
        // Van Oosterom and Strackee: tan(omega / 2) = a.(b x c) / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|).
        const Eigen::Vector3d a = mesh_.positions[t[0]] - q, b = mesh_.positions[t[1]] - q, c = mesh_.positions[t[2]] - q;
        const double la = a.norm(), lb = b.norm(), lc = c.norm();
        angle += 2 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
    }
    return angle > 0;
}

RadiusLimiter::~RadiusLimiter() = default;

bool RadiusLimiter::protrudes(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double r, uint32_t vertex,
                              const Eigen::Vector3d& start) const {
    if (r <= protrusion_) return false;
    const Eigen::Vector3d c = p - r * n;
    // Whatever the walls near p say, a sphere that leaves the mesh's box by more than the
    // allowance pokes out of the mesh by more. The tests below assume that the centre's way
    // enters the solid at p; on a sliver it may not (assimp's regr01.obj: faces 0.01 wide edging
    // a gable 0.01 thick), and at eight times the default allowance spheres of 172 units stood
    // beside the model.
    if (((c.array() - r) < reach_.min().array()).any() || ((c.array() + r) > reach_.max().array()).any()) return true;
    // The tangent point p is at distance r; a surface nearer than r - allowance means the
    // sphere pokes out there by more than the allowance.
    // A centre beyond a wall thinner than the allowance passes that test; the segment from
    // the tangent point to the centre then crosses the surface. A crossing deeper than twice
    // the allowance lies in the ball above with a margin of an allowance, so the segment is
    // searched only that far: one walk of the tree near p answers both. The start is skipped
    // so the faces at the start itself do not count: it lies on them only up to the rounding of
    // its coordinates, which grows with their distance from the file's origin, not with r (a
    // 1e-4 mesh 1e6 away is rounded to 1e-10, a sizeable fraction of its small spheres).
    const double rounding = 64 * std::numeric_limits<double>::epsilon() * start.cwiseAbs().maxCoeff();
    const detail::BallSegmentProbe probe{c, (r - protrusion_) * (r - protrusion_), start, c - start,
                                         std::max(1e-6, rounding / r), std::min(1.0, 2 * protrusion_ / r), vertex};
    return bvh_->touches(probe);
}

float RadiusLimiter::limit(const Eigen::Vector3d& p, const Eigen::Vector3f& nf, float r_max, bool two_sided,
                           uint32_t vertex, const Eigen::Vector3d* inside_face, const FacePoint* on_face) const {
    // Where inside and outside are not defined, no solid may be invented: a sphere of an open
    // part is centred on its surface and stays within the allowance of it, on both sides.
    if (two_sided) {
        // The largest rung of a ladder R, R/sqrt(2), R/2, ... at or below r_max: few distinct
        // radii, so the tree builder can keep one radius per active node (radius_class.hpp).
        const double top = two_sided_radius_;
        if (!(r_max < top)) return float(top);
        if (!(r_max > 0)) return r_max;
        int k = std::max(0, int(std::ceil(2 * std::log2(top / r_max))));
        while (k < 4000 && top * std::exp2(-0.5 * k) > r_max) ++k;
        return float(top * std::exp2(-0.5 * k));
    }
    float r = limit_here(p, nf.cast<double>(), r_max, vertex, inside_face);
    // The sample carried to each other pose, with the normal it has there (snapped as a deformed
    // model's are): a sphere that fits at the bind pose can poke through a limb that the clip
    // squeezes or bends.
    for (const auto& pose : poses_) {
        const TriangleMesh& m = pose->mesh_;
        if (vertex != ~0u) {
            if (vertex >= m.positions.size() || !m.normal_valid[vertex]) continue;
            const Eigen::Vector3f pn = snap_normal(m.normals[vertex].cast<float>());
            r = pose->limit_here(m.positions[vertex], pn.cast<double>(), r, vertex, nullptr);
        } else if (on_face && on_face->face < m.triangles.size()) {
            const std::optional<FaceFrame> frame = face_frame(m, on_face->face);
            if (!frame) continue; // collapsed at this pose: nothing to poke out of
            const auto& t = m.triangles[on_face->face];
            const Eigen::Vector3d a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
            const Eigen::Vector3f pn = snap_normal(frame->normal);
            r = pose->limit_here(a + on_face->s * (b - a) + on_face->t * (c - a), pn.cast<double>(), r, ~0u,
                                 &frame->centroid);
        }
    }
    return r;
}

void RadiusLimiter::add_pose(const TriangleMesh& posed) {
    if (posed.positions.size() != mesh_.positions.size() || posed.triangles != mesh_.triangles ||
        posed.normals.size() != posed.positions.size() || posed.normal_valid.size() != posed.positions.size())
        throw Error(ErrorKind::Usage, mesh_.name + ": a pose to limit radii at is not this mesh moved");
    poses_.push_back(std::make_unique<RadiusLimiter>(posed, protrusion_, two_sided_radius_));
}

float RadiusLimiter::limit_here(const Eigen::Vector3d& p, const Eigen::Vector3d& n, float r_max, uint32_t vertex,
                                const Eigen::Vector3d* inside_face) const {
    // On a face's edge the centre's direction can run along the neighbouring face (a box's edge)
    // and, tipped a hair outwards by the normal's rounding, leave the solid at p itself: past the
    // skipped start, the segment then crosses nothing, and a neighbour smaller than the sphere
    // (the end of a thin bar) never comes near the centre either. From a point of the face a
    // little inside its edges the segment lies inside the solid until it crosses a wall.
    const Eigen::Vector3d start = inside_face ? p + kInsideFaceStep * (*inside_face - p) : p;
    // Both tests assume that the way to the centre enters the solid at p. A vertex's normal, the
    // mean of its faces', need not where faces fold about the vertex (regr01's needles, faces
    // 10^-5 wide with opposite normals, gave a vertex sphere poking out by 3.5 allowances): its
    // sphere then keeps the floor, the allowance.
    if (vertex != ~0u && !enters_solid(vertex, n)) return std::min(float(protrusion_), r_max);
    // Protrusion grows with r (a centre that passes through a thin part counts as outside),
    // so the largest allowed radius is found by bisection.
    if (!protrudes(p, n, r_max, vertex, start)) return r_max;
    double lo = std::min<double>(protrusion_, r_max), hi = r_max;
    for (int i = 0; i < 20 && hi > lo * 1.01; ++i) {
        const double mid = (lo + hi) / 2;
        (protrudes(p, n, mid, vertex, start) ? hi : lo) = mid;
    }
    return float(lo);
}

} // namespace spt
