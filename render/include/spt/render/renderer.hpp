#pragma once
/// The OpenGL 3.3 core renderer shared by the editor, the viewer and `spt render`.
/// It needs only a current context and a loader; it never calls GL directly.
/// Every method must be called with the same context current.
#include "spt/mesh.hpp"
#include "spt/render/camera.hpp"
#include "spt/render/frame.hpp"
#include "spt/render/gl_loader.hpp"
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace spt::render {

/// A rectangle of the target framebuffer in pixels, origin at the lower left (GL convention).
struct Viewport {
    int x = 0;      ///< left edge, pixels from the framebuffer's left
    int y = 0;      ///< bottom edge, pixels from the framebuffer's bottom row (GL window coordinates)
    int width = 0;  ///< pixels; <= 0 draws nothing
    int height = 0; ///< pixels; <= 0 draws nothing
};

/// The four viewports of the quad layout inside a width x height target (pixels), in
/// fit_quad_cameras order: top (upper left), front (upper right), side (lower
/// left), camera (lower right), with a one-pixel separator between them.
std::array<Viewport, 4> quad_viewports(int width, int height);

/// How Renderer::draw made its last picture.
enum class DrawKind {
    Full,        ///< every pass drawn into the layers, then composited
    Recoloured,  ///< the cached layers composited with the marked spheres' pixels in their new colour
    Composited,  ///< the cached layers composited again
};

/// Draws frames into the current context's framebuffers.
class Renderer {
public:
    /// Loads GL through `load` and compiles the shaders; the context must be current.
    explicit Renderer(const ProcLoader& load);
    /// Frees every GL object; the context must still be current.
    ~Renderer();
    /// Not copyable: it owns GL objects of one context.
    Renderer(const Renderer&) = delete;
    /// Not copyable: it owns GL objects of one context.
    Renderer& operator=(const Renderer&) = delete;

    /// Uploads a mesh (positions and vertex normals, object frame, model units) and returns
    /// its handle; throws std::invalid_argument naming the mesh if a triangle index is out of range.
    /// Positions are uploaded relative to `origin` (subtracted in double); draw the mesh with a
    /// pose that adds it back (local_frame). Far from the origin float keeps a mesh's detail
    /// only so: at 10^6 its spacing is 1/16 of a unit.
    MeshHandle add_mesh(const TriangleMesh& mesh, const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());
    /// An origin for add_mesh when no model's local origin is at hand: zero for a mesh near the
    /// origin (its picture as before), the centre of its box for one far out (TriangleMesh::far_for_float).
    static Eigen::Vector3d drawing_origin(const TriangleMesh& mesh);
    /// Frees an uploaded mesh; the handle becomes invalid. An unknown handle is ignored.
    void remove_mesh(MeshHandle mesh);
    /// Replaces an uploaded mesh's vertex positions and normals (a deformed pose: the same
    /// vertices and triangles, moved), relative to `origin` as add_mesh takes it; throws
    /// std::invalid_argument for an unknown handle or another vertex count.
    void update_mesh(MeshHandle mesh, const std::vector<Eigen::Vector3d>& positions,
                     const std::vector<Eigen::Vector3d>& normals, const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());
    /// Uploads solid spheres (object frame, model units) for instanced drawing and returns the set's handle.
    SphereSetHandle add_spheres(const std::vector<SphereInstance>& spheres);
    /// Replaces the spheres of a set (e.g. new colours after a split) and unmarks them all; throws
    /// std::invalid_argument for an unknown handle.
    void update_spheres(SphereSetHandle set, const std::vector<SphereInstance>& spheres);
    /// Marks spheres `marked` (indices into the set, any order; out-of-range ones ignored) and
    /// unmarks the rest; SphereItem::marked_color draws marked spheres in one colour (e.g. a
    /// selection) without a second set. Throws std::invalid_argument for an unknown handle.
    void set_sphere_marks(SphereSetHandle set, const std::vector<uint32_t>& marked);
    /// Frees an uploaded sphere set; an unknown handle is ignored.
    void remove_spheres(SphereSetHandle set);
    /// Number of spheres in a set (0 for an unknown handle).
    uint32_t sphere_count(SphereSetHandle set) const;

    /// World-frame box around everything `frame` shows (the grid excepted), model units.
    Bounds bounds(const Frame& frame) const;
    /// Writes every colour pixel of `viewport` of `framebuffer` (a GL framebuffer object name, such
    /// as OffscreenContext::framebuffer() or QOpenGLWidget::defaultFramebufferObject(); its depth
    /// buffer is left alone) with `frame` drawn through `camera`. Throws std::invalid_argument for
    /// an unknown mesh or sphere-set handle in the frame. The frame is drawn into layers (about 30
    /// bytes a pixel) kept until the next draw and composited into the viewport; a draw of the same frame, camera and viewport
    /// size (its uploads unchanged) only composites them again, also when its only change is
    /// set_sphere_marks (the layers keep both colours of each marked sphere's pixels): the same
    /// pixels as a full draw, at a cost that depends on the viewport's size alone.
    void draw(const Frame& frame, const Camera& camera, const Viewport& viewport, uint32_t framebuffer);
    /// Draws the 2x2 layout (cameras in fit_quad_cameras order) over a width x height target
    /// (pixels); the one-pixel separators are the frame's background darkened.
    void draw_quad(const Frame& frame, const std::array<Camera, 4>& cameras, int width, int height,
                   uint32_t framebuffer);

    /// How the last draw() (or the last view of draw_quad()) was made.
    DrawKind last_draw_kind() const;

    /// GL_RENDERER of the context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    const std::string& gl_renderer() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace spt::render
