// EditorDocument: the open document, current tree and node, selection, pose shown; change signals.
#include "editor_document.hpp"
#include <algorithm>

namespace spt::editor {

EditorDocument::EditorDocument(QObject* parent) : QObject(parent) {}

void EditorDocument::reset(SptDocument doc, std::optional<TriangleMesh> mesh, std::shared_ptr<const AnimatedMesh> animated) {
    doc_ = std::move(doc);
    mesh_ = std::move(mesh);
    tree_ = 0;
    current_ = root_id();
    selection_.clear();
    forget_strokes();
    pose_.reset(std::move(animated));
    emit documentReset();
}

void EditorDocument::forget_strokes() {
    strokes_.clear();
    strokes_pose_ = {};
    strokes_unrecorded_ = false;
}

void EditorDocument::tree_edited() {
    current_ = has_tree() && tree().find(current_) ? current_ : root_id();
    selection_.clear();
    forget_strokes();
    update_pose(true);
    emit treeChanged();
}

void EditorDocument::set_tree_index(int index) {
    if (index < 0 || size_t(index) >= doc_.trees.size()) return;
    tree_ = index;
    current_ = root_id();
    tree_edited();
}

void EditorDocument::set_current(NodeId id) {
    if (!has_tree() || !tree().find(id) || id == current_) return;
    current_ = id;
    selection_.clear();
    forget_strokes();
    emit currentChanged();
}

void EditorDocument::set_selection(std::vector<uint32_t> selection) {
    selection_ = std::move(selection);
    forget_strokes();
    emit selectionChanged();
}

size_t EditorDocument::select_rect(const ViewProjection& view, const PixelRect& rect, SelectionMode mode,
                                   bool visible_only) {
    if (!has_tree()) return 0;
    // Where the views draw the samples: at the pose shown, with the mesh there hiding them.
    const TriangleMesh* depth_mesh = posed() ? pose_.mesh() : mesh();
    const SamplePoints points =
        posed() ? SamplePoints(posed()->sample_points(), doc_.samples.origin) : SamplePoints(doc_.samples);
    const RecipeStroke stroke{view, rect, mode, visible_only && depth_mesh != nullptr};
    // The rectangle's own hits (the stroke in replace mode), then combined: apply_stroke's result.
    RecipeStroke alone = stroke;
    alone.mode = SelectionMode::Replace;
    const std::vector<uint32_t> hits = apply_stroke(points, tree(), current_, {}, alone, depth_mesh);
    selection_ = combine_selection(selection_, hits, mode);
    // A recipe step holds one pose: a rectangle drawn at another pose than those before it
    // leaves the selection unrecorded until a rectangle replaces it.
    const RecipePose here = pose_.recipe_pose();
    if (mode == SelectionMode::Replace) forget_strokes();
    if (!strokes_.empty() && strokes_pose_ != here) {
        strokes_.clear();
        strokes_unrecorded_ = true;
    }
    if (!strokes_unrecorded_) {
        if (strokes_.empty()) strokes_pose_ = here;
        strokes_.push_back(stroke);
    }
    emit selectionChanged();
    return hits.size();
}

void EditorDocument::set_pose(int clip, double time) {
    if (!pose_.set(clip, time)) return;
    update_pose(false);
    emit poseChanged();
}

void EditorDocument::update_pose(bool tree_changed) {
    if (!has_tree()) return;
    const std::string why = pose_.update(doc_, tree().name(), tree_changed);
    if (!why.empty()) emit poseRefused(QString::fromStdString(why));
}

void EditorDocument::set_tree(int index, const SamplingTree& tree, NodeId current) {
    doc_.trees[size_t(index)] = tree;
    tree_ = index;
    current_ = current;
    tree_edited();
}

void EditorDocument::insert_tree(int index, const SamplingTree& tree) {
    doc_.trees.insert(doc_.trees.begin() + index, tree);
    tree_ = index;
    current_ = root_id();
    tree_edited();
}

void EditorDocument::remove_tree(int index) {
    doc_.trees.erase(doc_.trees.begin() + index);
    tree_ = std::max(0, index - 1);
    current_ = root_id();
    tree_edited();
}

} // namespace spt::editor
