#pragma once
/// Mesh to sampling-tree document in one call: what `spt convert` and tools that
/// accept a mesh in place of a .spt file do.
#include "spt/recipe.hpp"
#include "spt/spt_file.hpp"
#include "spt/tree_builder.hpp"
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace spt {

/// Options for make_document.
struct ConvertOptions {
    BuildOptions build;              ///< tree shape, radius rule, bounds
    /// Model units: adds face samples so that no surface point is more than tolerance/2
    /// outside every sampling sphere (two objects' gaps together stay within it).
    std::optional<double> tolerance;
    /// How far a sampling sphere may poke out of the mesh, model units. Default: an eighth
    /// of the tolerance if set, else kDefaultProtrusion x the mesh diagonal. Two-sided spheres (open
    /// parts) take up to this, or without it a quarter of the tolerance (docs/sampling.md).
    std::optional<double> protrusion;
    /// The mesh at further poses (a deforming object's clips; spt::clip_poses gives them): the same
    /// vertices and triangles, moved, with the normals of that pose. Each one-sided sampling
    /// sphere's radius is then limited at every one of them as at the mesh itself, so that it
    /// pokes out by at most the allowance wherever the clips take the surface, not only at the
    /// bind pose (docs/sampling.md, "The promise on a deforming object"). Empty: the mesh alone.
    std::vector<TriangleMesh> poses;
    std::string tree_name = "default"; ///< name of the tree in the document
    /// Without a tolerance: if vertex samples alone would leave the surface uncovered deeper
    /// than kAutoTolerance x the diagonal, or leave a face of an open part partly outside every
    /// sphere, sample the faces to that tolerance (open parts: until their spheres hold them).
    bool auto_tolerance = true;
    /// Threads that sample vertices and faces (0: the machine's cores). The document is the
    /// same, byte for byte, whatever the count.
    int threads = 0;
    /// A host's threads for the sampling and the tree (spt/task_system.hpp); null: the library's
    /// pool. Overrides build.tasks.
    TaskSystem* tasks = nullptr;
    /// Another thread sets it to stop the conversion: make_document looks at it as each stage
    /// starts, every 256 vertices or faces while sampling (and every 256 probes inside one face),
    /// and through the tree builder (BuildOptions::cancel), and throws Cancelled. Null: never stops.
    const std::atomic<bool>* cancel = nullptr;
    /// Called (on the converting thread) as each stage starts, with its name: "sampling
    /// vertices", "sampling faces", "building the tree"; stages come again when the automatic
    /// tolerance samples the faces after a first tree.
    std::function<void(const std::string& stage)> on_stage;
};

/// Default protrusion allowance as a fraction of the mesh diagonal: two objects together
/// stay well inside the 1% band in which the accuracy targets are set.
constexpr double kDefaultProtrusion = 0.0025;

/// Tolerance applied automatically (fraction of the diagonal) when vertices leave holes.
constexpr double kAutoTolerance = 0.005;

/// Most samples a conversion with face samples makes (about 1.2 GB in memory, as much again
/// as a file): a tolerance that would need more, far below the mesh's own detail, is refused
/// as bad input.
constexpr size_t kMaxSamples = size_t(1) << 25;

/// What make_document did beyond the document itself.
struct ConvertStats {
    size_t vertex_samples = 0;       ///< samples at mesh vertices
    size_t face_samples = 0;         ///< samples added on faces (tolerance-driven)
    double worst_predicted_gap = 0;  ///< largest uncovered depth the final radii allow on a face, model units
    double automatic_tolerance = 0;  ///< > 0: the tolerance applied because vertices left holes
    size_t uncovered_open_faces = 0; ///< faces of open parts that vertex samples alone leave partly outside every
                                     ///< (two-sided) sphere; any makes the automatic tolerance apply
    double sample_seconds = 0;       ///< wall time of sampling and radius limiting, seconds
    double build_seconds = 0;        ///< wall time of building the tree, seconds
};

/// Samples `mesh` and builds one tree over the samples.
SptDocument make_document(const TriangleMesh& mesh, const ConvertOptions& options = {},
                          ConvertStats* stats = nullptr);

/// One tree that replay_trees made.
struct TreeReplay {
    std::string tree;                 ///< its name, as in the recipe document
    bool built_automatically = false; ///< the recipe document's tree had no recipe: built with the options
    size_t steps = 0;                 ///< authoring steps in its recipe
    ReplayReport report;              ///< what replaying them did (nothing when built automatically)
    size_t motion_builds = 0;         ///< builds from motion redone after the steps (their scenes run again)
};

/// Replaces `doc`'s trees with the trees of `recipes` (an authored document of an earlier mesh)
/// over `doc`'s samples of `mesh`: a tree with an authoring recipe is replayed split by split,
/// one without is built with `build`. One entry per tree, in order; on an exception `doc` is
/// unchanged. What `spt convert NEW_MESH --recipe OLD.spt` does after sampling. Steps made at a
/// clip's pose (recipe_has_poses) need `animated`, `mesh` with its clips (mesh must be its
/// imported.mesh), and select at that pose; without it they are Error(BadInput).
/// A tree that records builds from motion (SamplingTree::motion_builds) has them redone after its
/// steps: each scene (a relative path resolved against `recipe_folder`, the recipe file's folder) is
/// run again with the new samples (replay_motion_builds); a split made after such a build is
/// Error(BadInput).
std::vector<TreeReplay> replay_trees(SptDocument& doc, const TriangleMesh& mesh, const SptDocument& recipes,
                                     const BuildOptions& build, std::shared_ptr<const AnimatedMesh> animated = nullptr,
                                     const std::string& recipe_folder = {});

/// Builds another tree named `name` over the samples already in `doc` (the paper keeps one a
/// kind of motion) and adds it, replacing one of that name only if `replace`. `mesh` must be
/// the document's mesh (else BadInput); a tree of that name without `replace` is CannotWrite;
/// `path` names the document in messages. Face samples keep the tree radius-coherent, so a
/// tolerance the samples were made for still holds. `stats` gets the sample counts and the
/// build time. What `spt convert MESH -o DOC.spt --append --tree-name NAME` does.
const SamplingTree& append_tree(SptDocument& doc, const TriangleMesh& mesh, const std::string& name,
                                BuildOptions build, bool replace, const std::string& path,
                                ConvertStats* stats = nullptr);

/// Reads a .spt file, or imports a mesh and converts it with default options.
SptDocument load_or_convert(const std::string& path, const ConvertOptions& options = {});

} // namespace spt
