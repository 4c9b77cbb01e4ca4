// Samples that follow a deforming mesh (spt/deforming_model.hpp).
#include "spt/deforming_model.hpp"
#include "anim/lazy_pose.hpp"
#include "base/parallel.hpp"
#include "mesh/vertex_normals.hpp"
#include "sampling/encoding.hpp"
#include "spt/error.hpp"
#include "spt/samples.hpp"

namespace spt {
namespace {

// Barycentric weights of p on triangle (a, b, c), from its projection on the triangle's plane.
Eigen::Vector3d barycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& c) {
    const Eigen::Vector3d v0 = b - a, v1 = c - a, v2 = p - a;
    const double d00 = v0.dot(v0), d01 = v0.dot(v1), d11 = v1.dot(v1), d20 = v2.dot(v0), d21 = v2.dot(v1);
    const double den = d00 * d11 - d01 * d01;
    if (!(den > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3}; // a degenerate face: its middle
    const double v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
    return {1 - v - w, v, w};
}

// A normal as the .spt file stores it (octahedral-snapped), so that the bind pose gives the
// document's own spheres.
Eigen::Vector3f stored(const Eigen::Vector3d& n) { return snap_normal(n.cast<float>()); }

} // namespace

DeformingModel::DeformingModel(const SptDocument& doc, std::shared_ptr<const AnimatedMesh> mesh,
                               const std::string& tree_name, bool triangles)
    : mesh_(std::move(mesh)), model_(doc, mesh_->imported.mesh, tree_name), triangles_(triangles) {
    const TriangleMesh& m = mesh_->imported.mesh;
    const SampleSet& s = doc.samples;
    bind_points_ = s.points, bind_normals_ = s.normals;
    source_ = s.sources;
    barycentric_.assign(s.size(), Eigen::Vector3d::Zero());
    bind_at_.resize(s.size());
    for (size_t i = 0; i < s.size(); ++i) {
        const uint32_t src = s.source_index(i);
        if (s.is_face_sample(i)) {
            const Triangle& t = m.triangles[src];
            barycentric_[i] = barycentric(s.position(i), m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
            const Eigen::Vector3d& w = barycentric_[i];
            bind_at_[i] = w[0] * m.positions[t[0]] + w[1] * m.positions[t[1]] + w[2] * m.positions[t[2]];
        } else {
            bind_at_[i] = m.positions[src];
        }
    }
    diagonal_ = m.diagonal();
    vertices_ = m.positions;
    vertex_normals_ = m.normals;
    points_ = bind_points_, normals_ = bind_normals_;
    measure_joints();
    face_sampled_.assign(m.triangles.size(), 0);
    for (size_t i = 0; i < s.size(); ++i)
        if (s.is_face_sample(i)) face_sampled_[s.source_index(i)] = 1;
}

void DeformingModel::pose(const Clip* clip, double time) { pose_on(clip_vertices(clip, time)); }

const std::vector<Eigen::Vector3d>& DeformingModel::clip_vertices(const Clip* clip, double time) {
    if (!clip) return mesh_->imported.mesh.positions;
    pose_vertices(*mesh_, clip, time, next_vertices_);
    return next_vertices_;
}

void DeformingModel::pose_on(const std::vector<Eigen::Vector3d>& positions) {
    take_vertices(positions);
    follow();
}

void DeformingModel::take_vertices(const std::vector<Eigen::Vector3d>& positions) {
    const TriangleMesh& m = mesh_->imported.mesh;
    if (positions.size() != m.positions.size())
        throw Error(ErrorKind::Usage, m.name + ": a pose of " + std::to_string(positions.size()) +
                                          " vertices for a mesh of " + std::to_string(m.positions.size()));
    // Checked before anything changes: a pending lazy pose reads vertices_ until it is settled.
    for (const Eigen::Vector3d& p : positions)
        if (!p.allFinite()) throw_bad_input(m.name, "a posed vertex is not finite");
    if (&positions != &vertices_) vertices_.assign(positions.begin(), positions.end());
}

void DeformingModel::follow() {
    const TriangleMesh& m = mesh_->imported.mesh;
    // Degenerate faces as import decided them, at the bind pose's size.
    detail::angle_weighted_normals(vertices_, m.triangles, detail::degenerate_twice_area(diagonal_), m.is_copy,
                                   vertex_normals_, normal_valid_);
    vertex_normals_stale_ = false;
    // Snapped normals, once a vertex or face (a face's samples share its normal): a face squeezed
    // flat has none of its own, and takes its corners'; without any, a sample keeps the bind's.
    const size_t nv = vertices_.size(), nf = m.triangles.size();
    snapped_.resize(nv + nf);
    snapped_ok_.assign(nv + nf, 0);
    const size_t n = source_.size();
    points_.resize(n), normals_.resize(n);
    const size_t jobs = size_t(threads_);
    // Each job a share of the vertices, faces and samples; the samples read only the normals.
    detail::parallel_for(jobs, threads_, [&](size_t job, int) {
        for (size_t v = nv * job / jobs; v < nv * (job + 1) / jobs; ++v)
            if (normal_valid_[v]) snapped_[v] = stored(vertex_normals_[v]), snapped_ok_[v] = 1;
        for (size_t f = nf * job / jobs; f < nf * (job + 1) / jobs; ++f) {
            if (!face_sampled_[f]) continue;
            const Triangle& t = m.triangles[f];
            Eigen::Vector3d normal = (vertices_[t[1]] - vertices_[t[0]]).cross(vertices_[t[2]] - vertices_[t[0]]);
            if (!(normal.norm() > 0)) normal = vertex_normals_[t[0]] + vertex_normals_[t[1]] + vertex_normals_[t[2]];
            if (normal.norm() > 0) snapped_[nv + f] = stored(normal.normalized()), snapped_ok_[nv + f] = 1;
        }
    }, tasks_);
    detail::parallel_for(jobs, threads_, [&](size_t job, int) {
        for (size_t i = n * job / jobs; i < n * (job + 1) / jobs; ++i) {
            const uint32_t src = source_[i] & kMaxSourceIndex;
            const size_t k = (source_[i] & kFaceSampleBit) ? nv + src : src;
            place_sample(i, snapped_ok_[k] ? &snapped_[k] : nullptr);
        }
    }, tasks_);
    model_.follow_surface(vertices_, points_, normals_, triangles_, threads_, tasks_);
    model_.pending_.pose = nullptr;
}

void DeformingModel::place_sample(size_t i, const Eigen::Vector3f* snapped) {
    const TriangleMesh& m = mesh_->imported.mesh;
    const uint32_t src = source_[i] & kMaxSourceIndex;
    Eigen::Vector3d at;
    if (source_[i] & kFaceSampleBit) {
        const Triangle& t = m.triangles[src];
        const Eigen::Vector3d& w = barycentric_[i];
        at = w[0] * vertices_[t[0]] + w[1] * vertices_[t[1]] + w[2] * vertices_[t[2]];
    } else {
        at = vertices_[src];
    }
    // The stored point plus how far its surface point moved: the bind pose gives the
    // document's spheres bit for bit.
    points_[i] = bind_points_[i] + (at - bind_at_[i]).cast<float>();
    normals_[i] = snapped ? *snapped : bind_normals_[i];
}

void DeformingModel::pose_lazily(const Clip* clip, double time) { pose_lazily_on(clip_vertices(clip, time)); }

void DeformingModel::pose_lazily_on(const std::vector<Eigen::Vector3d>& positions) {
    take_vertices(positions);
    if (!lazy_checked_) {
        std::vector<double> offset(source_.size());
        for (size_t i = 0; i < source_.size(); ++i)
            offset[i] = (bind_points_[i].cast<double>() - (bind_at_[i] - model_.origin())).norm() +
                        1e-6 * bind_points_[i].cast<double>().norm();
        lazy_layout_ = detail::make_lazy_layout(model_.tree(), mesh_->imported.mesh, source_, barycentric_, offset,
                                                lazy_region_);
        lazy_checked_ = true;
    }
    if (!lazy_layout_) return follow();
    if (!lazy_ || lazy_.use_count() > 1 || lazy_->owner() != this)
        lazy_ = std::make_shared<detail::LazyPose>(this, lazy_layout_);
    lazy_->begin();
}

void DeformingModel::settle() { detail::settle(model_); }

void DeformingModel::set_tight_refit(bool tight) {
    settle(); // a pending pose finishes with the rule it started with
    model_.tree_.set_tight_refit(tight);
}

void DeformingModel::set_lazy_region(uint32_t samples) {
    lazy_region_ = std::max<uint32_t>(1, samples);
    settle();
    lazy_checked_ = false, lazy_layout_.reset(), lazy_.reset();
}

const std::vector<Eigen::Vector3d>& DeformingModel::vertex_normals() const {
    detail::settle(model_);
    if (vertex_normals_stale_) {
        const TriangleMesh& m = mesh_->imported.mesh;
        detail::angle_weighted_normals(vertices_, m.triangles, detail::degenerate_twice_area(diagonal_), m.is_copy,
                                       vertex_normals_, normal_valid_);
        vertex_normals_stale_ = false;
    }
    return vertex_normals_;
}

const std::vector<Eigen::Vector3f>& DeformingModel::sample_points() const {
    detail::settle(model_);
    return points_;
}

} // namespace spt
