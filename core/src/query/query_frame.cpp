// Checks and set-up shared by every query: poses, the far-apart test, B's frame in A's, scratch sizes.
#include "query/model_access.hpp"
#include "query/query_run.hpp"
#include "spt/error.hpp"
#include "query/exact_data.hpp"
#include <algorithm>
#include <cmath>

namespace spt {

void check_pose(const Pose& p, const char* what) {
    if (!p.translation.allFinite())
        throw Error(ErrorKind::BadInput, std::string(what) + ": the translation is not finite");
    const Eigen::Vector4d q = p.rotation.coeffs();
    if (!q.allFinite() || q.cwiseAbs().maxCoeff() == 0)
        throw Error(ErrorKind::BadInput, std::string(what) + ": the rotation quaternion is zero or not finite");
}

Eigen::Quaterniond unit_rotation(const Eigen::Quaterniond& q) {
    if (std::abs(q.squaredNorm() - 1) <= 1e-12) return q; // unit already: leave the bits alone
    return unit_quaternion(q);
}

double model_radius(const CollisionModel& m) {
    double r = m.extent();
    if (!m.tree().nodes().empty()) {
        const CompactNode& root = m.tree().nodes()[0];
        const double c = Eigen::Vector3d(root.center[0], root.center[1], root.center[2]).norm();
        r = std::max({r, c + root.bv_radius, c + (m.bounds_reach().empty() ? 0.0 : m.bounds_reach()[0])});
    }
    return r;
}

bool cannot_meet(const CollisionModel& a, const CollisionModel& b, const Eigen::Vector3d& td, double inflate) {
    // Every piece of B lies within model_radius(b) of td, every piece of A within
    // model_radius(a) of 0: a larger gap on one axis means no pair can meet. Slack of
    // 1e-6 for the rounding of the radii; NaN never happens (poses are checked).
    const double reach = (model_radius(a) + model_radius(b) + std::max(0.0, inflate)) * (1 + 1e-6);
    return !(td.cwiseAbs().maxCoeff() <= reach);
}

QueryFrame::QueryFrame(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a, float inflate) {
    check_pose(b_in_a, "pose of B in A's frame");
    Rd = unit_rotation(b_in_a.rotation).toRotationMatrix();
    td = local_translation(a, b, Rd, b_in_a.translation);
    apart = cannot_meet(a, b, td, inflate); // also when td overflowed to infinity
    if (!td.allFinite()) td = clamp_far(td); // far, finite, same direction
    R = Rd.cast<float>();
    t = td.cast<float>();
    // Float moves of B's centres are off by a few ulps of |t| + |x|; pruning and the
    // exact level's prefilters add this so rounding can never prune a real contact.
    // Every term is local (the pair's offset and the models' sizes), so the margin does
    // not grow with the distance from any origin. |t| bounded by its 1-norm: no square
    // root on the way to the first test.
    margin = float(1e-5 * (td.cwiseAbs().sum() + a.extent() + b.extent()));
}

void prepare_scratch(detail::ScratchBuffers& s, const CollisionModel& a, const CollisionModel& b, bool exact) {
    const size_t la = a.max_leaf() + 8, lb = b.max_leaf() + 8;
    if (s.d2.size() < la * lb) s.d2.resize(la * lb);
    if (s.moved_b.size() < 3 * lb) s.moved_b.resize(3 * lb);
    if (s.ga.size() < 3 * la) s.ga.resize(3 * la), s.ia.resize(la);
    if (s.gb.size() < 3 * lb) s.gb.resize(3 * lb), s.ib.resize(lb);
    const size_t nodes = b.tree().nodes().size();
    s.leaf_slot = 3 * lb <= detail::kLeafCacheFloats / std::max<size_t>(nodes, 1) ? 3 * lb : 0, s.leaf_column = lb;
    if (s.leaf_slot) {
        if (s.leaf_cache.size() < nodes * s.leaf_slot) s.leaf_cache.resize(nodes * s.leaf_slot);
        if (s.leaf_stamp.size() < nodes) s.leaf_stamp.resize(nodes, 0);
    }
    s.group_cache = nodes * sizeof(detail::NodeGroup) <= detail::kLeafCacheFloats * sizeof(float);
    if (s.group_cache && s.b_groups.size() < nodes) s.b_groups.resize(nodes), s.b_group_stamp.resize(nodes, 0);
    if (s.stack.capacity() < 256) s.stack.reserve(256);
    if (s.visits.size() < 256) s.visits.resize(256);
    // B's vertices: the exact level's triangles, and the faces of two-sided spheres at the sphere level.
    if (exact || !detail::exact_of(b).sphere_source.empty()) {
        const size_t nv = detail::exact_of(b).positions.size();
        if (s.bverts.size() < nv) s.bverts.resize(nv), s.vert_stamp.resize(nv, 0);
    }
    if (exact) {
        const size_t nt = detail::exact_of(b).triangles.size();
        if (s.btri.size() < 4 * nt) s.btri.resize(4 * nt), s.tri_stamp.resize(nt, 0);
        if (s.bplane.size() < 4 * nt) s.bplane.resize(4 * nt), s.plane_stamp.resize(nt, 0);
        const size_t nn = detail::exact_of(b).tri_nodes.size();
        if (s.bboxes.size() < nn) s.bboxes.resize(nn), s.bbox_stamp.resize(nn, 0);
        if (s.bcentres.size() < nn) s.bcentres.resize(nn), s.bcentre_stamp.resize(nn, 0);
    }
    if (++s.epoch == 0) { // wrapped: forget every stamp
        std::fill(s.vert_stamp.begin(), s.vert_stamp.end(), 0);
        std::fill(s.tri_stamp.begin(), s.tri_stamp.end(), 0);
        std::fill(s.plane_stamp.begin(), s.plane_stamp.end(), 0);
        std::fill(s.bbox_stamp.begin(), s.bbox_stamp.end(), 0);
        std::fill(s.bcentre_stamp.begin(), s.bcentre_stamp.end(), 0);
        std::fill(s.leaf_stamp.begin(), s.leaf_stamp.end(), 0);
        std::fill(s.b_group_stamp.begin(), s.b_group_stamp.end(), 0);
        s.epoch = 1;
    }
    s.pairs.clear();
    s.tri_pairs.clear();
}

} // namespace spt
