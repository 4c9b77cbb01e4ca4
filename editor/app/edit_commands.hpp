#pragma once
// The editor's edits as undo commands (paper §3-3): split, merge, sampling-sphere radius,
// automatic subtree, and named trees. Each command keeps the tree before and after, so
// undo and redo restore a document byte for byte. The tree arithmetic is core's.
#include "editor_document.hpp"
#include "spt/recipe.hpp"
#include "spt/tree_builder.hpp"
#include <QString>
#include <QUndoCommand>
#include <memory>

namespace spt::editor {

/// An edit ready to push, or why it was refused.
struct EditOutcome {
    std::unique_ptr<QUndoCommand> command; ///< null when refused
    QString reason;                        ///< why it was refused, for the status bar
};

/// Split of the current node by the selection: left = node ∩ selection, right = the rest;
/// afterwards the right child (what is left to author) is current.
EditOutcome make_split(EditorDocument& doc);
/// Merges node `id`'s children back into it.
EditOutcome make_merge(EditorDocument& doc, NodeId id);
/// Sets active node `id`'s sampling-sphere radius (model units).
EditOutcome make_set_radius(EditorDocument& doc, NodeId id, float radius);
/// Builds a subtree automatically under active node `id`.
EditOutcome make_build_subtree(EditorDocument& doc, NodeId id, const BuildOptions& options);
/// The same edit from a tree built elsewhere (in the background) from the edited tree:
/// `built` is the edited tree with the subtree under `id` built with `options`.
EditOutcome make_built_subtree(EditorDocument& doc, NodeId id, SamplingTree built, const BuildOptions& options);
/// A build from motion under active node `id` made elsewhere (in the background, core's
/// build_motion_subtree): `built` is the edited tree with it made; `step` (its scene, object,
/// steps and leaf size) is recorded in the tree (SamplingTree::add_motion_build) for replays.
EditOutcome make_built_motion_subtree(EditorDocument& doc, NodeId id, SamplingTree built, MotionBuildStep step,
                                      const QString& motion);
/// Adds a tree whose root holds every sample, named `name` (unique, non-empty).
EditOutcome make_add_tree(EditorDocument& doc, const QString& name);
/// Renames tree `index`.
EditOutcome make_rename_tree(EditorDocument& doc, int index, const QString& name);
/// Copies tree `index` under a new name.
EditOutcome make_duplicate_tree(EditorDocument& doc, int index, const QString& name);
/// Deletes tree `index` (never the last one).
EditOutcome make_delete_tree(EditorDocument& doc, int index);

/// A name not used by any tree of the document: `base`, else `base 2`, `base 3`, ...
QString unused_tree_name(const EditorDocument& doc, const QString& base);

} // namespace spt::editor
