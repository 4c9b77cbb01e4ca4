// Draw passes of the scene itself: the ground grid, meshes (faces, wireframe, points), sampling spheres.
#include "renderer_impl.hpp"
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spt::render {
namespace {

// Largest 1, 2 or 5 times a power of ten not above x.
float nice_step(float x) {
    const float p = std::pow(10.0f, std::floor(std::log10(x)));
    const float m = x / p;
    return (m >= 5 ? 5.0f : m >= 2 ? 2.0f : 1.0f) * p;
}

// View times pose in double: geometry far from the origin is uploaded relative to a point near
// it (local_frame), and the view's and the pose's large translations cancel here, not in float.
Eigen::Matrix4f model_view(const Eigen::Matrix4f& view, const Eigen::Affine3f& pose) {
    return (view.cast<double>() * pose.matrix().cast<double>()).cast<float>();
}

} // namespace

// The grid lies under the meshes and spheres (not under overlays such as bounding
// spheres, which reach below the object) and spans the whole scene.
void Renderer::Impl::draw_grid(const Bounds& b, float ground) {
    if (b.empty()) return;
    const float r = std::max(b.radius(), 1e-6f);
    const float step = nice_step(r / 3.0f);
    const Eigen::Vector3f c = b.center();
    const int half = int(std::ceil(1.5f * r / step));
    const float cx = std::round(c.x() / step) * step, cz = std::round(c.z() / step) * step;
    const float y = ground;
    const float ext = float(half) * step;
    // Far from the origin the lines are made relative to the grid's centre and placed by a pose
    // composed in double, as meshes are: in world floats they would snap to the float spacing
    // there. Near it they stay in world floats, as the golden images have them.
    const bool far = std::max({std::abs(cx), std::abs(cz), std::abs(y)}) > 8 * ext;
    const Eigen::Vector3f at = far ? Eigen::Vector3f(cx, y, cz) : Eigen::Vector3f::Zero();
    const Eigen::Vector3f base = Eigen::Vector3f(cx, y, cz) - at; // the grid's centre as uploaded
    const long first_x = std::lround(cx / step), first_z = std::lround(cz / step);
    std::vector<LineVertex> v;
    const Color minor{0.80f, 0.81f, 0.84f, 1}, major{0.62f, 0.64f, 0.69f, 1};
    for (int i = -half; i <= half; ++i) {
        const float x = base.x() + float(i) * step, z = base.z() + float(i) * step;
        // Every fifth line from the world origin is darker, so scale can be read off.
        const Color& cxcol = ((first_x + i) % 5 == 0) ? major : minor;
        const Color& czcol = ((first_z + i) % 5 == 0) ? major : minor;
        push_line_vertex(v, {x, base.y(), base.z() - ext}, cxcol);
        push_line_vertex(v, {x, base.y(), base.z() + ext}, cxcol);
        push_line_vertex(v, {base.x() - ext, base.y(), z}, czcol);
        push_line_vertex(v, {base.x() + ext, base.y(), z}, czcol);
    }
    if (!far) return draw_lines(v, GL_LINES);
    draw_lines(v, GL_LINES,
               (proj.cast<double>() * model_view(view, Eigen::Affine3f(Eigen::Translation3f(at))).cast<double>()).cast<float>());
}

void Renderer::Impl::draw_mesh_faces(const GpuMesh& m, const MeshItem& item) {
    const MeshStyle& s = item.style;
    const Eigen::Matrix4f mv = model_view(view, item.pose);
    if (s.shading != Shading::None) {
        gl.UseProgram(prog.mesh.id);
        gl.UniformMatrix4fv(prog.mesh.model_view, 1, GL_FALSE, mv.data());
        gl.UniformMatrix4fv(prog.mesh.projection, 1, GL_FALSE, proj.data());
        const Eigen::Matrix3f nm = mv.block<3, 3>(0, 0).inverse().transpose();
        gl.UniformMatrix3fv(prog.mesh.normal_matrix, 1, GL_FALSE, nm.data());
        gl.Uniform4f(prog.mesh.color, s.color.r, s.color.g, s.color.b, s.color.a * s.opacity);
        gl.Uniform1i(prog.mesh.smooth, s.shading == Shading::Smooth ? 1 : 0);
        gl.BindVertexArray(m.vao);
        if (s.wireframe) {
            gl.Enable(GL_POLYGON_OFFSET_FILL);
            gl.PolygonOffset(1.0f, 1.0f);
        }
        gl.DrawElements(GL_TRIANGLES, m.index_count, GL_UNSIGNED_INT, nullptr);
        gl.Disable(GL_POLYGON_OFFSET_FILL);
    }
    if (s.wireframe || s.points) {
        use_line_program(proj * mv, s.point_size, true);
        gl.BindVertexArray(m.vao);
        if (s.wireframe) {
            gl.VertexAttrib4f(detail::kColor, s.wire_color.r, s.wire_color.g, s.wire_color.b, s.wire_color.a);
            gl.PolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            gl.DrawElements(GL_TRIANGLES, m.index_count, GL_UNSIGNED_INT, nullptr);
            gl.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        }
        if (s.points) {
            gl.VertexAttrib4f(detail::kColor, s.point_color.r, s.point_color.g, s.point_color.b, s.point_color.a);
            gl.DrawArrays(GL_POINTS, 0, m.vertex_count);
        }
    }
}

void Renderer::Impl::draw_meshes(const Frame& f, bool transparent) {
    for (const MeshItem& item : f.meshes) {
        if ((item.style.opacity < 1.0f) != transparent) continue;
        auto it = meshes.find(item.mesh.id);
        if (it == meshes.end()) throw std::invalid_argument("Renderer::draw: unknown mesh handle");
        draw_mesh_faces(it->second, item);
    }
}

void Renderer::Impl::splat_sphere_items(const Frame& f) {
    for (const SphereItem& item : f.spheres) {
        auto it = sphere_sets.find(item.spheres.id);
        if (it == sphere_sets.end()) throw std::invalid_argument("Renderer::draw: unknown sphere-set handle");
        const GpuSphereSet& s = it->second;
        if (item.first >= s.count) continue;
        detail::SplatItem x;
        x.first_index = item.first;
        x.count = std::min<uint32_t>(item.count, s.count - item.first);
        x.spheres = s.spheres.data() + item.first;
        x.model_view = model_view(view, item.pose);
        if (item.color) x.override_color = true, x.color = {item.color->r, item.color->g, item.color->b, item.color->a};
        x.fade = std::clamp(item.fade, 0.0f, 1.0f);
        if (item.marked_color && s.mark_vbo) {
            x.use_mark = true;
            x.mark_color = {item.marked_color->r, item.marked_color->g, item.marked_color->b, item.marked_color->a};
            x.marks = s.marks.data();
        }
        splat.add(x);
    }
}

} // namespace spt::render
