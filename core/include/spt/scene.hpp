#pragma once
/// Scenes: objects with collision models, poses and motions, and the closed list of
/// effects a simulation of them computes (docs/scenes.md). World frame, model units,
/// seconds. Scene files are JSON; JSON stays inside the library.
#include "spt/animation.hpp"
#include "spt/collision_model.hpp"
#include "spt/mesh.hpp"
#include "spt/pose.hpp"
#include "spt/query.hpp"
#include "spt/response.hpp"
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace spt {

/// One effect of the closed list; a simulation runs the code of the listed ones only.
enum class Effect : uint8_t {
    Motion,   ///< objects move by their velocities and paths
    Gravity,  ///< dynamic objects accelerate (needs motion)
    Contacts, ///< broad phase, then the `any` query for every candidate pair
    Depth,    ///< deepest sphere pair, contact point and normal per colliding pair (needs contacts)
    Pairs,    ///< every colliding sphere pair, for drawing (needs contacts)
    Response, ///< colliding objects moved back by the rule (needs depth)
    Ccd,      ///< time of impact within the step for moving pairs (needs contacts and motion)
    Exact,    ///< contacts confirmed by the exact level (needs contacts)
    Deform,   ///< animated objects take their clip's pose at each step's time (docs/deforming.md)
    Dynamics, ///< rigid-body dynamics on sampling-sphere contact manifolds (needs contacts and motion)
};

/// Number of effects in the closed list.
constexpr int kEffectCount = 10;

/// The name of an effect as scene files and `--effects` spell it.
const char* effect_name(Effect e);

/// A set of effects.
class EffectSet {
public:
    /// The empty set.
    EffectSet() = default;
    /// True if `e` is in the set.
    bool has(Effect e) const { return (bits_ >> int(e)) & 1u; }
    /// Adds `e`.
    void add(Effect e) { bits_ |= 1u << int(e); }
    /// Bit i set for effect i.
    uint32_t bits() const { return bits_; }
    /// The names in list order, comma-separated ("motion,contacts").
    std::string names() const;

private:
    uint32_t bits_ = 0;
};

/// Parses effect names. An unknown name, an effect without one it needs, or two that exclude
/// each other (`response` and `dynamics`, `ccd` and `dynamics`, `exact` and `dynamics`) throws
/// Error(BadInput) naming both, prefixed with `where` (a file and JSON path, or an option).
EffectSet parse_effects(const std::vector<std::string>& names, const std::string& where);

/// Splits "a,b,c" and parses it as parse_effects does.
EffectSet parse_effect_list(const std::string& comma_separated, const std::string& where);

/// How an object moves.
enum class MotionKind : uint8_t {
    Static,   ///< never moves; two static objects are never tested against each other
    Velocity, ///< moves by its velocities (and gravity): a dynamic object
    Path,     ///< follows keyframes (kinematic: response does not move it)
};

/// A keyframe of a path.
struct Keyframe {
    double t = 0;                                                  ///< seconds
    Eigen::Vector3d position = Eigen::Vector3d::Zero();           ///< world frame, model units
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity(); ///< object to world, unit
};

/// Pose on a path at time t (seconds): linear position, slerp orientation between the keyframes
/// around t; held at the first and last keyframes outside them.
Pose path_pose(const std::vector<Keyframe>& path, double t);

/// Velocity on a path at time t (seconds), world frame: the linear (model units / s) and angular
/// (rad / s) velocity of the segment that starts at or before t; zero before the first keyframe
/// and from the last on (the path holds its ends).
std::pair<Eigen::Vector3d, Eigen::Vector3d> path_velocity(const std::vector<Keyframe>& path, double t);

/// How an object's animation clip plays (objects[].animation): at scene time t the clip's time is
/// offset + speed * t, wrapped into the clip when `loop`, held at its ends otherwise (clip_time).
struct AnimationSettings {
    std::string clip = "0"; ///< the clip's name, or its index in decimal
    double speed = 1;       ///< clip seconds per scene second
    double offset = 0;      ///< clip seconds at scene time 0
    bool loop = true;       ///< wrap into the clip's duration
};

/// How `dynamics` solves contacts (top-level "dynamics"); objects may override friction and restitution.
struct DynamicsSettings {
    double friction = 0.5;   ///< Coulomb friction coefficient, >= 0
    double restitution = 0;  ///< 0..1: share of the approaching normal speed kept after a contact
    double rolling_friction = 0; ///< >= 0, model units: torque against rolling = this x normal force (Bullet's)
    int iterations = 10;     ///< solver iterations a step, 1..1000
};

/// One object of a scene.
struct SceneObject {
    std::string name;         ///< unique within the scene
    std::string model_path;   ///< resolved path of the .spt file or mesh
    std::string mesh_path;    ///< resolved path of the mesh a .spt model was made from (objects[].mesh); empty: none
    std::string tree;         ///< tree name; empty: the first
    double scale = 1;         ///< uniform scale applied to the mesh before conversion
    MotionKind motion = MotionKind::Static; ///< how it moves
    Pose pose;                ///< initial pose, world frame
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();         ///< world frame, model units / s
    Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero(); ///< world frame, radians / s
    std::vector<Keyframe> path; ///< keyframes in increasing t (MotionKind::Path)
    std::shared_ptr<const CollisionModel> model; ///< shared between objects of the same model
    bool animated = false;          ///< has objects[].animation
    AnimationSettings animation;    ///< how its clip plays (animated)
    size_t clip = 0;                ///< index of its clip in animated_mesh->clips (load_models)
    std::shared_ptr<const AnimatedMesh> animated_mesh; ///< its mesh, rig and clips (animated, load_models)
    std::shared_ptr<const SptDocument> document;       ///< the document its model came from (animated, load_models)
    double mass = 0;     ///< objects[].mass, > 0; 0: from `density` and the closed mesh
    double density = 1;  ///< objects[].density, > 0: mass = density x volume of a closed mesh
    double friction = -1;    ///< objects[].friction (>= 0); < 0: not set, the scene's applies
    double restitution = -1; ///< objects[].restitution (0..1); < 0: not set, the scene's applies
    double rolling_friction = -1; ///< objects[].rolling_friction (>= 0); < 0: not set, the scene's applies
    /// The closed mesh's volume, centre of mass and inertia (load_models); null for an open mesh or a
    /// `.spt` model without a mesh.
    std::shared_ptr<const SolidMass> solid;
    /// Broad-phase sphere in the object frame: holds every sampling sphere and, with a mesh,
    /// every triangle of the model (model units).
    Eigen::Vector3d bound_center = Eigen::Vector3d::Zero();
    double bound_radius = 0; ///< model units
};

/// How `response` moves colliding objects back.
struct ResponseSettings {
    BacktrackRule rule = BacktrackRule::Exact; ///< `backtrack` (exact along the motion) or `paper`
    double restitution = 0; ///< 0..1: share of the approaching normal velocity reflected
};

/// A scene as read from a file.
struct Scene {
    std::string file;   ///< the scene file, as given
    double dt = 0.01;   ///< seconds a step
    int steps = 100;    ///< steps `spt simulate` runs by default
    Eigen::Vector3d gravity{0, -9.81, 0}; ///< model units / s^2
    EffectSet effects;  ///< what a simulation computes
    ResponseSettings response; ///< the response rule
    DynamicsSettings dynamics; ///< the solver's settings (effect dynamics)
    QueryLevel level = QueryLevel::Spheres; ///< level of the contact queries
    std::vector<SceneObject> objects; ///< in file order
};

/// Reads a scene file and loads its models (meshes converted with default options; a model
/// used twice is loaded once and kept in a process-wide cache keyed by file, time and scale).
/// Throws Error(BadInput) with the file and the JSON path of the problem, or Cancelled once
/// `cancel` (may be null) is set: reading and converting a mesh look at it (ImportOptions::cancel).
Scene load_scene(const std::string& path, const std::atomic<bool>* cancel = nullptr);

/// Parses scene JSON text; model paths are resolved against `base_dir`, models not loaded.
/// `file` names the text in messages.
Scene parse_scene(const std::string& text, const std::string& file, const std::string& base_dir);

/// Loads every object's model (and its broad-phase sphere). Throws Error(BadInput), or
/// Cancelled once `cancel` (may be null) is set; a model stopped so is not cached.
void load_models(Scene& scene, const std::atomic<bool>* cancel = nullptr);

/// Gives object `o` another model of the same object (another tree, or a document of its mesh):
/// tree `tree` (the first if empty) of `doc`, with `mesh` (the mesh `doc` was made from, with its
/// clips if the object is animated; may be null: spheres only, and an animated object keeps its
/// own mesh, which must then be the document's). The broad-phase sphere is fitted again.
/// Error(BadInput) naming the object if the document has no such tree or the mesh is another.
void set_object_model(SceneObject& o, std::shared_ptr<const SptDocument> doc, const std::string& tree,
                      std::shared_ptr<const AnimatedMesh> mesh);

} // namespace spt
