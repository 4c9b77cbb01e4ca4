// ViewGrid: a vertical splitter of two horizontal ones, kept in step, and maximise/restore.
#include "view_grid.hpp"
#include <QLabel>
#include <QSplitter>
#include <QVBoxLayout>
#include <algorithm>

namespace spt::editor {

ViewGrid::ViewGrid(EditorDocument& doc, Scene& scene, const ViewOptions& options, QWidget* parent)
    : QWidget(parent) {
    rows_ = new QSplitter(Qt::Vertical, this);
    rows_->setChildrenCollapsible(false);
    const render::View kinds[4] = {render::View::Top, render::View::Front, render::View::Side, render::View::Camera};
    for (int r = 0; r < 2; ++r) {
        columns_[size_t(r)] = new QSplitter(Qt::Horizontal, rows_);
        columns_[size_t(r)]->setChildrenCollapsible(false);
        for (int c = 0; c < 2; ++c) {
            auto* v = new ViewWidget(kinds[2 * r + c], doc, scene, options, columns_[size_t(r)]);
            views_[size_t(2 * r + c)] = v;
            columns_[size_t(r)]->addWidget(v);
        }
    }
    // Moving one column divider moves the other, so the grid stays a grid.
    for (int r = 0; r < 2; ++r) {
        QSplitter* self = columns_[size_t(r)];
        QSplitter* other = columns_[size_t(1 - r)];
        connect(self, &QSplitter::splitterMoved, other, [self, other] { other->setSizes(self->sizes()); });
    }
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(rows_);
    // A first start shows empty views: say what to do, until a document is in.
    hint_ = new QLabel("No document.\nOpen a mesh or a .spt file: File > Open (Ctrl+O),\nor drop it on the window.", this);
    hint_->setObjectName("empty_hint");
    hint_->setAlignment(Qt::AlignCenter);
    hint_->setAttribute(Qt::WA_TransparentForMouseEvents);
    hint_->setStyleSheet("QLabel { color: #303030; background: rgba(255, 255, 255, 200); padding: 10px 16px; }");
    hint_->setVisible(!doc.has_tree());
    connect(&doc, &EditorDocument::documentReset, this, [this, &doc] { hint_->setVisible(!doc.has_tree()); });
    place_hint();
}

void ViewGrid::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    place_hint();
}

void ViewGrid::place_hint() {
    hint_->adjustSize();
    // Across the middle of the top row: the grid's very centre would cover the camera view's name.
    hint_->move((width() - hint_->width()) / 2, std::max(0, (height() / 2 - hint_->height()) / 2));
    hint_->raise();
}

ViewWidget* ViewGrid::view_at(const QPoint& global) const {
    for (ViewWidget* v : views_)
        if (v->isVisible() && v->rect().contains(v->mapFromGlobal(global))) return v;
    return nullptr;
}

void ViewGrid::toggle_maximised(ViewWidget* target) {
    if (maximised_) {
        for (ViewWidget* v : views_) v->show();
        for (QSplitter* s : columns_) s->show();
        maximised_ = false;
        return;
    }
    if (!target) return;
    for (ViewWidget* v : views_) v->setVisible(v == target);
    for (QSplitter* s : columns_) s->setVisible(s->isAncestorOf(target));
    maximised_ = true;
}

} // namespace spt::editor
