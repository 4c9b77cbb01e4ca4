// The renderer's frame cache: a redraw with only the sphere marks changed recolours the cached
// layers and gives the pixels of a full draw; an unchanged frame is composited again; any other
// change draws everything.
#include "scenes.hpp"
#include "test_meshes.hpp"
#include <gtest/gtest.h>

using namespace spt::render;
using spt::test::OffscreenRenderer;

namespace {

// The level-spheres scene (spheres inside a see-through torus, over the grid, under the axes) with
// marks drawn in orange on every sphere item, and its bounding sphere as wire (an overlay).
Frame marked_scene(Renderer& r) {
    Frame f = spt::test::level_spheres_scene(r);
    for (SphereItem& item : f.spheres) item.marked_color = Color{1.0f, 0.55f, 0.05f, 1};
    const Bounds b = r.bounds(f);
    f.wire_spheres.push_back(WireSphere{Sphere{b.center(), b.radius()}});
    return f;
}

// Every third sphere of the frame's first set.
std::vector<uint32_t> every_third(Renderer& r, const Frame& f) {
    std::vector<uint32_t> marked;
    for (uint32_t i = 0; i < r.sphere_count(f.spheres.front().spheres); i += 3) marked.push_back(i);
    return marked;
}

bool same_pixels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.rgba == b.rgba;
}

// A camera a little off `cam`, so that a draw through it cannot reuse the layers.
Camera nudged(Camera cam) {
    cam.zoom *= 1.01f;
    return cam;
}

} // namespace

TEST(frame_cache, marks_changed_recolours_the_same_pixels_as_a_full_draw) {
    for (View v : {View::Front, View::Camera}) {
        OffscreenRenderer r("osmesa", 160, 120);
        const Frame f = marked_scene(*r.renderer);
        const Camera cam = fit_camera(v, r.renderer->bounds(f));
        const Image unmarked = r.view(f, cam);
        EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Full);

        r.renderer->set_sphere_marks(f.spheres.front().spheres, every_third(*r.renderer, f));
        const Image recoloured = r.view(f, cam);
        EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Recoloured) << view_name(v);
        EXPECT_FALSE(same_pixels(recoloured, unmarked)) << view_name(v) << ": the marks changed nothing";

        r.view(f, nudged(cam));
        const Image full = r.view(f, cam);
        EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Full);
        EXPECT_TRUE(same_pixels(recoloured, full)) << view_name(v);
    }
}

TEST(frame_cache, marks_cleared_again_give_back_the_unmarked_picture) {
    OffscreenRenderer r("osmesa", 160, 120);
    const Frame f = marked_scene(*r.renderer);
    const Camera cam = fit_camera(View::Top, r.renderer->bounds(f));
    const Image unmarked = r.view(f, cam);
    r.renderer->set_sphere_marks(f.spheres.front().spheres, every_third(*r.renderer, f));
    r.view(f, cam);
    r.renderer->set_sphere_marks(f.spheres.front().spheres, {});
    EXPECT_TRUE(same_pixels(r.view(f, cam), unmarked));
    EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Recoloured);
}

TEST(frame_cache, unchanged_frame_is_composited_with_the_same_pixels) {
    OffscreenRenderer r("osmesa", 160, 120);
    const Frame f = marked_scene(*r.renderer);
    const Camera cam = fit_camera(View::Side, r.renderer->bounds(f));
    const Image first = r.view(f, cam);
    const Image again = r.view(f, cam);
    EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Composited);
    EXPECT_TRUE(same_pixels(first, again));
}

TEST(frame_cache, any_other_change_draws_everything) {
    OffscreenRenderer r("osmesa", 160, 120);
    Frame f = marked_scene(*r.renderer);
    const Camera cam = fit_camera(View::Front, r.renderer->bounds(f));
    r.view(f, cam);
    r.view(f, nudged(cam));
    EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Full) << "camera";
    f.spheres.front().fade = 0.5f;
    r.view(f, nudged(cam));
    EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Full) << "frame";
    r.renderer->update_spheres(f.spheres.front().spheres, std::vector<SphereInstance>(3));
    r.view(f, nudged(cam));
    EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Full) << "spheres uploaded again";
    // Marks do not show without a marked colour: changing them keeps the layers as they are.
    f.spheres.front().marked_color.reset();
    r.view(f, nudged(cam));
    r.renderer->set_sphere_marks(f.spheres.front().spheres, {0, 1});
    const Image after_marks = r.view(f, nudged(cam));
    EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Composited);
    r.view(f, cam);
    EXPECT_TRUE(same_pixels(after_marks, r.view(f, nudged(cam))));
    EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Full);
}

TEST(frame_cache, a_moved_mesh_draws_everything_again) {
    // A deformed pose moves the mesh's vertices under the same handle (the editor's timeline, a
    // scene's animated objects): the cached layers showed it where it was.
    OffscreenRenderer r("osmesa", 160, 120);
    const Frame f = spt::test::level_spheres_scene(*r.renderer);
    const Camera cam = fit_camera(View::Front, r.renderer->bounds(f));
    const Image before = r.view(f, cam);
    const spt::TriangleMesh mesh = spt::test::torus(1.0, 0.35, 48, 24); // the scene's mesh
    std::vector<Eigen::Vector3d> moved = mesh.positions;
    for (Eigen::Vector3d& p : moved) p.x() += 0.2;
    r.renderer->update_mesh(f.meshes.front().mesh, moved, mesh.normals);
    const Image after = r.view(f, cam);
    EXPECT_EQ(r.renderer->last_draw_kind(), DrawKind::Full);
    EXPECT_FALSE(same_pixels(after, before)) << "the moved mesh did not show";
    r.renderer->update_mesh(f.meshes.front().mesh, mesh.positions, mesh.normals);
    EXPECT_TRUE(same_pixels(r.view(f, cam), before)) << "the mesh back where it was draws as it did";
}
