// EditorDocument: the open document, current tree and node, selection; change signals.
#include "editor_document.hpp"
#include <algorithm>

namespace spt::editor {

EditorDocument::EditorDocument(QObject* parent) : QObject(parent) {}

void EditorDocument::reset(SptDocument doc, std::optional<TriangleMesh> mesh) {
    doc_ = std::move(doc);
    mesh_ = std::move(mesh);
    tree_ = 0;
    current_ = root_id();
    selection_.clear();
    strokes_.clear();
    emit documentReset();
}

void EditorDocument::set_tree_index(int index) {
    if (index < 0 || size_t(index) >= doc_.trees.size()) return;
    tree_ = index;
    current_ = root_id();
    selection_.clear();
    strokes_.clear();
    emit treeChanged();
}

void EditorDocument::set_current(NodeId id) {
    if (!has_tree() || !tree().find(id) || id == current_) return;
    current_ = id;
    selection_.clear();
    strokes_.clear();
    emit currentChanged();
}

void EditorDocument::set_selection(std::vector<uint32_t> selection) {
    selection_ = std::move(selection);
    strokes_.clear();
    emit selectionChanged();
}

size_t EditorDocument::select_rect(const ViewProjection& view, const PixelRect& rect, SelectionMode mode,
                                   bool visible_only) {
    if (!has_tree()) return 0;
    const RecipeStroke stroke{view, rect, mode, visible_only && mesh_};
    // The rectangle's own hits (the stroke in replace mode), then combined: apply_stroke's result.
    RecipeStroke alone = stroke;
    alone.mode = SelectionMode::Replace;
    const std::vector<uint32_t> hits = apply_stroke(doc_.samples, tree(), current_, {}, alone, mesh());
    selection_ = combine_selection(selection_, hits, mode);
    if (mode == SelectionMode::Replace) strokes_.clear();
    strokes_.push_back(stroke);
    emit selectionChanged();
    return hits.size();
}

void EditorDocument::set_tree(int index, const SamplingTree& tree, NodeId current) {
    doc_.trees[size_t(index)] = tree;
    tree_ = index;
    current_ = tree.find(current) ? current : root_id();
    selection_.clear();
    strokes_.clear();
    emit treeChanged();
}

void EditorDocument::insert_tree(int index, const SamplingTree& tree) {
    doc_.trees.insert(doc_.trees.begin() + index, tree);
    tree_ = index;
    current_ = root_id();
    selection_.clear();
    strokes_.clear();
    emit treeChanged();
}

void EditorDocument::remove_tree(int index) {
    doc_.trees.erase(doc_.trees.begin() + index);
    tree_ = std::max(0, index - 1);
    current_ = root_id();
    selection_.clear();
    strokes_.clear();
    emit treeChanged();
}

} // namespace spt::editor
