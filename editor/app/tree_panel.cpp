// TreePanel: trees, nodes and properties; clicking a node makes it current.
#include "tree_panel.hpp"
#include "radius_box.hpp"
#include <QComboBox>
#include <QSignalBlocker>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTreeWidget>
#include <QThread>
#include <QTreeWidgetItemIterator>
#include <QVBoxLayout>
#include <filesystem>
#include <map>

namespace spt::editor {
namespace {

constexpr int kIdRole = Qt::UserRole + 1;

QString number(double v) { return QString::number(v, 'g', 5); }

} // namespace

TreePanel::TreePanel(EditorDocument& doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    trees_ = new QComboBox;
    trees_->setObjectName("tree_list");
    top->addWidget(new QLabel("Tree"));
    top->addWidget(trees_, 1);
    auto* color = color_ = new QComboBox;
    color->setObjectName("color_by");
    color->addItems({"Colour by level", "Colour by node", "Colour by contacts"});
    color->setItemData(2, "Each sample by how many steps of the loaded motion its sphere was in contact (File > Load motion)",
                       Qt::ToolTipRole);
    top->addWidget(color);
    layout->addLayout(top);

    nodes_ = new QTreeWidget;
    nodes_->setObjectName("node_tree");
    nodes_->setHeaderLabels({"Node", "Samples", "Bounding r", "Sampling r", "Active"});
    nodes_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    nodes_->setIndentation(nodes_->fontMetrics().height() * 3 / 4); // trees 15-20 deep stay readable
    layout->addWidget(nodes_, 1);

    properties_ = new QLabel;
    properties_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(properties_);
    auto* form = new QFormLayout;
    radius_ = new RadiusBox;
    radius_->setObjectName("sampling_radius");
    auto* set_radius = set_radius_ = new QPushButton("Set");
    auto* radius_row = new QHBoxLayout;
    radius_row->addWidget(radius_, 1);
    radius_row->addWidget(set_radius);
    form->addRow("Sampling r", radius_row);
    leaf_size_ = new QSpinBox;
    leaf_size_->setRange(1, 1 << 20);
    leaf_size_->setValue(int(BuildOptions{}.leaf_size));
    strategy_ = new QComboBox;
    strategy_->addItems({"volume", "median"});
    auto* build = build_ = new QPushButton("Build subtree");
    build->setObjectName("build_subtree");
    auto* build_row = new QHBoxLayout;
    build_row->addWidget(leaf_size_);
    build_row->addWidget(strategy_);
    build_row->addWidget(build);
    form->addRow("Leaf size", build_row);
    layout->addLayout(form);

    connect(trees_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int i) {
        if (!updating_ && i >= 0) doc_.set_tree_index(i);
    });
    connect(color, qOverload<int>(&QComboBox::currentIndexChanged), this,
            [this](int i) {
                emit colorByChosen(i == 2 ? render::ColorBy::Contacts : i == 1 ? render::ColorBy::Node : render::ColorBy::Level);
            });
    connect(nodes_, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (!updating_ && item) doc_.set_current(item->data(0, kIdRole).toULongLong());
    });
    connect(set_radius, &QPushButton::clicked, this, [this] { emit setRadiusRequested(float(radius_->value())); });
    connect(build, &QPushButton::clicked, this, [this] { emit buildSubtreeRequested(); });
    connect(&doc_, &EditorDocument::documentReset, this, &TreePanel::rebuild);
    connect(&doc_, &EditorDocument::treeChanged, this, &TreePanel::rebuild);
    connect(&doc_, &EditorDocument::currentChanged, this, &TreePanel::show_current);
    connect(&doc_, &EditorDocument::selectionChanged, this, &TreePanel::show_current);
    rebuild();
}

void TreePanel::show_color_by_node(bool by_node) { show_color_by(by_node ? render::ColorBy::Node : render::ColorBy::Level); }

void TreePanel::show_color_by(render::ColorBy by) {
    const QSignalBlocker block(color_);
    color_->setCurrentIndex(by == render::ColorBy::Contacts ? 2 : by == render::ColorBy::Node ? 1 : 0);
}

void TreePanel::set_measured(const QMap<QString, QString>& measured) {
    measured_ = measured;
    rebuild();
}

QString TreePanel::tree_label(const SamplingTree& tree) const {
    const QString name = QString::fromStdString(tree.name());
    QStringList motions;
    for (const MotionBuildStep& b : tree.motion_builds()) {
        const QString m = QString::fromStdString(std::filesystem::path(b.scene).filename().string()) + " / " +
                          QString::fromStdString(b.object);
        if (!motions.contains(m)) motions.push_back(m);
    }
    QStringList parts;
    if (!motions.isEmpty()) parts.push_back("motion: " + motions.join(", "));
    if (measured_.contains(name)) parts.push_back("measured: " + measured_.value(name));
    return parts.isEmpty() ? name : QString("%1 (%2)").arg(name, parts.join("; "));
}

QSize TreePanel::sizeHint() const {
    QSize hint = QWidget::sizeHint();
    const int rows = 24;
    hint.setHeight(hint.height() - nodes_->sizeHint().height() + rows * nodes_->fontMetrics().height());
    return hint;
}

BuildOptions TreePanel::build_options() const {
    BuildOptions o;
    o.leaf_size = uint32_t(leaf_size_->value());
    o.strategy = strategy_->currentIndex() == 1 ? SplitStrategy::Median : SplitStrategy::Volume;
    o.threads = QThread::idealThreadCount(); // the same subtree on any count; sooner on more
    return o;
}

void TreePanel::rebuild() {
    updating_ = true;
    trees_->clear();
    for (const SamplingTree& t : doc_.document().trees) trees_->addItem(tree_label(t));
    trees_->setCurrentIndex(doc_.tree_index());
    nodes_->clear();
    if (doc_.has_tree()) {
        // Parents come before children in id order, so each item's parent exists when it is made.
        std::map<NodeId, QTreeWidgetItem*> items;
        std::map<NodeId, size_t> counts;
        for (const TreeNode* n : doc_.tree().active_nodes())
            for (NodeId a = n->id; a != 0; a = parent_of(a)) counts[a] += n->samples.size();
        for (const TreeNode* n : doc_.tree().nodes()) {
            auto it = items.find(parent_of(n->id));
            auto* item = it == items.end() ? new QTreeWidgetItem(nodes_) : new QTreeWidgetItem(it->second);
            item->setText(0, QString::number(qulonglong(n->id)));
            item->setData(0, kIdRole, QVariant::fromValue(qulonglong(n->id)));
            item->setText(1, QString::number(qulonglong(counts[n->id])));
            item->setText(2, number(n->bv_radius));
            item->setText(3, number(n->ss_radius));
            item->setText(4, n->active ? "yes" : "no");
            items[n->id] = item;
        }
        nodes_->expandToDepth(3);
    }
    updating_ = false;
    show_current();
}

void TreePanel::show_current() {
    // Without a document there is no node to edit: the controls say so instead of showing a
    // radius no node has.
    const bool open = doc_.has_tree();
    for (QWidget* w : std::initializer_list<QWidget*>{radius_, set_radius_, leaf_size_, strategy_, build_, trees_, color_})
        w->setEnabled(open);
    radius_->setSpecialValueText(open ? QString() : QString("-"));
    if (!open) {
        radius_->setValue(radius_->minimum());
        properties_->setText("No document");
        return;
    }
    const TreeNode* n = doc_.tree().find(doc_.current());
    if (!n) return;
    updating_ = true;
    for (QTreeWidgetItemIterator it(nodes_); *it; ++it)
        if ((*it)->data(0, kIdRole).toULongLong() == n->id) nodes_->setCurrentItem(*it);
    updating_ = false;
    radius_->setValue(double(n->ss_radius));
    properties_->setText(QString("Node %1 (depth %2, %3)\nBounding sphere r %4 at (%5, %6, %7)\n%8 selected")
                             .arg(qulonglong(n->id))
                             .arg(node_depth(n->id))
                             .arg(n->active ? "active" : "inner")
                             .arg(number(n->bv_radius))
                             .arg(number(n->center.x() + doc_.samples().origin.x()))
                             .arg(number(n->center.y() + doc_.samples().origin.y()))
                             .arg(number(n->center.z() + doc_.samples().origin.z()))
                             .arg(doc_.selection().size()));
}

} // namespace spt::editor
