// Sampling keyframe tracks (keyframes.hpp).
#include "anim/keyframes.hpp"

namespace spt::detail {

Eigen::Vector3d sample_vector(const Track<Eigen::Vector3d>& track, double t) {
    const KeySpan p = find_span(track.times, t);
    const auto& v = track.values;
    if (p.span == 0 || track.interpolation == Interpolation::Step) return v[p.k];
    if (track.interpolation == Interpolation::CubicSpline)
        return hermite(v[p.k], track.out_tangents[p.k], v[p.k + 1], track.in_tangents[p.k + 1], p.s, p.span);
    return (1 - p.s) * v[p.k] + p.s * v[p.k + 1];
}

Eigen::Quaterniond sample_rotation(const Track<Eigen::Vector4d>& track, double t) {
    const KeySpan p = find_span(track.times, t);
    const auto& v = track.values;
    auto quat = [](const Eigen::Vector4d& q) { return Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()); };
    Eigen::Quaterniond q;
    if (p.span == 0 || track.interpolation == Interpolation::Step)
        q = quat(v[p.k]);
    else if (track.interpolation == Interpolation::CubicSpline)
        q = quat(hermite(v[p.k], track.out_tangents[p.k], v[p.k + 1], track.in_tangents[p.k + 1], p.s, p.span));
    else
        q = quat(v[p.k]).normalized().slerp(p.s, quat(v[p.k + 1]).normalized()); // Eigen takes the shorter arc
    const double n = q.norm();
    return n > 0 ? Eigen::Quaterniond(q.coeffs() / n) : Eigen::Quaterniond::Identity();
}

void sample_weights(const Track<std::vector<double>>& track, double t, size_t count, std::vector<double>& out) {
    out.assign(count, 0.0);
    const KeySpan p = find_span(track.times, t);
    const auto& v = track.values;
    for (size_t i = 0; i < count; ++i) {
        const double v0 = v[p.k][i];
        if (p.span == 0 || track.interpolation == Interpolation::Step) {
            out[i] = v0;
        } else if (track.interpolation == Interpolation::CubicSpline) {
            out[i] = hermite(v0, track.out_tangents[p.k][i], v[p.k + 1][i], track.in_tangents[p.k + 1][i], p.s, p.span);
        } else {
            out[i] = (1 - p.s) * v0 + p.s * v[p.k + 1][i];
        }
    }
}

} // namespace spt::detail
