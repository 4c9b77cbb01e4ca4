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
    connect(&doc_, &EditorDocument::visibilityChanged, this, [this] {
        rebuild_shown();
        emit changed();
    });
    // Another pose moves the mesh and the spheres; the layout, the highlight and the selection stay.
    connect(&doc_, &EditorDocument::poseChanged, this, [this] {
        rebuild_pose();
        rebuild_spheres();
        rebuild_current();
        rebuild_selection();
    });
}

void Scene::set_color_by(render::ColorBy by) {
    if (by == color_by_) return;
    color_by_ = by;
    rebuild_tree();
}

void Scene::set_motion(std::shared_ptr<const MotionRecording> motion) {
    motion_ = std::move(motion);
    if (color_by_ == render::ColorBy::Contacts) rebuild_tree();
}

void Scene::rebuild_mesh() {
    data_.mesh = doc_.mesh();
    data_.origin = doc_.samples().origin;
    ++data_.mesh_revision;
    rebuild_pose();
}

void Scene::rebuild_pose() {
    data_.vertices = data_.normals = nullptr;
    if (!doc_.animation() || !data_.mesh) return; // a mesh without clips stays as uploaded
    // At the bind pose, the mesh's own vertices: back where the timeline started.
    const DeformingModel* posed = doc_.posed();
    data_.vertices = posed ? &posed->vertices() : &data_.mesh->positions;
    data_.normals = posed ? &posed->vertex_normals() : &data_.mesh->normals;
    ++data_.pose_revision;
}

void Scene::rebuild_tree() {
    compact_.reset();
    sphere_of_sample_.assign(doc_.samples().size(), UINT32_MAX);
    if (doc_.has_tree()) {
        compact_ = std::make_unique<CompactTree>(doc_.tree(), doc_.samples());
        const uint32_t* sample = compact_->sample_index();
        for (uint32_t k = 0; k < uint32_t(compact_->sphere_count()); ++k)
            if (sample[k] < sphere_of_sample_.size()) sphere_of_sample_[sample[k]] = k;
    }
    rebuild_pose(); // an edit binds the tree to the pose again: the model is new
    rebuild_spheres();
    rebuild_legend();
    rebuild_shown();
    rebuild_current();
    rebuild_selection();
}

const std::vector<uint32_t>* Scene::contact_counts() const {
    // The motion's counts are per sample of the document it was recorded with: another
    // document's (a file opened since) colour nothing.
    return motion_ && motion_->contact_steps.size() == doc_.samples().size() ? &motion_->contact_steps : nullptr;
}

void Scene::rebuild_spheres() {
    data_.spheres.clear();
    if (doc_.has_tree() && compact_) {
        // At a pose, the posed layout: the same tree and sphere order, the centres moved.
        const CompactTree& drawn = doc_.posed() ? doc_.posed()->model().tree() : *compact_;
        data_.spheres = render::sampling_spheres(drawn, doc_.tree(), color_by_, data_.origin, contact_counts());
    }
    ++data_.spheres_revision;
}

void Scene::rebuild_legend() {
    // Once a tree, motion or colouring, not every pose the timeline plays.
    data_.legend.clear();
    data_.heat = {};
    if (color_by_ != render::ColorBy::Contacts || !doc_.has_tree()) return;
    const std::vector<uint32_t>* counts = contact_counts();
    const std::vector<uint32_t> none = counts ? std::vector<uint32_t>{} : std::vector<uint32_t>(doc_.samples().size(), 0);
    data_.heat = render::heat_scale(counts ? *counts : none);
    data_.legend = render::heat_legend(data_.heat, counts ? *counts : none);
}

void Scene::rebuild_shown() {
    // Hidden nodes (a view state): what is left of the spheres, as ranges of the one uploaded set.
    data_.hiding = doc_.has_tree() && compact_ && !doc_.hidden().empty();
    data_.shown = data_.hiding ? render::shown_ranges(*compact_, doc_.tree(), doc_.hidden(), uint32_t(data_.spheres.size()))
                               : std::vector<render::SphereRange>{};
    ++data_.revision;
}

void Scene::rebuild_current() {
    data_.highlight = {};
    data_.wires.clear();
    if (doc_.has_tree() && compact_) {
        data_.highlight = render::sphere_range(*compact_, doc_.tree(), doc_.current());
        data_.wires = doc_.posed() ? render::bounding_sphere(doc_.posed()->model().tree(), doc_.tree(), doc_.current(),
                                                             render::highlight_color())
                                   : render::bounding_spheres(doc_.tree(), doc_.samples().origin, doc_.current(), 0,
                                                              render::highlight_color());
    }
    ++data_.revision;
}

void Scene::rebuild_selection() {
    // A selected sample's own sphere turns the selection colour: no second set of spheres to upload and draw.
    data_.selected.clear();
    data_.selected.reserve(doc_.selection().size());
    for (uint32_t i : doc_.selection())
        if (i < sphere_of_sample_.size() && sphere_of_sample_[i] != UINT32_MAX)
            data_.selected.push_back(sphere_of_sample_[i]);
    ++data_.selected_revision;
    ++data_.revision;
    emit changed();
}

render::Frame Scene::frame(render::MeshHandle mesh, render::SphereSetHandle spheres) const {
    render::Frame f;
    if (data_.mesh && mesh.id) {
        render::MeshItem item;
        item.mesh = mesh;
        item.pose = render::local_frame(data_.origin);
        // Sampling spheres lie inside the surface: they show through a see-through mesh.
        item.style.opacity = data_.spheres.empty() ? 1.0f : 0.3f;
        f.meshes.push_back(item);
    }
    if (!data_.spheres.empty() && spheres.id) {
        // The selection: its samples' own spheres marked in the selection colour. Set even when
        // nothing is selected, so that a selection change leaves the frame as it was and the
        // renderer recolours its cached frame instead of drawing it again.
        for (render::SphereItem item :
             render::highlighted_node(spheres, uint32_t(data_.spheres.size()), data_.highlight, true,
                                      color_by_ == render::ColorBy::Contacts ||
                                          (doc_.has_tree() && render::is_inner_node(doc_.tree(), doc_.current())))) {
            item.marked_color = selection_color();
            item.pose = render::local_frame(data_.origin);
            f.spheres.push_back(item);
        }
        if (data_.hiding) f.spheres = render::clip_to_ranges(f.spheres, data_.shown);
    }
    f.wire_spheres = data_.wires;
    return f;
}

} // namespace spt::editor
