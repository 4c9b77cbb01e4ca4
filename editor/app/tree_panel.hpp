#pragma once
// The dock's tree panel: the named trees, the edited tree's nodes (paper id, samples,
// bounding-sphere radius, sampling-sphere radius, active), and the current node's
// properties with the edits that take parameters (radius, automatic subtree).
#include "editor_document.hpp"
#include "spt/render/tree_overlay.hpp"
#include "spt/tree_builder.hpp"
#include <QMap>
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTreeWidget;
class QTreeWidgetItem;

namespace spt::editor {

/// Tree list, node tree and properties of an EditorDocument.
class TreePanel : public QWidget {
    Q_OBJECT
public:
    /// A panel showing `doc`, which must outlive it.
    explicit TreePanel(EditorDocument& doc, QWidget* parent = nullptr);
    /// The node tree widget (tests click in it).
    QTreeWidget* nodes() const { return nodes_; }
    /// Build options chosen in the panel.
    BuildOptions build_options() const;
    /// Shows colouring by node (true) or by level without asking for it again.
    void show_color_by_node(bool by_node);
    /// Shows colouring `by` without asking for it again.
    void show_color_by(render::ColorBy by);
    /// The motion each tree was last measured on in this session (tree name to "scene / object"),
    /// shown in the tree box beside the motions it was built for.
    void set_measured(const QMap<QString, QString>& measured);
    /// What the tree box says of tree `tree`: its name, the motions it was built for
    /// (tree.motion_builds()) and the one it was last measured on.
    QString tree_label(const SamplingTree& tree) const;
    /// Room for about 24 rows of the node table (pixels), so that the dock column gives the
    /// tree most of its height and the history below it the rest.
    QSize sizeHint() const override;

signals:
    /// The user asked to set the current node's sampling-sphere radius (model units).
    void setRadiusRequested(float radius);
    /// The user asked for an automatic subtree under the current node.
    void buildSubtreeRequested();
    /// The user chose how spheres are coloured: by level, node or contacts (the loaded motion's heat map).
    void colorByChosen(render::ColorBy by);

private:
    void rebuild();
    void show_current();
    EditorDocument& doc_;
    QComboBox* trees_ = nullptr;
    QTreeWidget* nodes_ = nullptr;
    QLabel* properties_ = nullptr;
    QDoubleSpinBox* radius_ = nullptr;
    QPushButton *set_radius_ = nullptr, *build_ = nullptr;
    QSpinBox* leaf_size_ = nullptr;
    QComboBox* strategy_ = nullptr;
    QComboBox* color_ = nullptr;
    bool updating_ = false;
    QMap<QString, QString> measured_;
};

} // namespace spt::editor
