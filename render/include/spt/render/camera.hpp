#pragma once
/// Cameras of the four editor views. World frame: +Y is up, the ground is the
/// X-Z plane. Top looks down -Y (+X right, -Z up on screen); front looks down -Z
/// from +Z (+X right, +Y up); side looks down -X from +X (-Z right, +Y up); the
/// perspective camera orbits the target by yaw about +Y and pitch above the ground.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>

namespace spt::render {

/// The four views of the paper's sampling tool (Fig. 6).
enum class View {
    Top,    ///< orthographic, looking down -Y: +X right, -Z up on screen
    Front,  ///< orthographic, looking down -Z from +Z: +X right, +Y up
    Side,   ///< orthographic, looking down -X from +X: -Z right, +Y up
    Camera, ///< perspective, orbiting the target by yaw and pitch
};

/// Lower-case name of a view: "top", "front", "side", "camera".
const char* view_name(View view);

/// Axis-aligned box in the frame of the points added (the world for the renderer and
/// the cameras), model units; empty when min > max.
struct Bounds {
    Eigen::Vector3f min = Eigen::Vector3f::Constant(1e30f);  ///< lowest corner, model units
    Eigen::Vector3f max = Eigen::Vector3f::Constant(-1e30f); ///< highest corner, model units
    /// True if nothing has been added.
    bool empty() const { return (min.array() > max.array()).any(); }
    /// Grows the box to hold p.
    void add(const Eigen::Vector3f& p) { min = min.cwiseMin(p), max = max.cwiseMax(p); }
    /// Grows the box to hold the sphere of centre c and radius r.
    void add_sphere(const Eigen::Vector3f& c, float r) { add(c - Eigen::Vector3f::Constant(r)), add(c + Eigen::Vector3f::Constant(r)); }
    /// Grows the box to hold another box.
    void add(const Bounds& b) { if (!b.empty()) add(b.min), add(b.max); }
    /// Centre of the box (origin if empty).
    Eigen::Vector3f center() const { return empty() ? Eigen::Vector3f::Zero() : Eigen::Vector3f(0.5f * (min + max)); }
    /// Radius of the sphere around center() that holds the box (0 if empty).
    float radius() const { return empty() ? 0.0f : 0.5f * (max - min).norm(); }
};

/// A view camera. World frame; lengths are model units, angles degrees.
struct Camera {
    View view = View::Camera; ///< which view: the three orthographic ones or the perspective camera
    Eigen::Vector3f target = Eigen::Vector3f::Zero(); ///< world point at the centre of the view
    float radius = 1;       ///< radius of the world sphere around target kept in view and in depth range
    float zoom = 1;         ///< > 1 magnifies
    float yaw = 35;         ///< perspective: rotation about +Y, from looking down -Z
    float pitch = 25;       ///< perspective: elevation above the ground plane
    float fov_y = 35;       ///< perspective: vertical field of view

    /// True for the perspective camera, false for the orthographic views.
    bool perspective() const { return view == View::Camera; }
    /// Unit vector from the target towards the eye, world frame.
    Eigen::Vector3f back() const;
    /// Unit vector that is up on screen, world frame.
    Eigen::Vector3f up() const;
    /// Eye position, world frame; for the orthographic views a point far enough back
    /// (3 radii) to see the whole sphere.
    Eigen::Vector3f eye() const;
    /// World-to-eye transform (OpenGL convention: the eye looks down its -Z).
    Eigen::Matrix4f view_matrix() const;
    /// Eye-to-clip transform for a viewport of width/height `aspect`; the sphere
    /// (target, radius) fits the shorter side and lies inside the depth range.
    Eigen::Matrix4f projection_matrix(float aspect) const;
    /// Where world point p lands in a width x height view: x, y in pixels from the
    /// lower-left corner (GL window coordinates), z the depth in [0, 1]. For
    /// selecting vertices inside a dragged rectangle.
    Eigen::Vector3f project(const Eigen::Vector3f& p, int width, int height) const;
};

/// A camera of `view` that frames `bounds` (world frame): the box's bounding sphere, with an 8% margin.
Camera fit_camera(View view, const Bounds& bounds);

/// The four views fitted to `bounds` (world frame), in quad-layout order: top, front, side, camera.
std::array<Camera, 4> fit_quad_cameras(const Bounds& bounds);

} // namespace spt::render
