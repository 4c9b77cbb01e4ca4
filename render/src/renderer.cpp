#include "spt/render/renderer.hpp"
#include "shaders.hpp"
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>

namespace spt::render {
namespace {

using detail::Programs;

// One solid-sphere instance as the GPU reads it (20 bytes).
struct GpuSphere {
    float center[3];
    float radius;
    uint8_t rgba[4];
};
static_assert(sizeof(GpuSphere) == 20, "GpuSphere layout");

// One line or point vertex (16 bytes).
struct LineVertex {
    float p[3];
    uint8_t rgba[4];
};
static_assert(sizeof(LineVertex) == 16, "LineVertex layout");

uint8_t to_u8(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

void pack(const Color& c, uint8_t out[4]) { out[0] = to_u8(c.r), out[1] = to_u8(c.g), out[2] = to_u8(c.b), out[3] = to_u8(c.a); }

GpuSphere to_gpu(const SphereInstance& s) {
    GpuSphere g;
    g.center[0] = s.sphere.center.x(), g.center[1] = s.sphere.center.y(), g.center[2] = s.sphere.center.z();
    g.radius = s.sphere.radius;
    pack(s.color, g.rgba);
    return g;
}

void push_line_vertex(std::vector<LineVertex>& v, const Eigen::Vector3f& p, const Color& c) {
    LineVertex x;
    x.p[0] = p.x(), x.p[1] = p.y(), x.p[2] = p.z();
    pack(c, x.rgba);
    v.push_back(x);
}

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

// Largest 1, 2 or 5 times a power of ten not above x.
float nice_step(float x) {
    const float p = std::pow(10.0f, std::floor(std::log10(x)));
    const float m = x / p;
    return (m >= 5 ? 5.0f : m >= 2 ? 2.0f : 1.0f) * p;
}

constexpr int kCircleSegments = 64;

} // namespace

std::array<Viewport, 4> quad_viewports(int width, int height) {
    const int lw = std::max(1, (width - 1) / 2), rw = std::max(1, width - lw - 1);
    const int bh = std::max(1, (height - 1) / 2), th = std::max(1, height - bh - 1);
    const int rx = width - rw, ty = height - th;
    return {Viewport{0, ty, lw, th}, Viewport{rx, ty, rw, th}, Viewport{0, 0, lw, bh}, Viewport{rx, 0, rw, bh}};
}

struct Renderer::Impl {
    detail::GlFunctions gl;
    Programs prog;
    std::string renderer_name;

    struct GpuMesh {
        GLuint vao = 0, vbo = 0, ebo = 0;
        GLsizei index_count = 0, vertex_count = 0;
        Bounds bounds;
    };
    struct GpuSphereSet {
        GLuint vao = 0, vbo = 0;
        uint32_t count = 0;
        Bounds bounds; // of the spheres, object frame
    };
    std::map<uint32_t, GpuMesh> meshes;
    std::map<uint32_t, GpuSphereSet> sphere_sets;
    uint32_t next_id = 1;

    GLuint quad_vbo = 0;   // impostor corners, triangle strip
    GLuint circle_vbo = 0; // 4 circles as GL_LINES
    GLuint line_vao = 0, line_vbo = 0;     // streamed lines and points
    GLuint scratch_set_vao = 0, scratch_set_vbo = 0; // streamed solid spheres (collision pairs)
    GLuint wire_vao = 0, wire_vbo = 0;     // streamed wire-sphere instances

    // Per-draw state.
    Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
    Eigen::Matrix4f proj = Eigen::Matrix4f::Identity();
    bool ortho = false;

    explicit Impl(const ProcLoader& load) {
        gl.load(load);
        const GLubyte* name = gl.GetString(GL_RENDERER);
        renderer_name = name ? reinterpret_cast<const char*>(name) : "unknown";
        prog = detail::build_programs(gl);

        const float quad[6] = {0, 2, -1.7320508f, -1, 1.7320508f, -1};
        gl.GenBuffers(1, &quad_vbo);
        gl.BindBuffer(GL_ARRAY_BUFFER, quad_vbo);
        gl.BufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);

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

        make_sphere_vao(scratch_set_vao, scratch_set_vbo);

        make_instanced_vao(wire_vao, wire_vbo, circle_vbo, 3);
        check_gl(gl, "renderer set-up");
    }

    ~Impl() {
        for (auto& [id, m] : meshes) free_mesh(m);
        for (auto& [id, s] : sphere_sets) free_set(s);
        GLuint vaos[] = {line_vao, scratch_set_vao, wire_vao};
        GLuint bufs[] = {quad_vbo, circle_vbo, line_vbo, scratch_set_vbo, wire_vbo};
        gl.DeleteVertexArrays(3, vaos);
        gl.DeleteBuffers(5, bufs);
        detail::delete_programs(gl, prog);
    }

    // Per-instance centre/radius and colour from the bound GL_ARRAY_BUFFER of GpuSphere.
    void set_instance_attributes() {
        gl.EnableVertexAttribArray(detail::kSphere);
        gl.VertexAttribPointer(detail::kSphere, 4, GL_FLOAT, GL_FALSE, sizeof(GpuSphere), nullptr);
        gl.VertexAttribDivisor(detail::kSphere, 1);
        gl.EnableVertexAttribArray(detail::kColor);
        gl.VertexAttribPointer(detail::kColor, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(GpuSphere),
                               reinterpret_cast<void*>(offsetof(GpuSphere, rgba)));
        gl.VertexAttribDivisor(detail::kColor, 1);
    }

    // A VAO drawing the shape in `shape_vbo` (positions of `components` floats) once per
    // GpuSphere instance in a new buffer `vbo`.
    void make_instanced_vao(GLuint& vao, GLuint& vbo, GLuint shape_vbo, int components) {
        gl.GenVertexArrays(1, &vao);
        gl.GenBuffers(1, &vbo);
        gl.BindVertexArray(vao);
        gl.BindBuffer(GL_ARRAY_BUFFER, shape_vbo);
        gl.EnableVertexAttribArray(detail::kPosition);
        gl.VertexAttribPointer(detail::kPosition, components, GL_FLOAT, GL_FALSE, GLsizei(components * sizeof(float)),
                               nullptr);
        gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
        set_instance_attributes();
        gl.BindVertexArray(0);
    }

    // Sampling spheres: a screen-facing quad per instance.
    void make_sphere_vao(GLuint& vao, GLuint& vbo) { make_instanced_vao(vao, vbo, quad_vbo, 2); }

    void free_mesh(GpuMesh& m) {
        gl.DeleteVertexArrays(1, &m.vao);
        GLuint b[] = {m.vbo, m.ebo};
        gl.DeleteBuffers(2, b);
    }
    void free_set(GpuSphereSet& s) {
        gl.DeleteVertexArrays(1, &s.vao);
        gl.DeleteBuffers(1, &s.vbo);
    }

    void upload_spheres(GpuSphereSet& s, const std::vector<SphereInstance>& spheres) {
        std::vector<GpuSphere> data;
        data.reserve(spheres.size());
        s.bounds = Bounds{};
        for (const auto& x : spheres) {
            data.push_back(to_gpu(x));
            s.bounds.add_sphere(x.sphere.center, x.sphere.radius);
        }
        gl.BindBuffer(GL_ARRAY_BUFFER, s.vbo);
        gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(GpuSphere)), data.data(), GL_STATIC_DRAW);
        s.count = uint32_t(data.size());
    }

    void stream_lines(const std::vector<LineVertex>& v) {
        gl.BindBuffer(GL_ARRAY_BUFFER, line_vbo);
        gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(v.size() * sizeof(LineVertex)), v.data(), GL_STREAM_DRAW);
    }

    void use_line_program(const Eigen::Matrix4f& mvp, float point_size = 1, bool round = false) {
        gl.UseProgram(prog.line.id);
        gl.UniformMatrix4fv(prog.line.mvp, 1, GL_FALSE, mvp.data());
        gl.Uniform1f(prog.line.point_size, point_size);
        gl.Uniform1i(prog.line.round_points, round ? 1 : 0);
    }

    void draw_lines(const std::vector<LineVertex>& v, GLenum mode, float point_size = 1, bool round = false) {
        if (v.empty()) return;
        use_line_program(proj * view, point_size, round);
        gl.BindVertexArray(line_vao);
        stream_lines(v);
        gl.DrawArrays(mode, 0, GLsizei(v.size()));
    }

    // The grid lies under the meshes and spheres (not under overlays such as bounding
    // spheres, which reach below the object) and spans the whole scene.
    void draw_grid(const Bounds& b, float ground) {
        if (b.empty()) return;
        const float r = std::max(b.radius(), 1e-6f);
        const float step = nice_step(r / 3.0f);
        const Eigen::Vector3f c = b.center();
        const int half = int(std::ceil(1.5f * r / step));
        const float cx = std::round(c.x() / step) * step, cz = std::round(c.z() / step) * step;
        const float y = ground;
        const float ext = float(half) * step;
        std::vector<LineVertex> v;
        const Color minor{0.80f, 0.81f, 0.84f, 1}, major{0.62f, 0.64f, 0.69f, 1};
        for (int i = -half; i <= half; ++i) {
            const float x = cx + float(i) * step, z = cz + float(i) * step;
            // Every fifth line from the world origin is darker, so scale can be read off.
            const Color& cxcol = (std::lround(x / step) % 5 == 0) ? major : minor;
            const Color& czcol = (std::lround(z / step) % 5 == 0) ? major : minor;
            push_line_vertex(v, {x, y, cz - ext}, cxcol);
            push_line_vertex(v, {x, y, cz + ext}, cxcol);
            push_line_vertex(v, {cx - ext, y, z}, czcol);
            push_line_vertex(v, {cx + ext, y, z}, czcol);
        }
        draw_lines(v, GL_LINES);
    }

    void draw_mesh_faces(const GpuMesh& m, const MeshItem& item) {
        const MeshStyle& s = item.style;
        const Eigen::Matrix4f mv = view * item.pose.matrix();
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

    void draw_meshes(const Frame& f, bool transparent) {
        for (const MeshItem& item : f.meshes) {
            if ((item.style.opacity < 1.0f) != transparent) continue;
            auto it = meshes.find(item.mesh.id);
            if (it == meshes.end()) throw std::invalid_argument("Renderer::draw: unknown mesh handle");
            draw_mesh_faces(it->second, item);
        }
    }

    void begin_spheres(const Eigen::Matrix4f& model_view) {
        gl.UseProgram(prog.sphere.id);
        gl.UniformMatrix4fv(prog.sphere.model_view, 1, GL_FALSE, model_view.data());
        gl.UniformMatrix4fv(prog.sphere.projection, 1, GL_FALSE, proj.data());
        gl.Uniform1i(prog.sphere.ortho, ortho ? 1 : 0);
        gl.Uniform1i(prog.sphere.override_color, 0);
    }

    // Instanced draw of spheres [first, first + count) of the buffer bound to `vao`.
    void draw_sphere_range(GLuint vao, GLuint vbo, uint32_t first, uint32_t count) {
        if (count == 0) return;
        gl.BindVertexArray(vao);
        // Base instance is GL 4.2; point the instance attributes at the range instead.
        gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
        const size_t offset = size_t(first) * sizeof(GpuSphere);
        gl.VertexAttribPointer(detail::kSphere, 4, GL_FLOAT, GL_FALSE, sizeof(GpuSphere), reinterpret_cast<void*>(offset));
        gl.VertexAttribPointer(detail::kColor, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(GpuSphere),
                               reinterpret_cast<void*>(offset + offsetof(GpuSphere, rgba)));
        gl.DrawArraysInstanced(GL_TRIANGLES, 0, 3, GLsizei(count));
    }

    void draw_sphere_items(const Frame& f) {
        for (const SphereItem& item : f.spheres) {
            auto it = sphere_sets.find(item.spheres.id);
            if (it == sphere_sets.end()) throw std::invalid_argument("Renderer::draw: unknown sphere-set handle");
            const GpuSphereSet& s = it->second;
            if (item.first >= s.count) continue;
            const uint32_t count = std::min<uint32_t>(item.count, s.count - item.first);
            begin_spheres(view * item.pose.matrix());
            if (item.color) {
                gl.Uniform1i(prog.sphere.override_color, 1);
                gl.Uniform4f(prog.sphere.color, item.color->r, item.color->g, item.color->b, item.color->a);
            }
            draw_sphere_range(s.vao, s.vbo, item.first, count);
        }
    }

    float scene_diameter(const Bounds& b) const { return b.empty() ? 1.0f : 2.0f * std::max(b.radius(), 1e-6f); }

    void draw_collision_spheres(const CollisionOverlay& c) {
        if (c.pairs.empty()) return;
        std::vector<GpuSphere> data;
        data.reserve(c.pairs.size() * 2);
        for (const SpherePair& p : c.pairs) {
            data.push_back(to_gpu({p.a, c.color_a}));
            data.push_back(to_gpu({p.b, c.color_b}));
        }
        gl.BindBuffer(GL_ARRAY_BUFFER, scratch_set_vbo);
        gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(GpuSphere)), data.data(), GL_STREAM_DRAW);
        begin_spheres(view);
        draw_sphere_range(scratch_set_vao, scratch_set_vbo, 0, uint32_t(data.size()));
    }

    void draw_collision_marks(const CollisionOverlay& c, const Bounds& b) {
        if (c.pairs.empty()) return;
        const float len = c.normal_length > 0 ? c.normal_length : 0.04f * scene_diameter(b);
        std::vector<LineVertex> lines, points;
        for (const SpherePair& p : c.pairs) {
            push_line_vertex(lines, p.contact, c.normal_color);
            push_line_vertex(lines, p.contact + p.normal * len, c.normal_color);
            push_line_vertex(points, p.contact, c.contact_color);
        }
        draw_lines(lines, GL_LINES);
        draw_lines(points, GL_POINTS, c.contact_size, true);
    }

    void draw_trails(const Frame& f) {
        std::vector<LineVertex> v;
        for (const Trail& t : f.trails)
            for (size_t i = 1; i < t.points.size(); ++i) {
                push_line_vertex(v, t.points[i - 1], t.color);
                push_line_vertex(v, t.points[i], t.color);
            }
        draw_lines(v, GL_LINES);
    }

    void draw_wire_spheres(const Frame& f, bool outlines) {
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

    void draw_gizmo(const Viewport& vp) {
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

    Bounds solid_bounds(const Frame& f) const {
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

    void draw(const Frame& f, const Camera& cam, const Viewport& vp, GLuint fbo, const Bounds& b) {
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
};

Renderer::Renderer(const ProcLoader& load) : impl_(std::make_unique<Impl>(load)) {}
Renderer::~Renderer() = default;

const std::string& Renderer::gl_renderer() const { return impl_->renderer_name; }

MeshHandle Renderer::add_mesh(const TriangleMesh& mesh) {
    auto& gl = impl_->gl;
    Impl::GpuMesh m;
    std::vector<float> verts;
    verts.reserve(mesh.positions.size() * 6);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const Eigen::Vector3f p = mesh.positions[i].cast<float>();
        const Eigen::Vector3f n = i < mesh.normals.size() ? Eigen::Vector3f(mesh.normals[i].cast<float>()) : Eigen::Vector3f::Zero();
        verts.insert(verts.end(), {p.x(), p.y(), p.z(), n.x(), n.y(), n.z()});
        m.bounds.add(p);
    }
    std::vector<uint32_t> idx;
    idx.reserve(mesh.triangles.size() * 3);
    for (const Triangle& t : mesh.triangles) {
        if (t[0] >= mesh.positions.size() || t[1] >= mesh.positions.size() || t[2] >= mesh.positions.size())
            throw std::invalid_argument("Renderer::add_mesh: " + mesh.name + ": triangle index out of range");
        idx.insert(idx.end(), {t[0], t[1], t[2]});
    }
    m.index_count = GLsizei(idx.size());
    m.vertex_count = GLsizei(mesh.positions.size());
    gl.GenVertexArrays(1, &m.vao);
    gl.GenBuffers(1, &m.vbo);
    gl.GenBuffers(1, &m.ebo);
    gl.BindVertexArray(m.vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, m.vbo);
    gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(verts.size() * sizeof(float)), verts.data(), GL_STATIC_DRAW);
    gl.EnableVertexAttribArray(detail::kPosition);
    gl.VertexAttribPointer(detail::kPosition, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    gl.EnableVertexAttribArray(detail::kNormal);
    gl.VertexAttribPointer(detail::kNormal, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                           reinterpret_cast<void*>(3 * sizeof(float)));
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.ebo);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(idx.size() * sizeof(uint32_t)), idx.data(), GL_STATIC_DRAW);
    gl.BindVertexArray(0);
    check_gl(gl, "Renderer::add_mesh");
    const uint32_t id = impl_->next_id++;
    impl_->meshes[id] = m;
    return MeshHandle{id};
}

void Renderer::remove_mesh(MeshHandle mesh) {
    auto it = impl_->meshes.find(mesh.id);
    if (it == impl_->meshes.end()) return;
    impl_->free_mesh(it->second);
    impl_->meshes.erase(it);
}

SphereSetHandle Renderer::add_spheres(const std::vector<SphereInstance>& spheres) {
    Impl::GpuSphereSet s;
    impl_->make_sphere_vao(s.vao, s.vbo);
    impl_->upload_spheres(s, spheres);
    check_gl(impl_->gl, "Renderer::add_spheres");
    const uint32_t id = impl_->next_id++;
    impl_->sphere_sets[id] = s;
    return SphereSetHandle{id};
}

void Renderer::update_spheres(SphereSetHandle set, const std::vector<SphereInstance>& spheres) {
    auto it = impl_->sphere_sets.find(set.id);
    if (it == impl_->sphere_sets.end()) throw std::invalid_argument("Renderer::update_spheres: unknown handle");
    impl_->upload_spheres(it->second, spheres);
}

void Renderer::remove_spheres(SphereSetHandle set) {
    auto it = impl_->sphere_sets.find(set.id);
    if (it == impl_->sphere_sets.end()) return;
    impl_->free_set(it->second);
    impl_->sphere_sets.erase(it);
}

uint32_t Renderer::sphere_count(SphereSetHandle set) const {
    auto it = impl_->sphere_sets.find(set.id);
    return it == impl_->sphere_sets.end() ? 0 : it->second.count;
}

Bounds Renderer::bounds(const Frame& f) const {
    Bounds b = impl_->solid_bounds(f);
    for (const WireSphere& w : f.wire_spheres) b.add_sphere(w.sphere.center, w.sphere.radius);
    for (const SpherePair& p : f.collision.pairs) {
        b.add_sphere(p.a.center, p.a.radius);
        b.add_sphere(p.b.center, p.b.radius);
    }
    for (const Trail& t : f.trails)
        for (const auto& p : t.points) b.add(p);
    return b;
}

void Renderer::draw(const Frame& frame, const Camera& camera, const Viewport& viewport, uint32_t framebuffer) {
    impl_->draw(frame, camera, viewport, framebuffer, bounds(frame));
}

void Renderer::draw_quad(const Frame& frame, const std::array<Camera, 4>& cameras, int width, int height,
                         uint32_t framebuffer) {
    auto& gl = impl_->gl;
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.Viewport(0, 0, width, height);
    gl.Disable(GL_SCISSOR_TEST);
    gl.Disable(GL_DITHER);
    // The separators are the background seen between the views, darkened.
    const Color& bg = frame.background;
    gl.ClearColor(bg.r * 0.55f, bg.g * 0.55f, bg.b * 0.55f, 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const Bounds b = bounds(frame);
    const auto vps = quad_viewports(width, height);
    for (int i = 0; i < 4; ++i) impl_->draw(frame, cameras[size_t(i)], vps[size_t(i)], framebuffer, b);
}

} // namespace spt::render
