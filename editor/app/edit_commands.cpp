// Undo commands over whole trees: the document after undo is the document before, exactly.
#include "edit_commands.hpp"

namespace spt::editor {
namespace {

// One tree replaced by another (split, merge, radius, subtree, rename).
class TreeStateCommand : public QUndoCommand {
public:
    TreeStateCommand(EditorDocument& doc, SamplingTree after, NodeId after_current, const QString& text)
        : doc_(doc), index_(doc.tree_index()), before_(doc.tree()), after_(std::move(after)),
          before_current_(doc.current()), after_current_(after_current) {
        setText(text);
    }
    void redo() override { doc_.set_tree(index_, after_, after_current_); }
    void undo() override { doc_.set_tree(index_, before_, before_current_); }

private:
    EditorDocument& doc_;
    int index_;
    SamplingTree before_, after_;
    NodeId before_current_, after_current_;
};

// A tree added at the end (add, duplicate).
class InsertTreeCommand : public QUndoCommand {
public:
    InsertTreeCommand(EditorDocument& doc, SamplingTree tree, const QString& text)
        : doc_(doc), index_(int(doc.document().trees.size())), previous_(doc.tree_index()), tree_(std::move(tree)) {
        setText(text);
    }
    void redo() override { doc_.insert_tree(index_, tree_); }
    void undo() override {
        doc_.remove_tree(index_);
        doc_.set_tree_index(previous_);
    }

private:
    EditorDocument& doc_;
    int index_, previous_;
    SamplingTree tree_;
};

class RemoveTreeCommand : public QUndoCommand {
public:
    RemoveTreeCommand(EditorDocument& doc, int index)
        : doc_(doc), index_(index), previous_(doc.tree_index()), tree_(doc.document().trees[size_t(index)]) {
        setText(QString("Delete tree '%1'").arg(QString::fromStdString(tree_.name())));
    }
    void redo() override { doc_.remove_tree(index_); }
    void undo() override {
        doc_.insert_tree(index_, tree_);
        doc_.set_tree_index(previous_);
    }

private:
    EditorDocument& doc_;
    int index_, previous_;
    SamplingTree tree_;
};

EditOutcome refused(const QString& reason) { return {nullptr, reason}; }
EditOutcome refused(const std::string& reason) { return {nullptr, QString::fromStdString(reason)}; }

QString node_text(NodeId id) { return QString::number(qulonglong(id)); }

QString check_name(const EditorDocument& doc, const QString& name) {
    if (name.trimmed().isEmpty()) return "a tree needs a name";
    if (name.toUtf8().size() > 4096) return "a tree name is at most 4096 bytes";
    if (doc.document().tree(name.toStdString())) return QString("a tree named '%1' exists already").arg(name);
    return {};
}

} // namespace

EditOutcome make_split(EditorDocument& doc) {
    if (!doc.has_tree()) return refused(QString("no document is open"));
    SamplingTree after = doc.tree();
    const NodeId id = doc.current();
    if (doc.selection().empty()) return refused(QString("nothing is selected: drag a rectangle over node %1's samples").arg(node_text(id)));
    const EditResult r = after.split(id, doc.selection(), doc.samples());
    if (!r) return refused(r.reason);
    // How the selection was drawn, and at which pose, goes with the split, so `spt convert
    // --recipe` can redo it. The split itself is of the document's (bind-pose) samples.
    if (!doc.strokes().empty()) after.add_recipe_step({id, doc.strokes(), doc.strokes_pose()});
    QString text = QString("Split node %1 (%2 selected").arg(node_text(id)).arg(doc.selection().size());
    if (!doc.strokes().empty() && !doc.strokes_pose().bind())
        text += QString(" at %1 %2 s").arg(QString::fromStdString(doc.strokes_pose().clip)).arg(doc.strokes_pose().time, 0, 'f', 3);
    return {std::make_unique<TreeStateCommand>(doc, std::move(after), right_child(id), text + ")"), {}};
}

EditOutcome make_merge(EditorDocument& doc, NodeId id) {
    if (!doc.has_tree()) return refused(QString("no document is open"));
    SamplingTree after = doc.tree();
    const EditResult r = after.merge(id, doc.samples());
    if (!r) return refused(r.reason);
    return {std::make_unique<TreeStateCommand>(doc, std::move(after), id, QString("Merge node %1").arg(node_text(id))), {}};
}

EditOutcome make_set_radius(EditorDocument& doc, NodeId id, float radius) {
    if (!doc.has_tree()) return refused(QString("no document is open"));
    SamplingTree after = doc.tree();
    const EditResult r = after.set_radius(id, radius, doc.samples());
    if (!r) return refused(r.reason);
    return {std::make_unique<TreeStateCommand>(doc, std::move(after), doc.current(),
                                               QString("Radius of node %1 = %2").arg(node_text(id)).arg(double(radius))),
            {}};
}

EditOutcome make_build_subtree(EditorDocument& doc, NodeId id, const BuildOptions& options) {
    if (!doc.has_tree()) return refused(QString("no document is open"));
    SamplingTree after = doc.tree();
    const EditResult r = after.build_subtree(id, doc.samples(), options);
    if (!r) return refused(r.reason);
    return make_built_subtree(doc, id, std::move(after), options);
}

EditOutcome make_built_subtree(EditorDocument& doc, NodeId id, SamplingTree built, const BuildOptions& options) {
    if (!doc.has_tree()) return refused(QString("no document is open"));
    return {std::make_unique<TreeStateCommand>(doc, std::move(built), id,
                                               QString("Build subtree under node %1 (leaf size %2)")
                                                   .arg(node_text(id)).arg(options.leaf_size)),
            {}};
}

EditOutcome make_built_motion_subtree(EditorDocument& doc, NodeId id, SamplingTree built, MotionBuildStep step,
                                      const QString& motion) {
    if (!doc.has_tree()) return refused(QString("no document is open"));
    const uint32_t leaf_size = step.leaf_size;
    step.node = id;
    built.add_motion_build(std::move(step));
    return {std::make_unique<TreeStateCommand>(doc, std::move(built), id,
                                               QString("Build from motion under node %1 (%2, leaf size %3)")
                                                   .arg(node_text(id), motion)
                                                   .arg(leaf_size)),
            {}};
}

EditOutcome make_add_tree(EditorDocument& doc, const QString& name) {
    if (const QString bad = check_name(doc, name); !bad.isEmpty()) return refused(bad);
    return {std::make_unique<InsertTreeCommand>(doc, unsplit_tree(name.toStdString(), doc.samples()),
                                                QString("Add tree '%1'").arg(name)),
            {}};
}

EditOutcome make_rename_tree(EditorDocument& doc, int index, const QString& name) {
    if (index < 0 || size_t(index) >= doc.document().trees.size()) return refused(QString("no such tree"));
    if (const QString bad = check_name(doc, name); !bad.isEmpty()) return refused(bad);
    doc.set_tree_index(index);
    SamplingTree after = doc.tree();
    const QString old = QString::fromStdString(after.name());
    after.set_name(name.toStdString());
    return {std::make_unique<TreeStateCommand>(doc, std::move(after), doc.current(),
                                               QString("Rename tree '%1' to '%2'").arg(old, name)),
            {}};
}

EditOutcome make_duplicate_tree(EditorDocument& doc, int index, const QString& name) {
    if (index < 0 || size_t(index) >= doc.document().trees.size()) return refused(QString("no such tree"));
    if (const QString bad = check_name(doc, name); !bad.isEmpty()) return refused(bad);
    SamplingTree copy = doc.document().trees[size_t(index)];
    const QString old = QString::fromStdString(copy.name());
    copy.set_name(name.toStdString());
    return {std::make_unique<InsertTreeCommand>(doc, std::move(copy), QString("Duplicate tree '%1' as '%2'").arg(old, name)),
            {}};
}

EditOutcome make_delete_tree(EditorDocument& doc, int index) {
    if (index < 0 || size_t(index) >= doc.document().trees.size()) return refused(QString("no such tree"));
    if (doc.document().trees.size() == 1) return refused(QString("a document keeps at least one tree"));
    return {std::make_unique<RemoveTreeCommand>(doc, index), {}};
}

QString unused_tree_name(const EditorDocument& doc, const QString& base) {
    if (!doc.document().tree(base.toStdString())) return base;
    for (int k = 2;; ++k) {
        const QString name = QString("%1 %2").arg(base).arg(k);
        if (!doc.document().tree(name.toStdString())) return name;
    }
}

} // namespace spt::editor
