#pragma once
/// Rigid poses in double precision. A pose maps an object's frame to the world:
/// x_world = rotation * x_object + translation. Queries run in one object's frame,
/// so the other object's pose is taken relative to it in double before any float.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace spt {

/// `q` scaled to unit length, however long or short it is: scaled by its largest component
/// first where its squared length would under- or overflow. A zero quaternion stays zero.
inline Eigen::Quaterniond unit_quaternion(const Eigen::Quaterniond& q) {
    const double big = q.coeffs().cwiseAbs().maxCoeff();
    if (big >= 1e-150 && big <= 1e150) return q.normalized();
    if (!(big > 0) || !std::isfinite(big)) return q;
    return Eigen::Quaterniond(Eigen::Vector4d(q.coeffs() / big)).normalized();
}

/// Rotation and translation of an object, object frame to world frame (model units).
struct Pose {
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity(); ///< unit quaternion
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();        ///< model units

    /// The identity pose.
    static Pose identity() { return {}; }
    /// Pose from a translation and a rotation (the quaternion is normalised).
    static Pose from(const Eigen::Vector3d& t, const Eigen::Quaterniond& q) { return {unit_quaternion(q), t}; }
    /// Maps a point of the object frame to the world frame.
    Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return rotation * p + translation; }
    /// Maps a direction of the object frame to the world frame.
    Eigen::Vector3d rotate(const Eigen::Vector3d& v) const { return rotation * v; }
    /// The inverse pose: world frame to object frame.
    Pose inverse() const {
        const Eigen::Quaterniond qi = rotation.conjugate();
        return {qi, -(qi * translation)};
    }
    /// Composition: (this * other).apply(p) == this->apply(other.apply(p)).
    Pose operator*(const Pose& o) const { return {(rotation * o.rotation).normalized(), rotation * o.translation + translation}; }
};

/// Largest length a relative translation keeps (model units): a longer one, or one that
/// overflowed, is shortened to this along its direction. Any model is far smaller (its
/// geometry is float), so the answer (apart) is the same and rotating it cannot overflow.
constexpr double kFarthest = 1e300;

/// `d` shortened to at most kFarthest on every axis, direction kept (an infinite component
/// gives the axis direction of the infinite components).
inline Eigen::Vector3d clamp_far(const Eigen::Vector3d& d) {
    const double big = d.cwiseAbs().maxCoeff();
    if (big <= kFarthest) return d;
    Eigen::Vector3d u = d;
    if (std::isinf(big))
        for (int k = 0; k < 3; ++k) u[k] = std::isinf(d[k]) ? std::copysign(1.0, d[k]) : 0.0;
    return u * (kFarthest / u.cwiseAbs().maxCoeff());
}

/// Pose of B expressed in A's frame: inverse(a) * b, computed in double.
inline Pose relative_pose(const Pose& a, const Pose& b) {
    // Subtract translations first so that two far-away poses keep their small difference exactly.
    const Eigen::Quaterniond qi = a.rotation.conjugate();
    return {(qi * b.rotation).normalized(), qi * clamp_far(b.translation - a.translation)};
}

/// Pose at t in [0, 1] on the motion from p0 to p1: translation linear, rotation slerp.
inline Pose interpolate(const Pose& p0, const Pose& p1, double t) {
    const Eigen::Vector3d d = p1.translation - p0.translation;
    // (1 - t) p0 + t p1 where the difference overflows: it cannot, and stays finite.
    const Eigen::Vector3d x = d.allFinite() ? Eigen::Vector3d(p0.translation + t * d)
                                            : Eigen::Vector3d((1 - t) * p0.translation + t * p1.translation);
    return {p0.rotation.slerp(t, p1.rotation).normalized(), x};
}

/// Angle (radians) swept by the rotation from p0 to p1 along the shortest arc.
inline double rotation_angle(const Pose& p0, const Pose& p1) {
    const double c = std::abs(p0.rotation.dot(p1.rotation));
    return 2.0 * std::acos(std::min(1.0, c));
}

} // namespace spt
