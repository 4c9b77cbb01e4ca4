// EditorDocument: the open document, current tree and node, selection, pose shown; change signals.
#include "editor_document.hpp"
#include <algorithm>
#include <optional>

namespace spt::editor {

EditorDocument::EditorDocument(QObject* parent) : QObject(parent) {}

void EditorDocument::reset(SptDocument doc, std::optional<TriangleMesh> mesh, std::shared_ptr<const AnimatedMesh> animated) {
    doc_ = std::move(doc);
    mesh_ = std::move(mesh);
    tree_ = 0;
    current_ = root_id();
    selection_.clear();
    forget_strokes();
    hidden_.clear();
    adjacency_.reset();
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
    // A selection made in code has no strokes: strokes added to it (add, subtract, invert, grow,
    // shrink) would replay on nothing, so none is recorded until a stroke replaces the selection.
    strokes_unrecorded_ = !selection_.empty();
    emit selectionChanged();
}

SamplePoints EditorDocument::points() const {
    return posed() ? SamplePoints(posed()->sample_points(), doc_.samples.origin) : SamplePoints(doc_.samples);
}

size_t EditorDocument::select_rect(const ViewProjection& view, const PixelRect& rect, SelectionMode mode,
                                   bool visible_only) {
    return apply(RecipeStroke{view, rect, mode, visible_only});
}

size_t EditorDocument::apply(RecipeStroke stroke, QString* why) {
    if (why) why->clear();
    if (!has_tree()) return 0;
    // Where the views draw the samples: at the pose shown, with the mesh there hiding them.
    const TriangleMesh* depth_mesh = posed() ? pose_.mesh() : mesh();
    stroke.visible_only = stroke.visible_only && depth_mesh != nullptr;
    if (stroke.needs_adjacency()) {
        if (!mesh()) {
            if (why) *why = "the mesh is not known: linked, grow and shrink need its edges";
            return 0;
        }
        if (!adjacency_) adjacency_ = std::make_unique<SampleAdjacency>(*mesh(), doc_.samples);
    }
    const SamplePoints at = points();
    size_t hits = 0;
    if (stroke.is_operation()) {
        selection_ = apply_stroke(at, tree(), current_, selection_, stroke, depth_mesh, adjacency_.get());
        hits = selection_.size();
    } else {
        // The stroke's own hits, then combined: apply_stroke's result.
        const std::vector<uint32_t> h = stroke_hits(at, tree(), current_, stroke, depth_mesh, adjacency_.get());
        selection_ = combine_selection(selection_, h, stroke.mode);
        hits = h.size();
    }
    // A recipe step holds one pose: a stroke drawn at another pose than those before it leaves
    // the selection unrecorded until a stroke replaces it.
    const RecipePose here = pose_.recipe_pose();
    if (!stroke.is_operation() && stroke.mode == SelectionMode::Replace) forget_strokes();
    if (!strokes_.empty() && strokes_pose_ != here) {
        strokes_.clear();
        strokes_unrecorded_ = true;
    }
    if (!strokes_unrecorded_) {
        if (strokes_.empty()) strokes_pose_ = here;
        strokes_.push_back(std::move(stroke));
    }
    emit selectionChanged();
    return hits;
}

size_t EditorDocument::select_linked(const ViewProjection& view, const Eigen::Vector2f& window, SelectionMode mode,
                                     bool visible_only, QString* why) {
    if (why) why->clear();
    if (!has_tree()) return 0;
    if (!mesh()) {
        if (why) *why = "the mesh is not known: linked needs its edges";
        return 0;
    }
    const TriangleMesh* depth_mesh = posed() ? pose_.mesh() : mesh();
    const SamplePoints at = points();
    std::optional<DepthMap> depth;
    if (visible_only) {
        constexpr float kReach = 12; // physical pixels
        depth = render_depth(*depth_mesh, view, PixelRect{window.x() - kReach, window.y() - kReach, window.x() + kReach,
                                                          window.y() + kReach});
    }
    const int64_t picked = pick_sample(at, tree(), current_, view, window, 12, depth ? &*depth : nullptr,
                                       visible_tolerance(*depth_mesh));
    if (picked < 0) {
        if (why) *why = QString("no sample of node %1 under the cursor").arg(qulonglong(current_));
        return 0;
    }
    RecipeStroke stroke{view, {}, mode, false};
    stroke.kind = StrokeKind::Linked;
    // Recorded as the picked sample's point: replaying takes the sample nearest it.
    stroke.pick = at.origin + at.points[size_t(picked)].cast<double>();
    return apply(std::move(stroke), why);
}

void EditorDocument::hide(NodeId id) {
    if (!has_tree() || !tree().find(id)) return;
    if (std::find(hidden_.begin(), hidden_.end(), id) == hidden_.end()) hidden_.push_back(id);
    emit visibilityChanged();
}

void EditorDocument::isolate(NodeId id) {
    if (!has_tree() || !tree().find(id)) return;
    hidden_.clear();
    for (NodeId a = id; a > root_id(); a = parent_of(a)) hidden_.push_back(a ^ 1); // the sibling
    emit visibilityChanged();
}

void EditorDocument::show_all() {
    hidden_.clear();
    emit visibilityChanged();
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
