#pragma once
// The open document of the editor: the .spt document, its mesh (if found), the current
// tree and node, the selection, and the pose the views show it at (a clip of an animated mesh
// at a time: a view state, not an edit). Every change goes through here and is announced.
#include "document_pose.hpp"
#include "spt/selection.hpp"
#include "spt/spt_file.hpp"
#include <QObject>
#include <QString>
#include <memory>
#include <optional>
#include <vector>

namespace spt::editor {

/// State of the edited document; geometry in the samples' object frame, model units.
class EditorDocument : public QObject {
    Q_OBJECT
public:
    /// An empty document (no samples, no trees).
    explicit EditorDocument(QObject* parent = nullptr);

    /// Replaces everything (a file was opened or recovered); the first tree's root becomes current
    /// and the views show the bind pose. `animated`: the mesh with its clips, if it has some.
    void reset(SptDocument doc, std::optional<TriangleMesh> mesh,
               std::shared_ptr<const AnimatedMesh> animated = nullptr);
    /// True once a document with at least one tree is open.
    bool has_tree() const { return !doc_.trees.empty(); }

    /// The whole .spt document.
    const SptDocument& document() const { return doc_; }
    /// The mesh the samples were taken from, or nullptr if it was not found.
    const TriangleMesh* mesh() const { return mesh_ ? &*mesh_ : nullptr; }
    /// The samples, object frame = origin + local points.
    const SampleSet& samples() const { return doc_.samples; }
    /// Index of the tree being edited.
    int tree_index() const { return tree_; }
    /// The tree being edited (has_tree() must hold).
    const SamplingTree& tree() const { return doc_.trees[size_t(tree_)]; }
    /// Paper id of the current node.
    NodeId current() const { return current_; }
    /// Selected samples (sorted), all below the current node.
    const std::vector<uint32_t>& selection() const { return selection_; }

    /// Makes tree `index` the edited one; its root becomes current and the selection is cleared.
    void set_tree_index(int index);
    /// Makes node `id` current (ignored if the tree has no such node); clears the selection.
    void set_current(NodeId id);
    /// Replaces the selection (sorted sample indices); how it was made is not known, so a
    /// split by it records no recipe step.
    void set_selection(std::vector<uint32_t> selection);
    /// The rectangles that made the selection, in order (the next split's recipe step); empty
    /// when it cannot be recorded (made in code, or drawn at two poses: a step holds one).
    const std::vector<RecipeStroke>& strokes() const { return strokes_; }
    /// The pose the strokes were drawn at.
    const RecipePose& strokes_pose() const { return strokes_pose_; }
    /// Applies a rectangle drawn in a view to the samples where the pose shown puts them: through,
    /// or visible only when the mesh is known. Returns the number of samples the rectangle hit.
    size_t select_rect(const ViewProjection& view, const PixelRect& rect, SelectionMode mode, bool visible_only);
    /// Applies a stroke of any kind (core's apply_stroke) to the selection and records it for the
    /// next split: a rectangle, lasso or brush drawn in a view, a linked pick, invert, grow or
    /// shrink. Visible only is dropped without a mesh; linked, grow and shrink are refused without
    /// one (empty `why`: done). Returns the stroke's own hits (for an operation, the selection's size).
    size_t apply(RecipeStroke stroke, QString* why = nullptr);
    /// Select linked: the mesh part of the sample of the current node nearest window point
    /// `window` (GL window pixels of `view`, at most 12 physical pixels away; visible only when
    /// asked and the mesh is known), combined in `mode`. Returns the hits; `why` says why nothing was picked.
    size_t select_linked(const ViewProjection& view, const Eigen::Vector2f& window, SelectionMode mode,
                         bool visible_only, QString* why = nullptr);

    /// Nodes hidden in the views (a view state, not an edit: each hides its subtree).
    const std::vector<NodeId>& hidden() const { return hidden_; }
    /// Hides node `id`'s subtree (H).
    void hide(NodeId id);
    /// Hides everything but node `id`'s subtree (Shift+H): the sibling of `id` and of each of its ancestors.
    void isolate(NodeId id);
    /// Shows every node again (Alt+H).
    void show_all();

    /// The mesh with its clips, or null when it has none (no timeline).
    const AnimatedMesh* animation() const { return pose_.animation(); }
    /// The same, shared (what a scene run with the document's tree animates it by).
    std::shared_ptr<const AnimatedMesh> shared_animation() const { return pose_.shared_animation(); }
    /// The pose the views show: clip index (-1 for the bind pose) and seconds into it.
    const DocumentPose& pose() const { return pose_; }
    /// Shows clip `clip` (-1: the bind pose) at `time` seconds, held within the clip. A view
    /// state, not an edit: the tree and the selection stay, and nothing goes on the undo stack.
    void set_pose(int clip, double time);
    /// The edited tree at the pose shown (its posed spheres and sample points), or null at the bind pose.
    const DeformingModel* posed() const { return pose_.model(); }

    /// Replaces tree `index` (an undo command's redo or undo) and sets the current node.
    void set_tree(int index, const SamplingTree& tree, NodeId current);
    /// Inserts a tree at `index` and makes it the edited one.
    void insert_tree(int index, const SamplingTree& tree);
    /// Removes tree `index`; the edited tree becomes the one before it (or the first).
    void remove_tree(int index);

    /// Bytes of the document as save_spt writes them.
    std::vector<uint8_t> encode() const { return encode_spt(doc_); }

signals:
    /// A new document replaced the old one.
    void documentReset();
    /// The edited tree, the set of trees or a tree's nodes changed.
    void treeChanged();
    /// The current node changed (the tree did not).
    void currentChanged();
    /// The selection changed.
    void selectionChanged();
    /// The pose shown changed (clip or time), or the tree was bound to it again after a change.
    void poseChanged();
    /// Core could not pose the mesh (why); the views show the bind pose instead.
    void poseRefused(const QString& why);
    /// Nodes were hidden or shown.
    void visibilityChanged();

private:
    SptDocument doc_;
    std::optional<TriangleMesh> mesh_;
    int tree_ = 0;
    NodeId current_ = root_id();
    std::vector<uint32_t> selection_;
    std::vector<RecipeStroke> strokes_;
    RecipePose strokes_pose_;
    bool strokes_unrecorded_ = false; // strokes at two poses: none recorded until one replaces
    DocumentPose pose_;
    std::vector<NodeId> hidden_;
    std::unique_ptr<SampleAdjacency> adjacency_; // made at the first linked, grow or shrink
    SamplePoints points() const;                 // the samples where the pose shown puts them
    void forget_strokes();
    void tree_edited(); // the edited tree changed: its pose is bound again, then announced
    void update_pose(bool tree_changed);
};

} // namespace spt::editor
