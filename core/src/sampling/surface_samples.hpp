#pragma once
// Vertex samples and tolerance-driven face samples of a mesh.
#include "spt/samples.hpp"
#include "sampling/radius_limiter.hpp"
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace spt {

/// How far the radius search looks, relative to the radius the rule asks for: room for a
/// node's median spacing to exceed a member's own. Beyond it max_radius is not explored.
constexpr float kRadiusSearchHeadroom = 2.0f;

/// The local origin samples of `mesh` are stored relative to: the centre of its bounding box,
/// snapped to a grid whose spacing is the power of two at or above the mesh's diagonal (so
/// zero for a mesh around its file's origin).
Eigen::Vector3d local_origin(const TriangleMesh& mesh);

/// Radius passed to RadiusLimiter::limit for a sample of local `spacing`: kRadiusSearchHeadroom x
/// the rule's radius, or for a two-sided sample the rule's radius itself.
float search_radius(const RadiusRule& rule, float spacing, bool two_sided);

/// Vertices or faces are sampled in runs of this many, each run into a set of its own on one
/// thread, and the sets joined in run order: the samples do not depend on the thread count. A
/// run is short because an item's cost varies a thousandfold: a face of a small mesh carries
/// hundreds of samples, each with a probe of the mesh at every pose (ConvertOptions::poses), and
/// a mesh of fewer faces than one run was sampled on one thread.
constexpr size_t kSampleRun = 256;

/// One sample per vertex with a valid normal, relative to local_origin(mesh); spacing = mean length of its edges,
/// max_radius from `limiter` (search_radius); vertices of open parts are two-sided.
/// On up to `threads` threads, with the same samples as on one. Throws Cancelled once `cancel`
/// (may be null) is set: it is looked at every kSampleRun vertices.
SampleSet sample_vertices(const TriangleMesh& mesh, const RadiusLimiter& limiter, const RadiusRule& rule = {},
                          int threads = 1, const std::atomic<bool>* cancel = nullptr, TaskSystem* tasks = nullptr);

/// Two-sided spheres (open parts) must hold every point of their face, not merely come within
/// a tolerance of it, so that two open surfaces that cross always have overlapping spheres:
/// face samples are placed so that every point of a face is within this fraction of a
/// sphere's radius from its centre (the rest is a margin for rounding).
constexpr double kTwoSidedCoverage = 0.9;

/// What a face sample of triangle `face` takes from its face: the unit face normal (float, as
/// stored), the centroid (object frame, model units), where the radius limiter's segment test
/// starts, and the face's width (twice its area over its longest edge, model units): a one-sided
/// face narrower than the allowance is a needle, whose spheres keep the limiter's floor. Empty
/// for a degenerate face, which gets no face samples.
struct FaceFrame {
    Eigen::Vector3f normal;
    Eigen::Vector3d centroid;
    double width;
};
std::optional<FaceFrame> face_frame(const TriangleMesh& mesh, uint32_t face);

/// Thrown by add_face_samples and face_samples when the samples would pass their limit.
struct TooManySamples {
    size_t reached; ///< samples there would have been with the next one
};

namespace detail {
/// The widest step of a face's refinement whose probes go to the threads (add_face_samples);
/// wider steps and the rest of that face's refinement run on the calling thread. Tests lower it.
inline size_t most_planned_sub_triangles = size_t(1) << 18;
} // namespace detail

/// Adds face samples (face normals, relative to samples.origin) on `triangle`, refining adaptively until every point of
/// it lies within reach of a face sample whose sphere leaves it at most `eps` uncovered (on an
/// open part: lies inside the sphere, within kTwoSidedCoverage of its radius; the samples are
/// two-sided), assuming each sample's radius is `radius_factor` x rule.for_sample(spacing, max_radius)
/// (two-sided: 1 x, as the builder keeps their radius). Throws TooManySamples (counting this
/// face's samples) before it would add more than `room` samples (on several threads, often before
/// it adds any). On up to `threads` threads (the limiter's probes of each step of the refinement),
/// with the same samples in the same order as on one: a face of a few large triangles can carry
/// tens of thousands of samples, each probed at every pose. Once `cancel` (may be null) is set,
/// stops within kSampleRun of its probes (on several threads, within a step's), leaving part of
/// the face's samples in the set: the caller checks the flag after the call and discards the set.
void add_face_samples(SampleSet& samples, const RadiusLimiter& limiter, uint32_t triangle, double eps,
                      const RadiusRule& rule, float radius_factor, size_t room = SIZE_MAX, int threads = 1,
                      TaskSystem* tasks = nullptr, const std::atomic<bool>* cancel = nullptr);

/// The face samples of every triangle of the limiter's mesh, in triangle order, relative to
/// `origin` (add_face_samples of each), on up to `threads` threads with the same samples as on
/// one. Once `cancel` (may be null) is set, the faces not yet begun are skipped (it is looked at
/// every kSampleRun faces) and a face under way stops (add_face_samples): the caller checks it
/// after the call and discards the set.
/// Throws TooManySamples once the set would hold more than `max_samples` samples (a face stops
/// when its own samples would take the count past it; threads running at once may each reach it).
SampleSet face_samples(const RadiusLimiter& limiter, const Eigen::Vector3d& origin, double eps, const RadiusRule& rule,
                       float radius_factor, int threads, const std::atomic<bool>* cancel = nullptr,
                       size_t max_samples = SIZE_MAX, TaskSystem* tasks = nullptr);
/// A lower bound on the number of samples face_samples(limiter, ..., eps, rule, radius_factor)
/// makes, from each face's area and the largest sub-triangle its stopping rule can accept; O(faces).
double least_face_samples(const RadiusLimiter& limiter, double eps, const RadiusRule& rule, float radius_factor);
/// Largest in-plane distance between face samples that keeps the uncovered depth
/// under spheres of radius r within eps: sqrt(h^2 + r^2) - r <= eps.
double max_face_sample_gap(double radius, double eps);

} // namespace spt
