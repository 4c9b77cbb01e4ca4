#pragma once
/// What one frame shows, as plain data. The renderer owns only GPU copies of large
/// geometry (meshes, sphere sets, by handle); everything else is passed per frame,
/// so a caller such as the collision query can fill these structs directly.
/// Lengths are model units (the meshes' own); sizes on screen are framebuffer pixels.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

namespace spt::render {

/// An RGBA colour, each channel in [0, 1], written to the framebuffer as is (no gamma conversion).
struct Color {
    float r = 0; ///< red
    float g = 0; ///< green
    float b = 0; ///< blue
    float a = 1; ///< alpha, 1 opaque; blends for see-through meshes, wire spheres and collision marks
};

/// A sphere in some frame (world unless stated), model units.
struct Sphere {
    Eigen::Vector3f center = Eigen::Vector3f::Zero(); ///< centre, model units
    float radius = 0; ///< radius, model units
};

/// One instance of a solid sphere set: a sphere and its colour.
struct SphereInstance {
    Sphere sphere; ///< in the set's object frame, model units
    Color color;   ///< fill colour
};

/// Handle of a mesh uploaded with Renderer::add_mesh.
struct MeshHandle {
    uint32_t id = 0; ///< 0 is no mesh
};

/// Handle of a sphere set uploaded with Renderer::add_spheres.
struct SphereSetHandle {
    uint32_t id = 0; ///< 0 is no set
};

/// How a mesh's faces are lit.
enum class Shading {
    None,   ///< faces not drawn (wireframe or points only)
    Flat,   ///< one normal per face
    Smooth, ///< interpolated vertex normals (faces of vertices without a normal fall back to flat)
};

/// Appearance of one drawn mesh.
struct MeshStyle {
    Shading shading = Shading::Smooth;          ///< how the faces are lit, or not drawn
    Color color{0.72f, 0.74f, 0.78f, 1};        ///< face colour; its alpha is multiplied by opacity
    float opacity = 1;          ///< < 1: drawn after opaque geometry, blended, back faces culled
    bool wireframe = false;     ///< edges over the faces, one pixel wide
    Color wire_color{0.15f, 0.17f, 0.22f, 1};   ///< colour of the edges
    bool points = false;        ///< vertices as round points
    Color point_color{0.1f, 0.1f, 0.1f, 1};     ///< colour of the vertex points
    float point_size = 3;       ///< diameter of a vertex point, framebuffer pixels
};

/// The pose of geometry uploaded relative to `origin` (Renderer::add_mesh, sampling_spheres):
/// `pose` after a move by origin. The renderer composes it with the view in double, so the
/// large translations cancel there and the picture keeps the geometry's detail.
inline Eigen::Affine3f local_frame(const Eigen::Vector3d& origin, const Eigen::Affine3f& pose = Eigen::Affine3f::Identity()) {
    return pose * Eigen::Translation3f(origin.cast<float>());
}

/// A mesh placed in the world.
struct MeshItem {
    MeshHandle mesh;  ///< the uploaded mesh; an unknown handle makes Renderer::draw throw
    Eigen::Affine3f pose = Eigen::Affine3f::Identity(); ///< object to world; rigid (sphere radii are not scaled)
    MeshStyle style;  ///< how it looks
};

/// A range of an uploaded sphere set placed in the world. Items are drawn in
/// order with a less-or-equal depth test, so a later item over the same spheres
/// (e.g. one highlighted node) replaces their colour.
struct SphereItem {
    SphereSetHandle spheres;            ///< the uploaded set; an unknown handle makes Renderer::draw throw
    Eigen::Affine3f pose = Eigen::Affine3f::Identity(); ///< object to world; rigid
    uint32_t first = 0;                 ///< first sphere of the range (index into the set)
    uint32_t count = UINT32_MAX;        ///< number of spheres; clamped to the set
    std::optional<Color> color;         ///< replaces the per-sphere colours when set
    float fade = 0;                     ///< 0: as coloured; up to 1: mixed towards light grey (dimmed)
    std::optional<Color> marked_color;  ///< colour of the set's marked spheres (Renderer::set_sphere_marks) when set
};

/// A bounding sphere drawn as wire: its outline always on top, its three
/// axis-aligned great circles faint and depth-tested. World frame.
struct WireSphere {
    Sphere sphere;                       ///< world frame, model units
    Color color{0.1f, 0.45f, 0.95f, 1};  ///< outline colour; the great circles take 35% of its alpha
};

/// Two overlapping spheres of a collision with their contact. World frame.
struct SpherePair {
    Sphere a;                  ///< sphere of the first object, world frame
    Sphere b;                  ///< sphere of the second object, world frame
    Eigen::Vector3f contact = Eigen::Vector3f::Zero(); ///< contact point, world frame
    Eigen::Vector3f normal = Eigen::Vector3f::UnitY(); ///< unit contact normal, from a towards b
    float depth = 0;           ///< penetration depth, model units
};

/// A contact point in a colour of its own, with its normal: a point of a contact manifold
/// (scene overlay `manifold`). World frame.
struct ContactMark {
    Eigen::Vector3f point = Eigen::Vector3f::Zero();   ///< world frame, model units
    Eigen::Vector3f normal = Eigen::Vector3f::UnitY(); ///< unit; drawn from the point along it, as a pair's normal
    Color color{1.0f, 0.85f, 0.1f, 1};                 ///< the point's fill
};

/// Colliding sphere pairs as a query reports them (collision_overlay.hpp makes them):
/// the two objects' spheres depth-tested, contact points and normals on top of everything.
/// Marks (manifold points) are drawn on top too, after the pairs' contacts.
struct CollisionOverlay {
    std::vector<SpherePair> pairs;                 ///< world frame; empty draws nothing
    Color color_a{0.93f, 0.27f, 0.18f, 1};         ///< fill of the first object's spheres
    Color color_b{0.16f, 0.42f, 0.92f, 1};         ///< fill of the second object's spheres
    Color contact_color{1.0f, 0.85f, 0.1f, 1};     ///< contact points
    Color normal_color{0.05f, 0.05f, 0.05f, 1};    ///< normal segments, drawn from the contact along the normal
    float normal_length = 0;   ///< model units; 0: 4% of the scene's bounding diameter
    float contact_size = 6;    ///< diameter of a contact point, framebuffer pixels
    std::vector<ContactMark> marks;                ///< world frame; each point in its own colour, with its normal
    Color mark_normal_color{0.1f, 0.2f, 0.5f, 1};  ///< the marks' normal segments (as long as the pairs')
    float mark_size = 5;       ///< diameter of a mark, framebuffer pixels
};

/// A polyline through successive positions of a moving point. World frame.
struct Trail {
    std::vector<Eigen::Vector3f> points;   ///< world frame, model units, in order of time
    Color color{0.55f, 0.2f, 0.75f, 1};    ///< line colour
};

/// Everything one draw shows, drawn in the order of each vector.
struct Frame {
    std::vector<MeshItem> meshes;           ///< opaque ones first, then those with opacity < 1
    std::vector<SphereItem> spheres;        ///< sampling-sphere ranges (tree_overlay.hpp)
    std::vector<WireSphere> wire_spheres;   ///< bounding spheres (tree_overlay.hpp)
    CollisionOverlay collision;             ///< colliding sphere pairs, contacts, normals
    std::vector<Trail> trails;              ///< motion trails
    bool grid = true;   ///< ground grid under the scene (at its lowest Y)
    bool axes = true;   ///< axis gizmo in the lower-left corner of each view
    Color background{0.95f, 0.95f, 0.96f, 1}; ///< clear colour of each view; its alpha goes into the image
};

} // namespace spt::render
