// The four view cameras: orientation, view and projection matrices, projection to window pixels, fitting.
#include "spt/render/camera.hpp"
#include <algorithm>
#include <cmath>

namespace spt::render {
namespace {

constexpr float kPi = 3.14159265358979f;
float radians(float deg) { return deg * kPi / 180.0f; }

// Room around the fitted sphere so silhouettes do not touch the border.
constexpr float kFitMargin = 1.08f;

} // namespace

const char* view_name(View view) {
    switch (view) {
    case View::Top: return "top";
    case View::Front: return "front";
    case View::Side: return "side";
    case View::Camera: return "camera";
    }
    return "camera";
}

Eigen::Vector3f Camera::back() const {
    switch (view) {
    case View::Top: return {0, 1, 0};
    case View::Front: return {0, 0, 1};
    case View::Side: return {1, 0, 0};
    case View::Camera: break;
    }
    const float y = radians(yaw), p = radians(pitch);
    return {std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y)};
}

Eigen::Vector3f Camera::up() const {
    if (view == View::Top) return {0, 0, -1};
    if (view != View::Camera) return {0, 1, 0};
    const Eigen::Vector3f b = back();
    const Eigen::Vector3f right = Eigen::Vector3f::UnitY().cross(b);
    // Straight down or up: keep the top view's orientation.
    if (right.squaredNorm() < 1e-10f) return {0, 0, b.y() > 0 ? -1.0f : 1.0f};
    return b.cross(right.normalized()).normalized();
}

Eigen::Vector3f Camera::eye() const {
    const float r = std::max(radius, 1e-6f);
    if (!perspective()) return target + back() * (3.0f * r);
    const float dist = r / std::sin(radians(fov_y) * 0.5f);
    return target + back() * dist;
}

Eigen::Matrix4f Camera::view_matrix() const {
    const Eigen::Vector3f z = back();
    const Eigen::Vector3f y = up();
    const Eigen::Vector3f x = y.cross(z).normalized();
    const Eigen::Vector3f e = eye();
    Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
    m.block<1, 3>(0, 0) = x.transpose();
    m.block<1, 3>(1, 0) = y.transpose();
    m.block<1, 3>(2, 0) = z.transpose();
    m(0, 3) = -x.dot(e), m(1, 3) = -y.dot(e), m(2, 3) = -z.dot(e);
    return m;
}

Eigen::Matrix4f Camera::projection_matrix(float aspect) const {
    const float r = std::max(radius, 1e-6f);
    const float a = std::max(aspect, 1e-3f);
    const float z = std::max(zoom, 1e-3f);
    Eigen::Matrix4f p = Eigen::Matrix4f::Zero();
    if (!perspective()) {
        // Half extents so the sphere fits the shorter side.
        const float half_h = (a >= 1 ? r : r / a) / z;
        const float half_w = half_h * a;
        // Eye is 3r back; depth holds [r, 5r] from it, more than the sphere and the grid.
        const float n = 0.5f * r, f = 6.0f * r;
        p(0, 0) = 1.0f / half_w;
        p(1, 1) = 1.0f / half_h;
        p(2, 2) = -2.0f / (f - n);
        p(2, 3) = -(f + n) / (f - n);
        p(3, 3) = 1.0f;
        return p;
    }
    const float dist = r / std::sin(radians(fov_y) * 0.5f);
    // The fitted sphere spans fov_y vertically; for a portrait viewport widen to fit the width.
    float t = std::tan(radians(fov_y) * 0.5f) / z;
    if (a < 1) t /= a;
    const float n = std::max(dist - 2.5f * r, dist * 0.02f), f = dist + 2.5f * r;
    p(0, 0) = 1.0f / (t * a);
    p(1, 1) = 1.0f / t;
    p(2, 2) = -(f + n) / (f - n);
    p(2, 3) = -2.0f * f * n / (f - n);
    p(3, 2) = -1.0f;
    return p;
}

Eigen::Vector3f Camera::project(const Eigen::Vector3f& p, int width, int height) const {
    const float w = float(std::max(width, 1)), h = float(std::max(height, 1));
    const Eigen::Vector4f clip = projection_matrix(w / h) * view_matrix() * p.homogeneous();
    const Eigen::Vector3f ndc = clip.head<3>() / clip.w();
    return {(ndc.x() + 1.0f) * 0.5f * w, (ndc.y() + 1.0f) * 0.5f * h, (ndc.z() + 1.0f) * 0.5f};
}

Camera fit_camera(View view, const Bounds& bounds) {
    Camera c;
    c.view = view;
    c.target = bounds.center();
    c.radius = std::max(bounds.radius(), 1e-6f) * kFitMargin;
    return c;
}

std::array<Camera, 4> fit_quad_cameras(const Bounds& bounds) {
    return {fit_camera(View::Top, bounds), fit_camera(View::Front, bounds), fit_camera(View::Side, bounds),
            fit_camera(View::Camera, bounds)};
}

} // namespace spt::render
