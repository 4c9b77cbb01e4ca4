#pragma once
// A loaded object as `spt query` loads one: a .spt file (its mesh optional, for level `exact`) or a
// mesh converted with `spt convert`'s defaults, and the collision model over them.
#include "spt/collision_model.hpp"
#include "spt/spt_file.hpp"
#include <optional>
#include <string>
#include <variant>

namespace spt::python {

/// Which tree of a .spt file: by name, by index, or (monostate) the first, as `spt query --tree`.
using TreeChoice = std::variant<std::monostate, std::string, long>;

/// What spt.load returns; immutable once made, so queries on several threads may share it.
struct Model {
    std::string path;                // the file it was loaded from, for repr and messages
    std::string tree;                // the name of the tree the model uses
    SptDocument doc;                 // kept with the model, as the CLI keeps it
    std::optional<TriangleMesh> mesh; // the triangles of level `exact`, when known
    CollisionModel model;
};

/// Loads `path` (a .spt file, or a mesh converted in memory with default options), the tree
/// `tree` of it, and `mesh_path`'s triangles for a .spt file (empty: none). Throws spt::Error.
Model load_model(const std::string& path, const TreeChoice& tree, const std::string& mesh_path);

} // namespace spt::python
