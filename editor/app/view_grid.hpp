#pragma once
// The four views in a resizable 2x2 grid in `spt render --view quad` order: top | front
// over side | camera. One view can fill the grid and give the space back (Ctrl+Space).
#include "view_widget.hpp"
#include <QWidget>
#include <array>

class QLabel;
class QSplitter;

namespace spt::editor {

/// Top, front, side and camera views in splitters whose columns stay aligned.
class ViewGrid : public QWidget {
    Q_OBJECT
public:
    /// Makes the four views over `scene`; selections go to `doc`.
    ViewGrid(EditorDocument& doc, Scene& scene, const ViewOptions& options, QWidget* parent = nullptr);
    /// View i in quad order: 0 top, 1 front, 2 side, 3 camera.
    ViewWidget* view(int i) const { return views_[size_t(i)]; }
    /// The view under global screen point `p`, or nullptr.
    ViewWidget* view_at(const QPoint& global) const;
    /// Fills the grid with `v`, or restores all four if one is already maximised.
    void toggle_maximised(ViewWidget* v);
    /// True while one view fills the grid.
    bool maximised() const { return maximised_; }
    /// The hint over the views while no document is open ("open a mesh or a .spt file...").
    const QLabel& empty_hint() const { return *hint_; }

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void place_hint();
    QLabel* hint_ = nullptr;
    std::array<ViewWidget*, 4> views_{};
    QSplitter* rows_ = nullptr;
    std::array<QSplitter*, 2> columns_{};
    bool maximised_ = false;
};

} // namespace spt::editor
