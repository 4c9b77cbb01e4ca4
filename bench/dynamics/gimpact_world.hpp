#pragma once
// The peer of effect dynamics in dynamics_bench: a scene built as a plain Bullet
// btDiscreteDynamicsWorld whose moving objects are btGImpactMeshShapes of their mesh triangles and
// whose static ones are btBvhTriangleMeshShapes (Bullet's shape for static concave meshes) or
// GImpact shapes too, with the masses, inertia, friction, restitution and solver settings spt's
// world gives them.
#include "spt/mesh.hpp"
#include "spt/pose.hpp"
#include "spt/scene.hpp"
#include <cstdint>
#include <memory>
#include <vector>

namespace bench {

/// What the benchmark reads of a stepping world, spt's or Bullet's.
class Engine {
public:
    virtual ~Engine() = default;
    /// One step of the scene's dt.
    virtual void step() = 0;
    /// Object i's pose now (its object frame, as the scene places it), world frame.
    virtual spt::Pose pose(size_t i) const = 0;
    /// Linear velocity of object i's frame origin now, world frame.
    virtual Eigen::Vector3d velocity(size_t i) const = 0;
    /// Kinetic plus potential energy of the moving objects (Simulation::mechanical_energy's sum).
    virtual double energy() const = 0;
    /// Object pairs with contact points after the last step.
    virtual size_t touching() const = 0;
    /// Wall nanoseconds of the last step's collision detection (broad and narrow phase).
    virtual int64_t collision_ns() const = 0;
};

/// Every object's triangles in its object frame, models used twice read once: the mesh file
/// (scaled), the `mesh` beside a `.spt` model, or for the pile's `.spt`-only pebble.spt and
/// grit.spt the icospheres tools/scenegen makes them from, checked against the file's mesh hash.
/// Throws spt::Error(BadInput) for another `.spt`-only model.
std::vector<std::shared_ptr<const spt::TriangleMesh>> object_meshes(const spt::Scene& scene);

/// How the GImpact world departs from spt's: what its behaviour depends on beyond the scene.
struct GImpactOptions {
    double margin = -1;         ///< collision margin of the GImpact shapes' triangles, model units; < 0: Bullet's own (0.01)
    bool bullet_solver = false; ///< Bullet's default solver settings (but the scene's iterations), not spt's
    bool static_gimpact = false; ///< static objects as GImpact shapes too, not btBvhTriangleMeshShape
};

/// The scene in Bullet with GImpact, one thread; path objects are refused.
class GImpactWorld final : public Engine {
public:
    /// `scene` (models loaded) and `meshes` (object_meshes) must outlive the world.
    GImpactWorld(const spt::Scene& scene, const std::vector<std::shared_ptr<const spt::TriangleMesh>>& meshes,
                 const GImpactOptions& options);
    ~GImpactWorld() override;
    void step() override;
    spt::Pose pose(size_t i) const override;
    Eigen::Vector3d velocity(size_t i) const override;
    double energy() const override;
    size_t touching() const override;
    int64_t collision_ns() const override;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace bench
