// The renderer's GPU objects: set-up and tear-down, vertex arrays, sphere uploads, streamed lines.
#include "renderer_impl.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace spt::render {
namespace {

uint8_t to_u8(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

void pack(const Color& c, uint8_t out[4]) { out[0] = to_u8(c.r), out[1] = to_u8(c.g), out[2] = to_u8(c.b), out[3] = to_u8(c.a); }

} // namespace

Renderer::Impl::GpuSphere Renderer::Impl::to_gpu(const SphereInstance& s) {
    GpuSphere g;
    g.center[0] = s.sphere.center.x(), g.center[1] = s.sphere.center.y(), g.center[2] = s.sphere.center.z();
    g.radius = s.sphere.radius;
    pack(s.color, g.rgba);
    return g;
}

void Renderer::Impl::push_line_vertex(std::vector<LineVertex>& v, const Eigen::Vector3f& p, const Color& c) {
    LineVertex x;
    x.p[0] = p.x(), x.p[1] = p.y(), x.p[2] = p.z();
    pack(c, x.rgba);
    v.push_back(x);
}

Renderer::Impl::Impl(const ProcLoader& load) {
    gl.load(load);
    const GLubyte* name = gl.GetString(GL_RENDERER);
    renderer_name = name ? reinterpret_cast<const char*>(name) : "unknown";
    prog = detail::build_programs(gl);

    std::vector<float> circles;
    for (int c = 0; c < 4; ++c)
        for (int i = 0; i < kCircleSegments; ++i)
            for (int k : {i, i + 1}) {
                const double a = 2.0 * 3.14159265358979323846 * double(k % kCircleSegments) / kCircleSegments;
                circles.insert(circles.end(), {float(std::cos(a)), float(std::sin(a)), float(c)});
            }
    gl.GenBuffers(1, &circle_vbo);
    gl.BindBuffer(GL_ARRAY_BUFFER, circle_vbo);
    gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(circles.size() * sizeof(float)), circles.data(), GL_STATIC_DRAW);

    gl.GenVertexArrays(1, &line_vao);
    gl.GenBuffers(1, &line_vbo);
    gl.BindVertexArray(line_vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, line_vbo);
    gl.EnableVertexAttribArray(detail::kPosition);
    gl.VertexAttribPointer(detail::kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex), nullptr);
    gl.EnableVertexAttribArray(detail::kColor);
    gl.VertexAttribPointer(detail::kColor, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(LineVertex),
                           reinterpret_cast<void*>(offsetof(LineVertex, rgba)));

    make_instanced_vao(wire_vao, wire_vbo, circle_vbo, 3);
    check_gl(gl, "renderer set-up");
}

Renderer::Impl::~Impl() {
    free_layers();
    gl.DeleteVertexArrays(1, &layers.empty_vao);
    gl.DeleteTextures(1, &layers.marks_texture);
    for (auto& [id, m] : meshes) free_mesh(m);
    for (auto& [id, s] : sphere_sets) free_set(s);
    GLuint vaos[] = {line_vao, wire_vao};
    GLuint bufs[] = {circle_vbo, line_vbo, wire_vbo};
    gl.DeleteVertexArrays(2, vaos);
    gl.DeleteBuffers(3, bufs);
    detail::delete_programs(gl, prog);
}

// Centre/radius and colour from the bound GL_ARRAY_BUFFER of GpuSphere, per instance (divisor 1:
// the wire spheres).
void Renderer::Impl::set_sphere_attributes(GLuint divisor) {
    gl.EnableVertexAttribArray(detail::kSphere);
    gl.VertexAttribPointer(detail::kSphere, 4, GL_FLOAT, GL_FALSE, sizeof(GpuSphere), nullptr);
    gl.VertexAttribDivisor(detail::kSphere, divisor);
    gl.EnableVertexAttribArray(detail::kColor);
    gl.VertexAttribPointer(detail::kColor, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(GpuSphere),
                           reinterpret_cast<void*>(offsetof(GpuSphere, rgba)));
    gl.VertexAttribDivisor(detail::kColor, divisor);
}

// A VAO drawing the shape in `shape_vbo` (positions of `components` floats) once per
// GpuSphere instance in a new buffer `vbo`.
void Renderer::Impl::make_instanced_vao(GLuint& vao, GLuint& vbo, GLuint shape_vbo, int components) {
    gl.GenVertexArrays(1, &vao);
    gl.GenBuffers(1, &vbo);
    gl.BindVertexArray(vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, shape_vbo);
    gl.EnableVertexAttribArray(detail::kPosition);
    gl.VertexAttribPointer(detail::kPosition, components, GL_FLOAT, GL_FALSE, GLsizei(components * sizeof(float)),
                           nullptr);
    gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
    set_sphere_attributes(1);
    gl.BindVertexArray(0);
}

void Renderer::Impl::free_mesh(GpuMesh& m) {
    gl.DeleteVertexArrays(1, &m.vao);
    GLuint b[] = {m.vbo, m.ebo};
    gl.DeleteBuffers(2, b);
}

void Renderer::Impl::free_set(GpuSphereSet& s) {
    if (s.mark_vbo) gl.DeleteBuffers(1, &s.mark_vbo);
}

void Renderer::Impl::upload_spheres(GpuSphereSet& s, const std::vector<SphereInstance>& spheres) {
    s.spheres.clear();
    s.spheres.reserve(spheres.size());
    s.bounds = Bounds{};
    for (const auto& x : spheres) {
        s.spheres.push_back(to_gpu(x));
        s.bounds.add_sphere(x.sphere.center, x.sphere.radius);
    }
    s.count = uint32_t(spheres.size());
    s.revision = next_revision++;
    set_marks(s, {});
}

// Only the span of marks that changed is uploaded: a selection change rewrites a 3-byte-a-sphere
// buffer in each view's context, and most of it often stays as it was.
void Renderer::Impl::set_marks(GpuSphereSet& s, const std::vector<uint32_t>& marked) {
    std::vector<uint8_t>& marks = scratch_marks;
    marks.assign(std::max<size_t>(3 * size_t(s.count), 3), 0);
    for (uint32_t i : marked)
        if (i < s.count) marks[3 * size_t(i)] = marks[3 * size_t(i) + 1] = marks[3 * size_t(i) + 2] = 255;
    if (!s.mark_vbo) gl.GenBuffers(1, &s.mark_vbo);
    gl.BindBuffer(GL_ARRAY_BUFFER, s.mark_vbo);
    if (s.marks.size() != marks.size()) {
        gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(marks.size()), marks.data(), GL_STATIC_DRAW);
    } else {
        const auto first = std::mismatch(marks.begin(), marks.end(), s.marks.begin()).first;
        if (first != marks.end()) {
            const auto last = std::mismatch(marks.rbegin(), marks.rend(), s.marks.rbegin()).first.base();
            gl.BufferSubData(GL_ARRAY_BUFFER, GLintptr(first - marks.begin()), GLsizeiptr(last - first), &*first);
        }
    }
    s.marks.swap(marks);
    s.mark_revision = next_revision++;
}

void Renderer::Impl::stream_lines(const std::vector<LineVertex>& v) {
    gl.BindBuffer(GL_ARRAY_BUFFER, line_vbo);
    gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(LineVertex)), v.data(), GL_STREAM_DRAW);
}

void Renderer::Impl::use_line_program(const Eigen::Matrix4f& mvp, float point_size, bool round) {
    gl.UseProgram(prog.line.id);
    gl.UniformMatrix4fv(prog.line.mvp, 1, GL_FALSE, mvp.data());
    gl.Uniform1f(prog.line.point_size, point_size);
    gl.Uniform1i(prog.line.round_points, round ? 1 : 0);
}

void Renderer::Impl::draw_lines(const std::vector<LineVertex>& v, GLenum mode, float point_size, bool round) {
    draw_lines(v, mode, proj * view, point_size, round);
}

void Renderer::Impl::draw_lines(const std::vector<LineVertex>& v, GLenum mode, const Eigen::Matrix4f& mvp,
                                float point_size, bool round) {
    if (v.empty()) return;
    use_line_program(mvp, point_size, round);
    gl.BindVertexArray(line_vao);
    stream_lines(v);
    gl.DrawArrays(mode, 0, GLsizei(v.size()));
}

} // namespace spt::render
