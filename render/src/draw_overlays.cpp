// Draw passes over the scene: collision pairs and contacts, trails, wire spheres, the axis gizmo.
#include "renderer_impl.hpp"
#include <algorithm>

namespace spt::render {

float Renderer::Impl::scene_diameter(const Bounds& b) const {
    return b.empty() ? 1.0f : 2.0f * std::max(b.radius(), 1e-6f);
}

// The pairs' spheres join the splat after the sampling spheres, in the world frame, with id 0.
void Renderer::Impl::splat_collision_spheres(const CollisionOverlay& c) {
    collision_spheres.clear();
    for (const SpherePair& p : c.pairs) {
        collision_spheres.push_back(to_gpu({p.a, c.color_a}));
        collision_spheres.push_back(to_gpu({p.b, c.color_b}));
    }
    detail::SplatItem item;
    item.spheres = collision_spheres.data();
    item.count = uint32_t(collision_spheres.size());
    item.model_view = view;
    splat.add(item);
}

void Renderer::Impl::draw_collision_marks(const CollisionOverlay& c, const Bounds& b) {
    if (c.pairs.empty() && c.marks.empty()) return;
    const float len = c.normal_length > 0 ? c.normal_length : 0.04f * scene_diameter(b);
    std::vector<LineVertex> lines, points, marks;
    for (const SpherePair& p : c.pairs) {
        push_line_vertex(lines, p.contact, c.normal_color);
        push_line_vertex(lines, p.contact + p.normal * len, c.normal_color);
        push_line_vertex(points, p.contact, c.contact_color);
    }
    for (const ContactMark& m : c.marks) {
        push_line_vertex(lines, m.point, c.mark_normal_color);
        push_line_vertex(lines, m.point + m.normal * len, c.mark_normal_color);
        push_line_vertex(marks, m.point, m.color);
    }
    draw_lines(lines, GL_LINES);
    draw_lines(points, GL_POINTS, c.contact_size, true);
    draw_lines(marks, GL_POINTS, c.mark_size, true);
}

void Renderer::Impl::draw_trails(const Frame& f) {
    std::vector<LineVertex> v;
    for (const Trail& t : f.trails)
        for (size_t i = 1; i < t.points.size(); ++i) {
            push_line_vertex(v, t.points[i - 1], t.color);
            push_line_vertex(v, t.points[i], t.color);
        }
    draw_lines(v, GL_LINES);
}

void Renderer::Impl::draw_wire_spheres(const Frame& f, bool outlines) {
    if (f.wire_spheres.empty()) return;
    std::vector<GpuSphere> data;
    data.reserve(f.wire_spheres.size());
    for (const WireSphere& w : f.wire_spheres) data.push_back(to_gpu({w.sphere, w.color}));
    gl.BindBuffer(GL_ARRAY_BUFFER, wire_vbo);
    gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(GpuSphere)), data.data(), GL_STREAM_DRAW);
    gl.UseProgram(prog.circle.id);
    gl.UniformMatrix4fv(prog.circle.view, 1, GL_FALSE, view.data());
    gl.UniformMatrix4fv(prog.circle.projection, 1, GL_FALSE, proj.data());
    gl.Uniform1i(prog.circle.ortho, ortho ? 1 : 0);
    gl.Uniform1f(prog.circle.alpha, outlines ? 1.0f : 0.35f);
    gl.BindVertexArray(wire_vao);
    const GLsizei per_circle = 2 * kCircleSegments;
    if (outlines)
        gl.DrawArraysInstanced(GL_LINES, 3 * per_circle, per_circle, GLsizei(data.size()));
    else
        gl.DrawArraysInstanced(GL_LINES, 0, 3 * per_circle, GLsizei(data.size()));
}

void Renderer::Impl::draw_gizmo(const Viewport& vp) {
    const int size = std::clamp(std::min(vp.width, vp.height) / 5, 24, 96);
    if (size > vp.width || size > vp.height) return;
    gl.Viewport(vp.x, vp.y, size, size);
    Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
    m.block<3, 3>(0, 0) = view.block<3, 3>(0, 0) / 1.25f;
    const Color colors[3] = {{0.86f, 0.2f, 0.18f, 1}, {0.2f, 0.66f, 0.25f, 1}, {0.18f, 0.36f, 0.9f, 1}};
    std::vector<LineVertex> lines, tips;
    for (int a = 0; a < 3; ++a) {
        push_line_vertex(lines, Eigen::Vector3f::Zero(), colors[a]);
        push_line_vertex(lines, Eigen::Vector3f::Unit(a), colors[a]);
        push_line_vertex(tips, Eigen::Vector3f::Unit(a), colors[a]);
    }
    use_line_program(m, 1, false);
    gl.BindVertexArray(line_vao);
    stream_lines(lines);
    gl.DrawArrays(GL_LINES, 0, GLsizei(lines.size()));
    use_line_program(m, std::max(3.0f, float(size) / 10.0f), true);
    stream_lines(tips);
    gl.DrawArrays(GL_POINTS, 0, GLsizei(tips.size()));
    gl.Viewport(vp.x, vp.y, vp.width, vp.height);
}

} // namespace spt::render
