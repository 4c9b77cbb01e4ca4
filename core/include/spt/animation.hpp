#pragma once
/// Skeletal animation and morph targets of an imported mesh (docs/deforming.md): a rig that
/// poses the mesh's welded vertices, and the clips that drive it. Skinning is glTF 2.0's linear
/// blend skinning: a vertex is the sum over at most 4 joints of w_i * (G_i * B_i) * v, G_i the
/// joint's global transform at the pose, B_i its inverse bind matrix, v the vertex in its mesh's
/// space after morph targets. Times in seconds; positions in model units, the file's root frame.
#include "spt/mesh.hpp"
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace spt {

/// How a track's value goes from one key to the next (glTF 2.0 sampler interpolation).
enum class Interpolation {
    Linear,     ///< translation, scale and weights lerp; rotation slerps
    Step,       ///< the earlier key's value holds until the next key
    CubicSpline ///< cubic Hermite through the keys with their in- and out-tangents
};

/// The keys of one animated property. `values` has one entry per key; with CubicSpline,
/// `in_tangents` and `out_tangents` have one each too (otherwise they are empty).
template <class Value>
struct Track {
    Interpolation interpolation = Interpolation::Linear;
    std::vector<double> times; ///< seconds from the clip's start, strictly ascending
    std::vector<Value> values, in_tangents, out_tangents;
    /// True when the track has no keys (the property keeps its rest value).
    bool empty() const { return times.empty(); }
};

/// What a clip does to one node of the hierarchy: each empty track keeps the node's rest value.
struct NodeChannel {
    uint32_t node = 0;                       ///< index into Rig::nodes
    Track<Eigen::Vector3d> translation;      ///< node's local translation
    Track<Eigen::Vector4d> rotation;         ///< node's local rotation as a quaternion (x, y, z, w)
    Track<Eigen::Vector3d> scale;            ///< node's local scale
};

/// What a clip does to the morph-target weights of one mesh of the file.
struct MorphChannel {
    uint32_t first_target = 0; ///< index into Rig::morph_targets of the mesh's first target
    uint32_t target_count = 0; ///< its number of targets; each key's value has this many weights
    Track<std::vector<double>> weights;
};

/// One named animation of the file (glTF's animation, FBX's take).
struct Clip {
    std::string name;     ///< as the file names it ("clip N" when it has no name)
    double duration = 0;  ///< seconds: its last key's time (0 for a clip of one pose)
    std::vector<NodeChannel> nodes;
    std::vector<MorphChannel> morphs;
    /// Number of distinct joints (nodes that move a skinned vertex) the clip animates.
    uint32_t joints_animated = 0;
};

/// A node of the file's hierarchy, parents before their children.
struct RigNode {
    std::string name;
    int32_t parent = -1;              ///< index into Rig::nodes, -1 for the root
    Eigen::Matrix4d rest_local;       ///< transform relative to the parent at rest, as the file has it
    Eigen::Vector3d rest_translation; ///< rest_local decomposed, for channels that leave a part at rest
    Eigen::Quaterniond rest_rotation;
    Eigen::Vector3d rest_scale;
};

/// One transform a vertex can follow: node `node`'s global transform times `offset` (the inverse
/// bind matrix of a joint, or the identity for a mesh that hangs rigidly from its node).
struct BoneSlot {
    uint32_t node = 0;
    Eigen::Matrix4d offset = Eigen::Matrix4d::Identity();
};

/// Up to four slots a vertex follows, weights normalised to sum 1 (unused entries weigh 0).
struct VertexInfluences {
    std::array<uint32_t, 4> slot{0, 0, 0, 0};
    std::array<double, 4> weight{0, 0, 0, 0};
};

/// A morph target of one mesh: position offsets for some of the welded vertices.
struct MorphTarget {
    std::string name;
    std::vector<uint32_t> vertices;      ///< welded vertex indices it moves
    std::vector<Eigen::Vector3d> delta;  ///< their offsets in mesh space at weight 1
    double default_weight = 0;           ///< the weight when no clip drives it
};

/// What poses a mesh: its welded vertices in their meshes' spaces and what each follows.
struct Rig {
    std::vector<RigNode> nodes;
    std::vector<BoneSlot> bone_slots;
    std::vector<Eigen::Vector3d> mesh_positions; ///< per welded vertex, in its mesh's space
    std::vector<VertexInfluences> influences;    ///< per welded vertex
    std::vector<MorphTarget> morph_targets;
    std::vector<uint8_t> joint_nodes;            ///< per node: 1 if some skinned vertex follows it
    size_t joint_count = 0;                      ///< nodes that are joints of a skin
    bool skinned = false;                        ///< some mesh of the file has bones
    double scale = 1;                            ///< uniform scale of posed vertices (a scene's `scale`)
};

/// A mesh with what animates it.
struct AnimatedMesh {
    ImportedMesh imported;   ///< the mesh at its bind pose, as import_mesh reads it
    Rig rig;
    std::vector<Clip> clips; ///< in file order
    /// Index of the clip named `name`, or of clip number `name` when it is a decimal index;
    /// throws Error(Usage) naming the clips the mesh has when there is none.
    size_t find_clip(const std::string& name) const;
};

/// Reads a mesh file as import_mesh does, plus its skins, morph targets and animations
/// (glTF 2.0, FBX, Collada, SMD, MDL: what assimp reads of them; a glTF 2.0 file's clips and skin
/// weights as its own samplers and accessors say, STEP and CUBICSPLINE kept). A file without them
/// gives an empty rig and no clips. Throws Error(BadInput) naming the file for joint weights that are not
/// finite or sum to 0, key times out of order or not finite, non-finite key values; more than 4
/// joints on a vertex keeps the 4 heaviest and says so in imported.report.warnings.
AnimatedMesh import_animated_mesh(const std::string& path, const ImportOptions& options = {});

/// Whether a mesh file's format can hold skins, morph targets or clips: false for OBJ, PLY, STL
/// and OFF (by the file name's extension, any case), which a caller need not read again for them.
bool may_hold_animation(const std::string& path);

/// A clip's time for a scene's time `t` (seconds): offset + speed * t, wrapped into
/// [0, duration] when `loop`, held at 0 or duration otherwise. A clip of zero duration gives 0.
double clip_time(const Clip& clip, double t, double speed = 1, double offset = 0, bool loop = true);

/// The welded vertices of `mesh` posed by `clip` at `time` seconds (clamped to the clip; a null
/// clip: the rest pose of the hierarchy), into `positions` (resized), model units.
void pose_vertices(const AnimatedMesh& mesh, const Clip* clip, double time, std::vector<Eigen::Vector3d>& positions);

/// The mesh posed by `clip` at `time` seconds (a null clip: the rest pose of the hierarchy):
/// positions from pose_vertices, vertex normals recomputed as import computes them.
TriangleMesh posed_mesh(const AnimatedMesh& mesh, const Clip* clip, double time);

/// The mesh posed along every clip, `step` seconds apart from each clip's start, and at its end
/// (posed_mesh): the poses at which ConvertOptions::poses limits a deforming object's spheres.
/// A clip longer than `max_per_clip` steps gets that many poses, spread evenly, and so does every
/// clip when the poses, with what the radius limiter builds over each, would take more than about
/// `max_bytes` (long captures, many clips, large meshes; at least each clip's start and end).
/// Empty without clips; Error(Usage) unless step > 0.
std::vector<TriangleMesh> clip_poses(const AnimatedMesh& mesh, double step, size_t max_per_clip = 240,
                                     size_t max_bytes = size_t(1) << 30);

/// How much a clip stretches the mesh's surface (docs/deforming.md, "Stretch"): over poses every
/// 1/frames_per_second seconds of the clip (its ends included), the largest ratio of an edge's
/// posed length to its bind length, when and where. Coverage gaps between sampling spheres grow
/// about as the square of the stretch (the spacing of the samples grows with it, their radii do not).
struct ClipStretch {
    double largest = 1;        ///< largest posed / bind edge length (1: nothing stretches)
    double smallest = 1;       ///< smallest ratio (compression)
    double time = 0;           ///< clip seconds of the pose with the largest stretch
    uint32_t edge[2] = {0, 0}; ///< the edge's two welded vertices
    Eigen::Vector3d where = Eigen::Vector3d::Zero(); ///< the edge's middle at the bind pose, object frame
    std::string joint;         ///< the joint its first vertex follows most ("" without a skin)
    /// How much deeper the coverage gaps there get than at the bind pose: largest squared.
    double gap_factor() const { return largest * largest; }
};

/// Measures `clip`'s stretch of `mesh` (see ClipStretch); frames_per_second > 0.
ClipStretch measure_stretch(const AnimatedMesh& mesh, const Clip& clip, double frames_per_second = 60);

/// Global transforms of every rig node posed by `clip` at `time` (a null clip: at rest), in
/// Rig::nodes order.
std::vector<Eigen::Affine3d> pose_nodes(const Rig& rig, const Clip* clip, double time);

} // namespace spt
