// Vertex samples and tolerance-driven face samples of a mesh.
#include "sampling/surface_samples.hpp"
#include "sampling/encoding.hpp"
#include "base/cancel.hpp"
#include "base/parallel.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace spt {

Eigen::Vector3d local_origin(const TriangleMesh& mesh) {
    const auto [lo, hi] = mesh.bounds();
    const Eigen::Vector3d centre = 0.5 * (lo + hi);
    // The centre snapped to a grid of a power of two at least the mesh's size: a mesh
    // around its file's origin keeps origin zero (and version-1 files), an edited or
    // re-exported mesh keeps its origin, and every sample is within a few diagonals of it.
    const double size = std::max(mesh.diagonal(), std::numeric_limits<double>::min());
    const double cell = std::exp2(std::ceil(std::log2(size)));
    Eigen::Vector3d o;
    for (int k = 0; k < 3; ++k) o[k] = cell * std::round(centre[k] / cell);
    return o.allFinite() ? o : Eigen::Vector3d::Zero();
}

float search_radius(const RadiusRule& rule, float spacing, bool two_sided) {
    // A two-sided radius is not searched: it is the rung at or below the rule's radius, so
    // that the rule gives every two-sided sample exactly its max_radius.
    const float want = rule.for_sample(spacing, INFINITY);
    return two_sided ? want : kRadiusSearchHeadroom * want;
}

namespace {

// fill(first, last, out) samples items [first, last) into `out` (its origin set); on `threads`.
template <class Fill>
SampleSet sample_in_runs(size_t n, const Eigen::Vector3d& origin, int threads, TaskSystem* tasks, Fill&& fill) {
    const size_t runs = (n + kSampleRun - 1) / kSampleRun;
    if (threads <= 1 || runs <= 1) { // the same samples, without copying them from the runs
        SampleSet s;
        s.origin = origin;
        fill(0, n, s);
        return s;
    }
    std::vector<SampleSet> parts(runs);
    detail::parallel_for(runs, threads, [&](size_t k, int) {
        parts[k].origin = origin;
        fill(k * kSampleRun, std::min(n, (k + 1) * kSampleRun), parts[k]);
    }, tasks);
    SampleSet s;
    s.origin = origin;
    size_t total = 0;
    for (const SampleSet& part : parts) total += part.size();
    for (auto* v : {&s.spacing, &s.max_radius}) v->reserve(total);
    s.points.reserve(total), s.normals.reserve(total), s.sources.reserve(total);
    for (SampleSet& part : parts) {
        s.append(part);
        part = SampleSet{}; // the copy is made: free the run's memory now
    }
    return s;
}

} // namespace

SampleSet sample_vertices(const TriangleMesh& mesh, const RadiusLimiter& limiter, const RadiusRule& rule,
                          int threads, const std::atomic<bool>* cancel, TaskSystem* tasks) {
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
    return sample_in_runs(n, local_origin(mesh), threads, tasks, [&](size_t first, size_t last, SampleSet& s) {
        for (auto v = uint32_t(first); v < last; ++v) {
            if (v % kSampleRun == 0) detail::stop_if_cancelled(cancel, "converting", mesh.name);
            if (!mesh.normal_valid[v] || edge_count[v] == 0) continue;
            const float spacing = float(edge_sum[v] / edge_count[v]);
            // The radius is limited at the exact vertex: the stored float point may lie a rounding
            // off the surface, and a segment from there to the centre can graze the faces at the vertex.
            const Eigen::Vector3d& p = mesh.positions[v];
            const Eigen::Vector3f nrm = snap_normal(mesh.normals[v].cast<float>());
            const bool two_sided = limiter.on_open_part(v);
            s.add((p - s.origin).cast<float>(), nrm, v | (two_sided ? kTwoSidedBit : 0), spacing,
                  limiter.limit(p, nrm, search_radius(rule, spacing, two_sided), two_sided, v));
        }
    });
}

double max_face_sample_gap(double radius, double eps) {
    // A point at in-plane distance h from a face sample is sqrt(h^2 + r^2) - r outside its sphere.
    return std::sqrt(eps * eps + 2.0 * radius * eps);
}

namespace {

// Largest distance from a point of a triangle (squared edge lengths `len2`) to its nearest
// corner: the circumradius of an acute triangle, at most half the longest edge otherwise
// (the circumcentre lies outside and the farthest points lie on the edges). Never above
// (longest edge)/sqrt(3), and far below it for slivers and right triangles.
double nearest_corner_bound(const double len2[3]) {
    const int c = len2[0] >= len2[1] ? (len2[0] >= len2[2] ? 0 : 2) : (len2[1] >= len2[2] ? 1 : 2);
    const double c2 = len2[c], a2 = len2[(c + 1) % 3], b2 = len2[(c + 2) % 3];
    if (a2 + b2 <= c2) return 0.5 * std::sqrt(c2);
    const double den = 4 * a2 * b2 - (a2 + b2 - c2) * (a2 + b2 - c2); // 16 x area^2
    const double circum2 = den > 0 ? a2 * b2 * c2 / den : INFINITY;
    return std::sqrt(std::min(circum2, c2 / 3.0));
}

// A face sample's spacing: it stands for the mesh's own resolution (it sets default radii),
// not the grid's.
float face_spacing(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    return float(((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3.0);
}

// Adaptive sampling of one triangle on a dyadic barycentric grid: a sub-triangle is fine
// when every point of it is close enough to one of its corners for that corner's sphere:
// within the tolerance of a one-sided sphere, inside a two-sided one (open parts).
struct FaceSampler {
    static constexpr int kLevels = 20; // finest grid: 2^-20 of the triangle
    static constexpr int64_t kGrid = int64_t(1) << kLevels;
    using GridPoint = std::pair<int64_t, int64_t>;
    using SubTriangle = std::array<GridPoint, 3>;
    SampleSet& out;
    const RadiusLimiter& limiter;
    uint32_t face;
    Eigen::Vector3d a, b, c;
    Eigen::Vector3f normal;
    Eigen::Vector3d centroid;
    bool two_sided; // the face is on an open part: spheres centred on it, which must cover it
    // A one-sided face narrower than the allowance (a needle between two walls): its normal tells
    // nothing of where the solid lies, so its spheres keep the allowance's floor.
    bool needle;
    float spacing;
    RadiusRule rule;
    float factor;
    double eps;
    size_t room; // samples this face may add before it stops (TooManySamples)
    struct Corner {
        float cap = 0;      // the limiter's largest radius there (the sample's max_radius)
        float r = 0;        // the radius the refinement assumes for its sphere
        bool added = false; // its sample is in `out`
    };
    std::map<GridPoint, Corner> corners;
    const std::atomic<bool>* cancel = nullptr; // the caller's: looked at every kSampleRun new corners and each planned step
    bool stopped = false;                      // cancelled: the refinement ends where it stands

    Eigen::Vector3d point(int64_t i, int64_t j) const {
        return a + (double(i) / kGrid) * (b - a) + (double(j) / kGrid) * (c - a);
    }
    // The limiter's cap at grid point (i, j): the probes, most of a face's cost.
    float cap_at(int64_t i, int64_t j) const {
        const float search = search_radius(rule, spacing, two_sided);
        const FacePoint where{face, double(i) / kGrid, double(j) / kGrid};
        return limiter.limit(point(i, j), normal, needle ? std::min(search, float(limiter.protrusion())) : search,
                             two_sided, ~0u, &centroid, &where);
    }
    // The radius assumed for a sample whose cap is `cap`, from the cap as SampleSet::add stores it
    // (the plan needs it before the sample is added). An active node of two-sided samples keeps
    // their own radius (radius_class.hpp).
    float radius_for(float cap) const {
        return (two_sided ? 1.0f : factor) * rule.for_sample(spacing, snap_length(cap, true));
    }
    float corner(int64_t i, int64_t j) {
        auto it = corners.find({i, j});
        if (it == corners.end()) {
            // One face can ask for more samples than memory holds (a tolerance far below its size).
            if (corners.size() >= room) throw TooManySamples{corners.size() + 1};
            if (corners.size() % kSampleRun == 0 && detail::cancel_requested(cancel)) stopped = true;
            const float cap = cap_at(i, j);
            it = corners.emplace(GridPoint{i, j}, Corner{cap, radius_for(cap), false}).first;
        }
        if (!it->second.added) { // on the face: limited there, stored local in float
            out.add((point(i, j) - out.origin).cast<float>(), normal,
                    face | kFaceSampleBit | (two_sided ? kTwoSidedBit : 0), spacing, it->second.cap);
            it->second.added = true;
        }
        return it->second.r;
    }
    // Whether sub-triangle v, its corners' least radius r, must be split; if so, its two halves.
    // Longest-edge bisection follows the triangle's shape, so a long thin face is refined along
    // its length only.
    bool split(const SubTriangle& v, float r, SubTriangle& left, SubTriangle& right) const {
        // Edge lengths from grid steps and the face's two edge vectors, not from rounded
        // points: halves of a bisected edge tie exactly, and a tie broken by the rounding of
        // coordinates would sample the same face differently at another scale or offset.
        const Eigen::Vector3d e1 = b - a, e2 = c - a;
        const double q11 = e1.squaredNorm(), q12 = e1.dot(e2), q22 = e2.squaredNorm();
        int k = 0; // edge k runs from v[k] to v[k+1]
        double longest2 = 0, len2[3];
        for (int e = 0; e < 3; ++e) {
            const double di = double(v[(e + 1) % 3].first - v[e].first) / kGrid;
            const double dj = double(v[(e + 1) % 3].second - v[e].second) / kGrid;
            len2[e] = di * di * q11 + 2 * di * dj * q12 + dj * dj * q22;
            if (len2[e] > longest2 * (1 + 1e-4)) longest2 = len2[e], k = e; // near-ties: the first edge
        }
        // Every point of a triangle is within (longest edge)/sqrt(3) of a corner. A one-sided
        // sphere lies flat under the face, a two-sided one is centred on it.
        if (two_sided) {
            if (nearest_corner_bound(len2) <= kTwoSidedCoverage * double(r)) return false;
        } else {
            const double rho = std::sqrt(longest2 / 3.0);
            if (std::sqrt(rho * rho + double(r) * r) - r <= eps) return false;
        }
        const GridPoint p = v[k], q = v[(k + 1) % 3], o = v[(k + 2) % 3];
        if (((p.first + q.first) | (p.second + q.second)) & 1) return false; // finest grid reached
        const GridPoint m{(p.first + q.first) / 2, (p.second + q.second) / 2};
        left = {p, m, o}, right = {m, q, o};
        return true;
    }
    void refine(const SubTriangle& v) {
        if (stopped) return;
        float r = INFINITY;
        for (auto [i, j] : v) r = std::min(r, corner(i, j));
        SubTriangle left, right;
        if (stopped || !split(v, r, left, right)) return;
        refine(left);
        refine(right);
    }
    // The corners that refine(v) will visit, with their caps and radii, found a level of the
    // refinement at a time so that each level's probes can go to `threads` threads; refine then
    // takes the same steps in its own order and adds the samples as on one thread. A level of
    // more than detail::most_planned_sub_triangles is left to refine (on this thread), so that
    // the plan takes no more than about 12 MB beside the corners. Throws TooManySamples once the
    // corners planned pass `room` (refine would pass it too: it visits every corner planned).
    void plan(const SubTriangle& root, int threads, TaskSystem* tasks) {
        std::vector<SubTriangle> level{root}, next;
        std::vector<std::map<GridPoint, Corner>::iterator> todo; // this step's new corners
        std::vector<float> caps;
        while (!level.empty()) {
            if (detail::cancel_requested(cancel)) {
                stopped = true;
                return;
            }
            todo.clear();
            for (const SubTriangle& v : level)
                for (const GridPoint& g : v)
                    if (auto [it, added] = corners.emplace(g, Corner{}); added) todo.push_back(it);
            if (corners.size() > room) throw TooManySamples{room + 1};
            caps.resize(todo.size());
            // A few probes are not worth a hand-over to other threads.
            // Cancelled: the rest of the step's probes are skipped, and so is the refinement.
            std::atomic<bool> skipped{false};
            detail::parallel_for(todo.size(), todo.size() >= 16 ? threads : 1,
                                 [&](size_t q, int) {
                                     if (detail::cancel_requested(cancel)) skipped.store(true, std::memory_order_relaxed);
                                     else caps[q] = cap_at(todo[q]->first.first, todo[q]->first.second);
                                 },
                                 tasks);
            if (skipped.load(std::memory_order_relaxed)) {
                stopped = true;
                return;
            }
            for (size_t q = 0; q < todo.size(); ++q) todo[q]->second = Corner{caps[q], radius_for(caps[q]), false};
            next.clear();
            for (const SubTriangle& v : level) {
                float r = INFINITY;
                for (const GridPoint& g : v) r = std::min(r, corners.find(g)->second.r);
                SubTriangle left, right;
                if (split(v, r, left, right)) next.push_back(left), next.push_back(right);
            }
            if (next.size() > detail::most_planned_sub_triangles) return;
            level.swap(next);
        }
    }
};

} // namespace

std::optional<FaceFrame> face_frame(const TriangleMesh& mesh, uint32_t face) {
    const auto& t = mesh.triangles[face];
    const Eigen::Vector3d a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const Eigen::Vector3d fn = (b - a).cross(c - a);
    if (!(fn.norm() > 0)) return std::nullopt;
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    return FaceFrame{fn.normalized().cast<float>(), (a + b + c) / 3, fn.norm() / longest};
}

void add_face_samples(SampleSet& samples, const RadiusLimiter& limiter, uint32_t face, double eps,
                      const RadiusRule& rule, float radius_factor, size_t room, int threads, TaskSystem* tasks,
                      const std::atomic<bool>* cancel) {
    const TriangleMesh& mesh = limiter.mesh();
    const std::optional<FaceFrame> frame = face_frame(mesh, face);
    if (!frame) return;
    const auto& t = mesh.triangles[face];
    const Eigen::Vector3d a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const float spacing = face_spacing(a, b, c);
    const bool two_sided = limiter.face_on_open_part(face);
    const bool needle = !two_sided && frame->width < limiter.protrusion();
    FaceSampler fs{samples, limiter, face, a, b, c, frame->normal, frame->centroid, two_sided, needle,
                   spacing, rule, radius_factor, eps, room, {}};
    const int64_t g = FaceSampler::kGrid;
    const FaceSampler::SubTriangle whole{FaceSampler::GridPoint{0, 0}, {g, 0}, {0, g}};
    fs.cancel = cancel;
    if (threads > 1) fs.plan(whole, threads, tasks);
    if (!fs.stopped) fs.refine(whole);
}

SampleSet face_samples(const RadiusLimiter& limiter, const Eigen::Vector3d& origin, double eps, const RadiusRule& rule,
                       float radius_factor, int threads, const std::atomic<bool>* cancel, size_t max_samples,
                       TaskSystem* tasks) {
    const size_t faces = limiter.mesh().triangles.size();
    std::atomic<size_t> made{0};
    return sample_in_runs(faces, origin, threads, tasks, [&](size_t first, size_t last, SampleSet& s) {
        for (auto f = uint32_t(first); f < last; ++f) {
            if (f % kSampleRun == 0 && detail::cancel_requested(cancel)) return;
            if (limiter.mesh().copies_earlier_face(f)) continue; // its samples would be its face's again
            const size_t before = s.size(), so_far = made.load(std::memory_order_relaxed);
            try {
                add_face_samples(s, limiter, f, eps, rule, radius_factor, max_samples - std::min(so_far, max_samples),
                                 threads, tasks, cancel);
            } catch (const TooManySamples& t) {
                throw TooManySamples{so_far + t.reached};
            }
            const size_t total = made.fetch_add(s.size() - before, std::memory_order_relaxed) + s.size() - before;
            if (total > max_samples) throw TooManySamples{total};
        }
    });
}

double least_face_samples(const RadiusLimiter& limiter, double eps, const RadiusRule& rule, float radius_factor) {
    // A sub-triangle with longest edge L has area at most sqrt(3)/4 L^2. add_face_samples stops
    // refining one only once L <= sqrt(3) x max_face_sample_gap(r, eps) (one-sided), or once
    // L <= 2 x kTwoSidedCoverage x r (two-sided: the nearest corner is at least L/2 away from
    // some point), for r at most the rule's radius, and a two-sided one at most the two-sided
    // cap (1% above either, for rounding). A face of area A thus ends in at least
    // A / (largest such area) sub-triangles, whose corners are samples: at least half as many
    // corners as sub-triangles (Euler's formula).
    const TriangleMesh& mesh = limiter.mesh();
    double least = 0;
    for (uint32_t f = 0; f < mesh.triangles.size(); ++f) {
        if (mesh.copies_earlier_face(f)) continue; // not sampled
        const auto& t = mesh.triangles[f];
        const Eigen::Vector3d a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        const double area = 0.5 * (b - a).cross(c - a).norm();
        if (!(area > 0) || !std::isfinite(area)) continue;
        const float spacing = face_spacing(a, b, c);
        const bool two_sided = limiter.face_on_open_part(f);
        const double r = 1.01 * (two_sided ? rule.for_sample(spacing, float(limiter.two_sided_radius()))
                                           : double(radius_factor) * rule.for_sample(spacing, INFINITY));
        const double longest = two_sided ? 2 * kTwoSidedCoverage * r : std::sqrt(3.0) * max_face_sample_gap(r, eps);
        const double largest_area = std::sqrt(3.0) / 4 * longest * longest;
        if (largest_area > 0) least += 0.5 * std::floor(area / largest_area);
    }
    return least;
}

} // namespace spt
