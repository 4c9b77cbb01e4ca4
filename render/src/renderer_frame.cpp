// One view of a frame: the pinned GL state, the order of the draw passes into the layers, the bounds they share.
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

// The passes of one view into the cached layers (width x height pixels): the opaque ones into the
// base, the see-through ones and the marks on top into the overlay.
void Renderer::Impl::draw_layers(const Frame& f, const Camera& cam, int width, int height, const Bounds& b) {
    resize_layers(width, height);
    const FrameLayers& l = layers;
    const GLenum base_only[4] = {GL_COLOR_ATTACHMENT0, GL_NONE, GL_NONE, GL_NONE};
    const GLenum base_all[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
    const GLenum overlay[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    const Viewport vp{0, 0, width, height};
    gl.BindFramebuffer(GL_FRAMEBUFFER, l.base_fbo);
    gl.Viewport(0, 0, width, height);
    gl.Disable(GL_SCISSOR_TEST);
    // Pinned for byte-identical output; the layers are single-sample.
    gl.Disable(GL_DITHER);
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.DepthMask(GL_TRUE);
    gl.DrawBuffers(4, base_all);
    const float background[4] = {f.background.r, f.background.g, f.background.b, f.background.a};
    const float zero[4] = {0, 0, 0, 0}, one[4] = {1, 1, 1, 1};
    const GLuint no_id[4] = {0, 0, 0, 0};
    gl.ClearBufferfv(GL_COLOR, 0, background);
    gl.ClearBufferfv(GL_COLOR, 1, zero);
    gl.ClearBufferfv(GL_COLOR, 2, zero);
    gl.ClearBufferuiv(GL_COLOR, 3, no_id);
    gl.ClearBufferfv(GL_DEPTH, 0, one);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LEQUAL);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_BLEND);
    gl.Enable(GL_PROGRAM_POINT_SIZE);
    gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

    view = cam.view_matrix();
    proj = cam.projection_matrix(float(width) / float(height));
    ortho = !cam.perspective();

    gl.DrawBuffers(4, base_only);
    if (f.grid) {
        const Bounds solid = solid_bounds(f);
        draw_grid(b, solid.empty() ? b.min.y() : solid.min.y());
    }
    draw_meshes(f, false);
    // Spheres write their ids and both mark colours; the collision pairs' spheres write id 0.
    gl.DrawBuffers(4, base_all);
    splat.begin(width, height, proj, ortho);
    splat_sphere_items(f);
    splat_collision_spheres(f.collision);
    draw_splat();
    gl.DrawBuffers(4, base_only);
    draw_trails(f);

    // The overlay: cover "over" nothing (premultiplied) and transmittance, blended pass by pass.
    gl.BindFramebuffer(GL_FRAMEBUFFER, l.overlay_fbo);
    gl.DrawBuffers(2, overlay);
    gl.ClearBufferfv(GL_COLOR, 0, zero);
    gl.ClearBufferfv(GL_COLOR, 1, one);
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
    gl.BindVertexArray(0);
    gl.UseProgram(0);
}

void Renderer::Impl::draw(const Frame& f, const Camera& cam, const Viewport& vp, GLuint fbo, const Bounds& b) {
    if (vp.width <= 0 || vp.height <= 0) return;
    switch (reuse(f, cam, vp.width, vp.height)) {
    case Reuse::None:
        layers.valid = false, layers.finals = false;
        draw_layers(f, cam, vp.width, vp.height, b);
        remember(f, cam);
        last_kind = DrawKind::Full;
        break;
    case Reuse::Recolour:
        marks_seen();
        last_kind = DrawKind::Recoloured;
        break;
    case Reuse::Composite: last_kind = DrawKind::Composited; break;
    }
    // A frame drawn again with its marks (changed or not) chooses between its two final
    // pictures; a new frame is put together once, without making them (its base already holds
    // the spheres in the colours of their current marks).
    if (last_kind != DrawKind::Full && layers.mark_set)
        recolour(vp, fbo);
    else
        composite(vp, fbo);
    check_gl(gl, "Renderer::draw");
}

} // namespace spt::render
