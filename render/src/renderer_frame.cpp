// One view of a frame: the pinned GL state, the order of the draw passes, the bounds they share.
#include "renderer_impl.hpp"

namespace spt::render {
namespace {

// The box around the eight corners of `b` moved by `pose`.
Bounds transformed(const Bounds& b, const Eigen::Affine3f& pose) {
    Bounds out;
    if (b.empty()) return out;
    for (int i = 0; i < 8; ++i) {
        const Eigen::Vector3f corner((i & 1) ? b.max.x() : b.min.x(), (i & 2) ? b.max.y() : b.min.y(),
                                     (i & 4) ? b.max.z() : b.min.z());
        out.add(pose * corner);
    }
    return out;
}

} // namespace

Bounds Renderer::Impl::solid_bounds(const Frame& f) const {
    Bounds b;
    for (const MeshItem& m : f.meshes) {
        auto it = meshes.find(m.mesh.id);
        if (it != meshes.end()) b.add(transformed(it->second.bounds, m.pose));
    }
    for (const SphereItem& s : f.spheres) {
        auto it = sphere_sets.find(s.spheres.id);
        if (it != sphere_sets.end()) b.add(transformed(it->second.bounds, s.pose));
    }
    return b;
}

void Renderer::Impl::draw(const Frame& f, const Camera& cam, const Viewport& vp, GLuint fbo, const Bounds& b) {
    if (vp.width <= 0 || vp.height <= 0) return;
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.Viewport(vp.x, vp.y, vp.width, vp.height);
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(vp.x, vp.y, vp.width, vp.height);
    // Pinned for byte-identical output. Multisampling is left to the target: the
    // off-screen framebuffers are single-sample, a window may want it.
    gl.Disable(GL_DITHER);
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.DepthMask(GL_TRUE);
    gl.ClearColor(f.background.r, f.background.g, f.background.b, f.background.a);
    gl.ClearDepth(1.0);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LEQUAL);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_BLEND);
    gl.Enable(GL_PROGRAM_POINT_SIZE);
    gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

    view = cam.view_matrix();
    proj = cam.projection_matrix(float(vp.width) / float(vp.height));
    ortho = !cam.perspective();

    if (f.grid) {
        const Bounds solid = solid_bounds(f);
        draw_grid(b, solid.empty() ? b.min.y() : solid.min.y());
    }
    draw_meshes(f, false);
    draw_sphere_items(f);
    draw_collision_spheres(f.collision);
    draw_trails(f);

    gl.Enable(GL_BLEND);
    draw_wire_spheres(f, false);
    gl.DepthMask(GL_FALSE);
    gl.Enable(GL_CULL_FACE);
    gl.CullFace(GL_BACK);
    gl.FrontFace(GL_CCW);
    draw_meshes(f, true);
    gl.Disable(GL_CULL_FACE);

    // Marks that must stay visible whatever covers them.
    gl.Disable(GL_DEPTH_TEST);
    draw_wire_spheres(f, true);
    draw_collision_marks(f.collision, b);
    if (f.axes) draw_gizmo(vp);

    gl.DepthMask(GL_TRUE);
    gl.Disable(GL_BLEND);
    gl.Disable(GL_SCISSOR_TEST);
    gl.BindVertexArray(0);
    gl.UseProgram(0);
    check_gl(gl, "Renderer::draw");
}

} // namespace spt::render
