// The golden-image scenes built in code, and an off-screen context with a renderer to draw them.
#include "scenes.hpp"
#include "spt/compact_tree.hpp"
#include "spt/convert.hpp"
#include "spt/render/collision_overlay.hpp"
#include "spt/render/tree_overlay.hpp"
#include "test_meshes.hpp"
#include <cmath>

namespace spt::test {

using namespace render;

OffscreenRenderer::OffscreenRenderer(const std::string& backend, int width, int height)
    : context(make_offscreen_context(backend, width, height)), renderer(std::make_unique<Renderer>(context->loader())) {}

OffscreenRenderer::~OffscreenRenderer() {
    context->make_current();
    renderer.reset(); // GL objects go before the context
}

Image OffscreenRenderer::view(const Frame& frame, View v) {
    renderer->draw(frame, fit_camera(v, renderer->bounds(frame)), Viewport{0, 0, context->width(), context->height()},
                   context->framebuffer());
    return context->read_pixels();
}

Image OffscreenRenderer::view(const Frame& frame, const Camera& camera) {
    renderer->draw(frame, camera, Viewport{0, 0, context->width(), context->height()}, context->framebuffer());
    return context->read_pixels();
}

Image OffscreenRenderer::quad(const Frame& frame) {
    renderer->draw_quad(frame, fit_quad_cameras(renderer->bounds(frame)), context->width(), context->height(),
                        context->framebuffer());
    return context->read_pixels();
}

namespace {

MeshItem mesh_item(Renderer& r, const TriangleMesh& m, float opacity = 1.0f) {
    MeshItem item;
    item.mesh = r.add_mesh(m);
    item.style.opacity = opacity;
    return item;
}

SphereItem all_spheres(SphereSetHandle set) {
    SphereItem item;
    item.spheres = set;
    return item;
}

} // namespace

Frame figure_scene(Renderer& r) {
    Frame f;
    f.meshes.push_back(mesh_item(r, box_figure()));
    return f;
}

Frame level_spheres_scene(Renderer& r) {
    const TriangleMesh mesh = torus(1.0, 0.35, 48, 24);
    const SptDocument doc = make_document(mesh);
    const CompactTree compact(doc.trees.front(), doc.samples);
    Frame f;
    f.meshes.push_back(mesh_item(r, mesh, 0.15f));
    f.spheres.push_back(all_spheres(r.add_spheres(sampling_spheres(compact, doc.trees.front(), ColorBy::Level))));
    return f;
}

Frame node_dimmed_scene(Renderer& r) {
    const TriangleMesh mesh = box_figure();
    const SptDocument doc = make_document(mesh);
    const SamplingTree& tree = doc.trees.front();
    const CompactTree compact(tree, doc.samples);
    Frame f;
    const std::vector<SphereInstance> spheres = sampling_spheres(compact, tree, ColorBy::Level);
    const SphereSetHandle set = r.add_spheres(spheres);
    f.spheres = highlighted_node(set, uint32_t(spheres.size()), sphere_range(compact, tree, 3), true);
    return f;
}

Frame node_bounds_scene(Renderer& r) {
    const TriangleMesh mesh = box_figure();
    const SptDocument doc = make_document(mesh);
    const SamplingTree& tree = doc.trees.front();
    const CompactTree compact(tree, doc.samples);
    const NodeId node = 2;
    Frame f;
    f.meshes.push_back(mesh_item(r, mesh, 0.3f));
    const SphereSetHandle set = r.add_spheres(sampling_spheres(compact, tree, ColorBy::Level));
    SphereItem dim = all_spheres(set);
    dim.color = Color{0.78f, 0.79f, 0.82f, 1};
    f.spheres.push_back(dim);
    const SphereRange range = sphere_range(compact, tree, node);
    SphereItem lit = all_spheres(set);
    lit.first = range.first, lit.count = range.count, lit.color = highlight_color();
    f.spheres.push_back(lit);
    f.wire_spheres = bounding_spheres(tree, doc.samples.origin, node, 2, Color{0.85f, 0.1f, 0.1f, 1});
    return f;
}

Frame collision_scene(Renderer& r, size_t* pairs) {
    const TriangleMesh mesh = torus(1.0, 0.35, 48, 24);
    const SptDocument doc = make_document(mesh);
    const CompactTree compact(doc.trees.front(), doc.samples);
    // B is A turned upright, its rim pressed into the outer rim of A on the +X side.
    const Eigen::Affine3f pose_a = Eigen::Affine3f::Identity();
    const Eigen::Affine3f pose_b =
        Eigen::Translation3f(2.55f, 0.3f, 0.0f) * Eigen::AngleAxisf(float(M_PI / 2), Eigen::Vector3f::UnitX());
    Frame f;
    MeshItem a = mesh_item(r, mesh, 0.25f), b = a;
    b.pose = pose_b;
    a.style.color = Color{0.95f, 0.72f, 0.68f, 1};
    b.style.color = Color{0.68f, 0.78f, 0.96f, 1};
    f.meshes = {a, b};
    f.collision.pairs = overlapping_pairs(world_spheres(compact, pose_a), world_spheres(compact, pose_b));
    f.collision.contact_size = 4;
    if (pairs) *pairs = f.collision.pairs.size();
    return f;
}

Camera collision_close_up(const Frame& frame, View view) {
    Bounds b;
    for (const render::SpherePair& p : frame.collision.pairs) b.add_sphere(p.a.center, p.a.radius), b.add_sphere(p.b.center, p.b.radius);
    Camera c = fit_camera(view, b);
    c.radius *= 1.5f;
    return c;
}

Frame wire_trail_scene(Renderer& r) {
    Frame f;
    MeshItem item = mesh_item(r, box_figure());
    item.style.shading = Shading::Flat;
    item.style.wireframe = true;
    item.style.points = true;
    item.style.point_size = 2;
    f.meshes.push_back(item);
    Trail t;
    for (int i = 0; i <= 40; ++i) {
        const float s = float(i) / 40.0f;
        t.points.emplace_back(0.9f * std::cos(6.0f * s), 0.1f + 2.0f * s, 0.9f * std::sin(6.0f * s));
    }
    f.trails.push_back(t);
    return f;
}

} // namespace spt::test
