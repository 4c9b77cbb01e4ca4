// Scene: the document as render data, rebuilt piecewise on the document's signals.
#include "scene.hpp"

namespace spt::editor {

render::Color selection_color() { return {1.0f, 0.55f, 0.05f, 1.0f}; }

Scene::Scene(EditorDocument& doc, QObject* parent) : QObject(parent), doc_(doc) {
    connect(&doc_, &EditorDocument::documentReset, this, [this] {
        rebuild_mesh();
        rebuild_tree();
    });
    connect(&doc_, &EditorDocument::treeChanged, this, &Scene::rebuild_tree);
    connect(&doc_, &EditorDocument::currentChanged, this, [this] {
        rebuild_current();
        rebuild_selection();
    });
    connect(&doc_, &EditorDocument::selectionChanged, this, &Scene::rebuild_selection);
}

void Scene::set_color_by(render::ColorBy by) {
    if (by == color_by_) return;
    color_by_ = by;
    rebuild_tree();
}

void Scene::rebuild_mesh() {
    data_.mesh = doc_.mesh();
    ++data_.mesh_revision;
}

void Scene::rebuild_tree() {
    data_.spheres.clear();
    compact_.reset();
    sample_radius_.assign(doc_.samples().size(), 0.0f);
    if (doc_.has_tree()) {
        compact_ = std::make_unique<CompactTree>(doc_.tree(), doc_.samples());
        data_.spheres = render::sampling_spheres(*compact_, doc_.tree(), color_by_);
        for (const TreeNode* n : doc_.tree().active_nodes())
            for (uint32_t s : n->samples) sample_radius_[s] = n->ss_radius;
    }
    ++data_.spheres_revision;
    rebuild_current();
    rebuild_selection();
}

void Scene::rebuild_current() {
    data_.highlight = {};
    data_.wires.clear();
    if (doc_.has_tree() && compact_) {
        data_.highlight = render::sphere_range(*compact_, doc_.tree(), doc_.current());
        data_.wires = render::bounding_spheres(doc_.tree(), doc_.samples().origin, doc_.current(), 0,
                                               render::highlight_color());
    }
    ++data_.revision;
}

void Scene::rebuild_selection() {
    data_.selected.clear();
    const SampleSet& s = doc_.samples();
    // The same float arithmetic as the tree's spheres, so a selected sphere covers its sphere exactly.
    const Eigen::Vector3f origin = s.origin.cast<float>();
    for (uint32_t i : doc_.selection()) {
        const float r = sample_radius_[i];
        data_.selected.push_back({{origin + s.sphere_centre(i, r), r}, selection_color()});
    }
    ++data_.selected_revision;
    ++data_.revision;
    emit changed();
}

render::Frame Scene::frame(render::MeshHandle mesh, render::SphereSetHandle spheres,
                           render::SphereSetHandle selected) const {
    render::Frame f;
    if (data_.mesh && mesh.id) {
        render::MeshItem item;
        item.mesh = mesh;
        // Sampling spheres lie inside the surface: they show through a see-through mesh.
        item.style.opacity = data_.spheres.empty() ? 1.0f : 0.3f;
        f.meshes.push_back(item);
    }
    if (!data_.spheres.empty() && spheres.id)
        for (const render::SphereItem& item :
             render::highlighted_node(spheres, uint32_t(data_.spheres.size()), data_.highlight, true))
            f.spheres.push_back(item);
    if (!data_.selected.empty() && selected.id) {
        render::SphereItem sel;
        sel.spheres = selected;
        f.spheres.push_back(sel);
    }
    f.wire_spheres = data_.wires;
    return f;
}

} // namespace spt::editor
