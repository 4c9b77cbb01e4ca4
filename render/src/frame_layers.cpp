// The renderer's frame cache: the layer textures of the last frame, when a frame may reuse them,
// and compositing the layers (with the spheres' current marks) into the target.
#include "renderer_impl.hpp"
#include <algorithm>
#include <initializer_list>
#include <utility>
#include <stdexcept>

namespace spt::render {
namespace {

// A 2D texture of `width` x `height` read with texelFetch.
GLuint make_texture(const detail::GlFunctions& gl, GLint internal, GLenum format, GLenum type, int width, int height) {
    GLuint t = 0;
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_2D, t);
    gl.TexImage2D(GL_TEXTURE_2D, 0, internal, width, height, 0, format, type, nullptr);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

void attach(const detail::GlFunctions& gl, GLenum attachment, GLuint texture) {
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture, 0);
}

// A framebuffer with `attachments` (attachment point, texture); `complete` is cleared unless GL
// accepts it.
GLuint make_framebuffer(const detail::GlFunctions& gl, std::initializer_list<std::pair<GLenum, GLuint>> attachments,
                        bool& complete) {
    GLuint fbo = 0;
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    for (const auto& [point, texture] : attachments) attach(gl, point, texture);
    complete = complete && gl.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    return fbo;
}

} // namespace

void Renderer::Impl::bind_unit(int unit, GLenum target, GLuint texture, GLint sampler) {
    gl.ActiveTexture(GLenum(GL_TEXTURE0 + unit));
    gl.BindTexture(target, texture);
    gl.Uniform1i(sampler, unit);
}

void Renderer::Impl::free_layers() {
    FrameLayers& l = layers;
    GLuint fbos[] = {l.base_fbo, l.overlay_fbo, l.finals_fbo};
    GLuint textures[] = {l.base,           l.plain,        l.marked,      l.ids,          l.depth,
                         l.cover,          l.transmittance, l.unmarked_final, l.marked_final, l.splat_depth,
                         l.splat_plain,    l.splat_marked, l.splat_ids};
    if (l.base_fbo) {
        gl.DeleteFramebuffers(3, fbos);
        gl.DeleteTextures(13, textures);
    }
    const GLuint empty_vao = l.empty_vao, marks_texture = l.marks_texture;
    l = FrameLayers{};
    l.empty_vao = empty_vao, l.marks_texture = marks_texture;
}

void Renderer::Impl::resize_layers(int width, int height) {
    FrameLayers& l = layers;
    if (!l.empty_vao) gl.GenVertexArrays(1, &l.empty_vao);
    if (!l.marks_texture) gl.GenTextures(1, &l.marks_texture);
    if (l.base_fbo && l.width == width && l.height == height) return;
    free_layers();
    l.width = width, l.height = height;
    l.base = make_texture(gl, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    l.plain = make_texture(gl, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    l.marked = make_texture(gl, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    l.ids = make_texture(gl, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, width, height);
    l.depth = make_texture(gl, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, width, height);
    l.cover = make_texture(gl, GL_RGBA16F, GL_RGBA, GL_FLOAT, width, height);
    l.transmittance = make_texture(gl, GL_R16F, GL_RED, GL_FLOAT, width, height);
    l.unmarked_final = make_texture(gl, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    l.marked_final = make_texture(gl, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    l.splat_depth = make_texture(gl, GL_R32F, GL_RED, GL_FLOAT, width, height);
    l.splat_plain = make_texture(gl, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    l.splat_marked = make_texture(gl, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
    l.splat_ids = make_texture(gl, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, width, height);
    bool complete = true;
    l.base_fbo = make_framebuffer(gl,
                                  {{GL_COLOR_ATTACHMENT0, l.base},
                                   {GL_COLOR_ATTACHMENT1, l.plain},
                                   {GL_COLOR_ATTACHMENT2, l.marked},
                                   {GL_COLOR_ATTACHMENT3, l.ids},
                                   {GL_DEPTH_ATTACHMENT, l.depth}},
                                  complete);
    l.overlay_fbo = make_framebuffer(
        gl, {{GL_COLOR_ATTACHMENT0, l.cover}, {GL_COLOR_ATTACHMENT1, l.transmittance}, {GL_DEPTH_ATTACHMENT, l.depth}},
        complete);
    l.finals_fbo = make_framebuffer(
        gl, {{GL_COLOR_ATTACHMENT0, l.unmarked_final}, {GL_COLOR_ATTACHMENT1, l.marked_final}}, complete);
    check_gl(gl, "Renderer: frame layers");
    if (!complete) throw std::runtime_error("Renderer: frame layers are incomplete");
}

Renderer::Impl::Reuse Renderer::Impl::reuse(const Frame& f, const Camera& cam, int width, int height) const {
    const FrameLayers& l = layers;
    if (!l.valid || l.width != width || l.height != height || !detail::same_camera(cam, l.camera) ||
        !detail::same_frame(f, l.frame))
        return Reuse::None;
    bool marks_changed = false;
    for (const auto& [id, revision] : l.revisions) {
        auto it = sphere_sets.find(id);
        if (it == sphere_sets.end() || it->second.revision != revision) return Reuse::None;
    }
    for (const auto& [id, revision] : l.mark_revisions) {
        if (sphere_sets.at(id).mark_revision == revision) continue;
        if (id != l.mark_set) return Reuse::None;
        marks_changed = true;
    }
    return marks_changed ? Reuse::Recolour : Reuse::Composite;
}

void Renderer::Impl::remember(const Frame& f, const Camera& cam) {
    FrameLayers& l = layers;
    l.frame = f;
    l.camera = cam;
    l.revisions.clear();
    l.mark_revisions.clear();
    l.mark_set = 0;
    bool several = false;
    for (const SphereItem& item : f.spheres) {
        const GpuSphereSet& s = sphere_sets.at(item.spheres.id);
        const auto listed = [&](const std::vector<std::pair<uint32_t, uint64_t>>& v) {
            return std::any_of(v.begin(), v.end(), [&](auto& r) { return r.first == item.spheres.id; });
        };
        if (!listed(l.revisions)) l.revisions.push_back({item.spheres.id, s.revision});
        // Marks show only through items with a marked colour.
        if (item.marked_color && !listed(l.mark_revisions)) l.mark_revisions.push_back({item.spheres.id, s.mark_revision});
        if (item.marked_color) {
            several = several || (l.mark_set && l.mark_set != item.spheres.id);
            l.mark_set = item.spheres.id;
        }
    }
    // The ids index one set's marks; trails are drawn over the spheres without clearing the ids.
    if (several || !f.trails.empty()) l.mark_set = 0;
    l.valid = true;
}

void Renderer::Impl::marks_seen() {
    for (auto& [id, revision] : layers.mark_revisions) revision = sphere_sets.at(id).mark_revision;
}

// The state every full-view pass draws with, into `fbo` over `vp` (clipped to it when `clip`).
void Renderer::Impl::begin_full_view(const Viewport& vp, GLuint fbo, bool clip) {
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.Viewport(vp.x, vp.y, vp.width, vp.height);
    if (clip) {
        gl.Enable(GL_SCISSOR_TEST);
        gl.Scissor(vp.x, vp.y, vp.width, vp.height);
    } else {
        gl.Disable(GL_SCISSOR_TEST);
    }
    gl.Disable(GL_DITHER);
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_BLEND);
}

// The cached layers on texture units 0-5, for a program's samplers.
void Renderer::Impl::bind_layers(const detail::LayerSamplers& s) {
    const FrameLayers& l = layers;
    bind_unit(0, GL_TEXTURE_2D, l.base, s.base);
    bind_unit(1, GL_TEXTURE_2D, l.cover, s.cover);
    bind_unit(2, GL_TEXTURE_2D, l.transmittance, s.transmittance);
    bind_unit(3, GL_TEXTURE_2D, l.ids, s.ids);
    bind_unit(4, GL_TEXTURE_2D, l.plain, s.plain);
    bind_unit(5, GL_TEXTURE_2D, l.marked, s.marked);
}

// The one triangle over the viewport, then the state left as the other passes expect it.
void Renderer::Impl::end_full_view() {
    gl.BindVertexArray(layers.empty_vao);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.Disable(GL_SCISSOR_TEST);
    gl.BindVertexArray(0);
    gl.UseProgram(0);
}

void Renderer::Impl::make_finals() {
    FrameLayers& l = layers;
    begin_full_view(Viewport{0, 0, l.width, l.height}, l.finals_fbo, false);
    const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl.DrawBuffers(2, both);
    gl.UseProgram(prog.finals.id);
    bind_layers(prog.finals.layers);
    end_full_view();
    l.finals = true;
}

void Renderer::Impl::recolour(const Viewport& vp, GLuint fbo) {
    FrameLayers& l = layers;
    if (!l.finals) make_finals();
    begin_full_view(vp, fbo, true);
    const detail::RecolourProgram& r = prog.recolour;
    gl.UseProgram(r.id);
    bind_unit(0, GL_TEXTURE_2D, l.unmarked_final, r.unmarked);
    bind_unit(1, GL_TEXTURE_2D, l.marked_final, r.marked);
    bind_unit(2, GL_TEXTURE_2D, l.ids, r.ids);
    bind_unit(3, GL_TEXTURE_BUFFER, l.marks_texture, r.marks);
    gl.TexBuffer(GL_TEXTURE_BUFFER, GL_R8UI, sphere_sets.at(l.mark_set).mark_vbo);
    gl.Uniform2i(r.origin, vp.x, vp.y);
    end_full_view();
}

void Renderer::Impl::composite(const Viewport& vp, GLuint fbo) {
    begin_full_view(vp, fbo, true);
    const detail::CompositeProgram& c = prog.composite;
    gl.UseProgram(c.id);
    bind_layers(c.layers);
    gl.Uniform2i(c.origin, vp.x, vp.y);
    end_full_view();
}

} // namespace spt::render
