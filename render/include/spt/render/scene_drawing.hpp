#pragma once
/// A simulated scene as a Frame: each object's mesh (or, for a .spt model, its sampling spheres)
/// at its pose, and the scene overlays (contacts, normals, manifold, pairs, ghost, trails). Shared by
/// `spt render SCENE.json` and a viewer, so both draw the same pixels. World frame, model units.
#include "spt/render/frame.hpp"
#include "spt/render/renderer.hpp"
#include "spt/deforming_model.hpp"
#include "spt/simulation.hpp"
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace spt::render {

/// What a scene frame shows on top of the objects.
struct SceneOverlays {
    bool contacts = false; ///< contact points of the colliding pairs (needs effect depth)
    bool normals = false;  ///< contact normals (needs effect depth)
    bool manifold = false; ///< contact manifold points and their normals, new and kept ones in two colours (effect dynamics)
    bool pairs = false;    ///< every overlapping sphere pair (needs effect pairs)
    bool ghost = false;    ///< objects at their pose before the response, see-through
    bool trails = false;   ///< the path of each moving object's origin so far
    bool spheres = false;  ///< sampling spheres of every object instead of its mesh
    bool bounds = false;   ///< each object's bounding sphere (its broad-phase sphere at rest), wire
    bool broad = false;    ///< the broad-phase spheres of the step (swept over it with ccd), wire
};

/// The flag of scene overlay `name` in `overlays`, spelled as `spt render --overlay` spells it
/// (contacts, normals, manifold, pairs, ghost, trails, spheres, bounds, broad); nullptr for any other name.
bool* scene_overlay_flag(SceneOverlays& overlays, std::string_view name);

/// The effects a simulation needs so that `overlays` can be drawn: `scene` plus contacts and
/// depth for contacts and normals, plus contacts and pairs for pairs. Nothing else is added:
/// manifold needs dynamics, which changes the motion, so it draws only what the scene runs.
EffectSet effects_for_overlays(EffectSet scene, const SceneOverlays& overlays);

/// Why `overlays` would draw nothing of a simulation with `effects` (manifold without effect
/// dynamics), naming the overlay and the effects; empty when every overlay can be drawn.
std::string scene_overlays_problem(EffectSet effects, const SceneOverlays& overlays);

/// The colour of a manifold point in overlay `manifold`: one for a point new this step (age 0),
/// another for one kept from earlier steps (the solver warm-starts it).
Color manifold_point_color(int age);

/// The uploaded geometry of one scene.
class SceneDrawing {
public:
    /// Uploads each distinct model once: the mesh of a mesh model (imported again, scaled) or of a
    /// .spt model given its mesh, and every model's sampling spheres; an animated object gets its
    /// own uploads, posed by show_time. Throws Error(BadInput) if a mesh cannot be read.
    SceneDrawing(Renderer& renderer, const Scene& scene);
    ~SceneDrawing();

    /// Poses every animated object at scene time `time` (seconds) as the effect `deform` does, or
    /// at its bind pose when `deform` is false (a simulation without the effect), and uploads its
    /// mesh and spheres: call before frame() for a scene whose objects deform.
    void show_time(Renderer& renderer, double time, bool deform);

    /// The frame of one state: `poses` (world, object order), the step that led to it (nullptr
    /// for the initial state), the poses before its response (`ghost`), each object's origin
    /// positions so far (`trails`) and the step's broad-phase spheres (`broad`); the last three
    /// may be empty when their overlay is off.
    Frame frame(const std::vector<Pose>& poses, const StepResult* step, const std::vector<Pose>& ghost,
                const std::vector<std::vector<Eigen::Vector3f>>& trails, const std::vector<BroadSphere>& broad,
                const SceneOverlays& overlays) const;
    /// The box `spt render` and the viewer fit their cameras to, so that frames line up: the
    /// objects at their initial poses, no overlays (world frame; a point at the origin if empty).
    Bounds initial_bounds(const Renderer& renderer) const;
    /// Frees the uploads in `renderer` (the one given to the constructor; its context current).
    void release(Renderer& renderer);

private:
    const Scene& scene_;
    std::vector<MeshHandle> mesh_;      // per object; id 0 without a mesh
    std::vector<SphereSetHandle> set_;  // per object
    std::vector<std::unique_ptr<DeformingModel>> deforming_; // per object: its own pose when animated
    // The model an object's spheres and pairs are drawn from: its posed one when animated.
    const CollisionModel& model_of(size_t i) const;
};

} // namespace spt::render
