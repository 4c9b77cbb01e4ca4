// Pan, zoom about the cursor and orbit for the view cameras.
#include "view_navigation.hpp"
#include <algorithm>
#include <cmath>

namespace spt::editor {
namespace {

constexpr float kPi = 3.14159265358979f;

// Half the height of the view in world units at the target (orthographic extent, or the
// perspective frustum's at the target's distance).
float half_height(const render::Camera& c, int width, int height) {
    const float aspect = float(std::max(width, 1)) / float(std::max(height, 1));
    const float r = std::max(c.radius, 1e-6f);
    if (!c.perspective()) return (aspect >= 1 ? r : r / aspect) / std::max(c.zoom, 1e-3f);
    const float dist = (c.eye() - c.target).norm();
    float t = std::tan(c.fov_y * kPi / 360.0f) / std::max(c.zoom, 1e-3f);
    if (aspect < 1) t /= aspect;
    return dist * t;
}

} // namespace

float pixel_size(const render::Camera& camera, int width, int height) {
    return 2.0f * half_height(camera, width, height) / float(std::max(height, 1));
}

void pan(render::Camera& camera, float dx, float dy, int width, int height) {
    const float s = pixel_size(camera, width, height);
    const Eigen::Vector3f up = camera.up();
    const Eigen::Vector3f right = up.cross(camera.back()).normalized();
    camera.target += -dx * s * right + dy * s * up;
}

void zoom_about(render::Camera& camera, float factor, float x, float y, int width, int height) {
    if (camera.perspective()) {
        camera.zoom = std::clamp(camera.zoom * factor, 0.05f, 1e4f);
        return;
    }
    // Offset of the cursor from the view centre in world units, before and after.
    const float cx = x - 0.5f * float(width), cy = 0.5f * float(height) - y;
    const float before = pixel_size(camera, width, height);
    camera.zoom = std::clamp(camera.zoom * factor, 0.05f, 1e4f);
    const float after = pixel_size(camera, width, height);
    const Eigen::Vector3f up = camera.up();
    const Eigen::Vector3f right = up.cross(camera.back()).normalized();
    camera.target += (before - after) * (cx * right + cy * up);
}

void orbit(render::Camera& camera, float dx, float dy) {
    if (!camera.perspective()) return;
    camera.yaw = std::fmod(camera.yaw - 0.4f * dx, 360.0f);
    camera.pitch = std::clamp(camera.pitch + 0.4f * dy, -89.0f, 89.0f);
}

} // namespace spt::editor
