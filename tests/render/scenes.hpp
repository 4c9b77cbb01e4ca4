#pragma once
// The scenes of the golden images, shared by the golden tests and the backend test.
#include "spt/render/offscreen.hpp"
#include "spt/render/renderer.hpp"
#include <memory>
#include <string>

namespace spt::test {

// An off-screen context and a renderer on it.
struct OffscreenRenderer {
    std::unique_ptr<render::OffscreenContext> context;
    std::unique_ptr<render::Renderer> renderer;

    OffscreenRenderer(const std::string& backend, int width, int height);
    ~OffscreenRenderer();
    // Renders one view fitted to the frame.
    render::Image view(const render::Frame& frame, render::View view);
    // Renders one view through `camera`.
    render::Image view(const render::Frame& frame, const render::Camera& camera);
    // Renders the 2x2 layout fitted to the frame.
    render::Image quad(const render::Frame& frame);
};

// The box figure, smooth shaded, grid and axes.
render::Frame figure_scene(render::Renderer& r);
// A torus's sampling spheres (tree built with default options) coloured by level,
// inside the see-through torus.
render::Frame level_spheres_scene(render::Renderer& r);
// The figure's tree: bounding spheres of node 2 and two levels below it, the
// node's spheres highlighted over the others.
render::Frame node_bounds_scene(render::Renderer& r);
/// The figure's spheres by level with node 3 highlighted and the rest dimmed (highlighted_node), no mesh.
render::Frame node_dimmed_scene(render::Renderer& r);
// Two tori, the second posed to overlap the first; colliding sampling-sphere pairs
// (brute force) with contact points and normals. `pairs` receives their number.
render::Frame collision_scene(render::Renderer& r, size_t* pairs = nullptr);
// A camera of `view` on the colliding pairs of `frame` and their surroundings.
render::Camera collision_close_up(const render::Frame& frame, render::View view);
// The figure flat shaded with wireframe and vertices, and a motion trail.
render::Frame wire_trail_scene(render::Renderer& r);

} // namespace spt::test
