// The sampling spheres of a view: ray-cast on the CPU (sphere_splat.hpp), then written into the
// base layer with their depth by one full-view pass.
#include "renderer_impl.hpp"
#include "spt/task_system.hpp"

namespace spt::render {
namespace {

// Uploads rows and columns [x0, x1) x [y0, y1) of a width-wide CPU image into `texture`.
void upload(const detail::GlFunctions& gl, GLuint texture, GLenum format, GLenum type, const void* pixels, int width,
            int x0, int y0, int x1, int y1) {
    gl.BindTexture(GL_TEXTURE_2D, texture);
    gl.PixelStorei(GL_UNPACK_ROW_LENGTH, width);
    gl.PixelStorei(GL_UNPACK_SKIP_PIXELS, x0);
    gl.PixelStorei(GL_UNPACK_SKIP_ROWS, y0);
    gl.TexSubImage2D(GL_TEXTURE_2D, 0, x0, y0, x1 - x0, y1 - y0, format, type, pixels);
}

} // namespace

void Renderer::Impl::draw_splat() {
    splat.run(spt::hardware_threads());
    const detail::SphereSplat& s = splat;
    if (s.x0() >= s.x1()) return;
    const FrameLayers& l = layers;
    const int x0 = s.x0(), y0 = s.y0(), x1 = s.x1(), y1 = s.y1(), w = s.width();
    gl.ActiveTexture(GL_TEXTURE0);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    upload(gl, l.splat_depth, GL_RED, GL_FLOAT, s.depth().data(), w, x0, y0, x1, y1);
    upload(gl, l.splat_plain, GL_RGBA, GL_UNSIGNED_BYTE, s.plain().data(), w, x0, y0, x1, y1);
    upload(gl, l.splat_marked, GL_RGBA, GL_UNSIGNED_BYTE, s.marked().data(), w, x0, y0, x1, y1);
    upload(gl, l.splat_ids, GL_RED_INTEGER, GL_UNSIGNED_INT, s.ids().data(), w, x0, y0, x1, y1);
    gl.PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    gl.PixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    gl.PixelStorei(GL_UNPACK_SKIP_ROWS, 0);

    const detail::SplatProgram& p = prog.splat;
    gl.UseProgram(p.id);
    bind_unit(0, GL_TEXTURE_2D, l.splat_depth, p.depth);
    bind_unit(1, GL_TEXTURE_2D, l.splat_plain, p.plain);
    bind_unit(2, GL_TEXTURE_2D, l.splat_marked, p.marked);
    bind_unit(3, GL_TEXTURE_2D, l.splat_ids, p.ids);
    // Into the bound base framebuffer with its depth test, over the covered pixels only.
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(x0, y0, x1 - x0, y1 - y0);
    end_full_view();
}

} // namespace spt::render
