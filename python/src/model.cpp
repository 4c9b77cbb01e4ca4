// spt.load: the loading of `spt query` (cli/query_command.cpp), with the tree chosen by name or index.
#include "model.hpp"
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "spt/mesh.hpp"

namespace spt::python {
namespace {

// The name of the chosen tree; "" lets CollisionModel take the first, as `spt query` without --tree.
std::string tree_name(const SptDocument& doc, const std::string& path, const TreeChoice& tree) {
    if (const auto* name = std::get_if<std::string>(&tree)) return *name;
    if (const auto* index = std::get_if<long>(&tree)) {
        if (*index < 0 || size_t(*index) >= doc.trees.size())
            throw_bad_input(path, "no tree at index " + std::to_string(*index) + " (the file holds " +
                                      std::to_string(doc.trees.size()) + ")");
        return doc.trees[size_t(*index)].name();
    }
    return "";
}

} // namespace

Model load_model(const std::string& path, const TreeChoice& tree, const std::string& mesh_path) {
    Model m;
    m.path = path;
    if (is_spt_file(path)) {
        m.doc = load_spt(path);
        if (!mesh_path.empty()) m.mesh = import_mesh(mesh_path).mesh;
    } else {
        if (!mesh_path.empty())
            throw Error(ErrorKind::Usage, path + ": mesh= goes with a .spt file; a mesh brings its own triangles");
        m.mesh = import_mesh(path).mesh;
        m.doc = make_document(*m.mesh); // spt convert's defaults
    }
    const std::string name = tree_name(m.doc, path, tree);
    m.model = m.mesh ? CollisionModel(m.doc, *m.mesh, name) : CollisionModel(m.doc, name);
    m.tree = name.empty() && !m.doc.trees.empty() ? m.doc.trees.front().name() : name;
    return m;
}

} // namespace spt::python
