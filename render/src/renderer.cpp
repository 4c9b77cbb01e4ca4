// The public Renderer: mesh and sphere-set handles, bounds, single and quad-layout draws.
#include "renderer_impl.hpp"
#include <algorithm>
#include <stdexcept>

namespace spt::render {

std::array<Viewport, 4> quad_viewports(int width, int height) {
    const int lw = std::max(1, (width - 1) / 2), rw = std::max(1, width - lw - 1);
    const int bh = std::max(1, (height - 1) / 2), th = std::max(1, height - bh - 1);
    const int rx = width - rw, ty = height - th;
    return {Viewport{0, ty, lw, th}, Viewport{rx, ty, rw, th}, Viewport{0, 0, lw, bh}, Viewport{rx, 0, rw, bh}};
}

Renderer::Renderer(const ProcLoader& load) : impl_(std::make_unique<Impl>(load)) {}
Renderer::~Renderer() = default;

const std::string& Renderer::gl_renderer() const { return impl_->renderer_name; }

DrawKind Renderer::last_draw_kind() const { return impl_->last_kind; }

Eigen::Vector3d Renderer::drawing_origin(const TriangleMesh& mesh) {
    if (!mesh.far_for_float()) return Eigen::Vector3d::Zero();
    const auto [lo, hi] = mesh.bounds();
    return 0.5 * (lo + hi);
}

MeshHandle Renderer::add_mesh(const TriangleMesh& mesh, const Eigen::Vector3d& origin) {
    auto& gl = impl_->gl;
    Impl::GpuMesh m;
    std::vector<float> verts;
    verts.reserve(mesh.positions.size() * 6);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const Eigen::Vector3f p = (mesh.positions[i] - origin).cast<float>();
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

void Renderer::update_mesh(MeshHandle mesh, const std::vector<Eigen::Vector3d>& positions,
                           const std::vector<Eigen::Vector3d>& normals, const Eigen::Vector3d& origin) {
    auto it = impl_->meshes.find(mesh.id);
    if (it == impl_->meshes.end()) throw std::invalid_argument("Renderer::update_mesh: unknown handle");
    Impl::GpuMesh& m = it->second;
    if (GLsizei(positions.size()) != m.vertex_count)
        throw std::invalid_argument("Renderer::update_mesh: " + std::to_string(positions.size()) + " vertices for a mesh of " +
                                    std::to_string(m.vertex_count));
    std::vector<float> verts;
    verts.reserve(positions.size() * 6);
    m.bounds = Bounds{};
    for (size_t i = 0; i < positions.size(); ++i) {
        const Eigen::Vector3f p = (positions[i] - origin).cast<float>();
        const Eigen::Vector3f n = i < normals.size() ? Eigen::Vector3f(normals[i].cast<float>()) : Eigen::Vector3f::Zero();
        verts.insert(verts.end(), {p.x(), p.y(), p.z(), n.x(), n.y(), n.z()});
        m.bounds.add(p);
    }
    auto& gl = impl_->gl;
    gl.BindBuffer(GL_ARRAY_BUFFER, m.vbo);
    gl.BufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(verts.size() * sizeof(float)), verts.data());
    gl.BindBuffer(GL_ARRAY_BUFFER, 0);
    check_gl(gl, "Renderer::update_mesh");
    // The cached layers hold the mesh where it was: a frame whose only change is a moved mesh
    // (the same handles, camera and sphere sets) must be drawn again, not composited.
    impl_->layers.valid = false;
}

void Renderer::remove_mesh(MeshHandle mesh) {
    auto it = impl_->meshes.find(mesh.id);
    if (it == impl_->meshes.end()) return;
    impl_->free_mesh(it->second);
    impl_->meshes.erase(it);
}

SphereSetHandle Renderer::add_spheres(const std::vector<SphereInstance>& spheres) {
    Impl::GpuSphereSet s;
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

void Renderer::set_sphere_marks(SphereSetHandle set, const std::vector<uint32_t>& marked) {
    auto it = impl_->sphere_sets.find(set.id);
    if (it == impl_->sphere_sets.end()) throw std::invalid_argument("Renderer::set_sphere_marks: unknown handle");
    impl_->set_marks(it->second, marked);
    check_gl(impl_->gl, "Renderer::set_sphere_marks");
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
    for (const ContactMark& m : f.collision.marks) b.add(m.point);
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
