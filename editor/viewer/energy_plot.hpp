#pragma once
// The viewer's energy plot: kinetic + potential energy of the moving objects over the states
// played so far (Simulation::mechanical_energy of each recorded state), drawn with spt::plot.
// It follows the playhead: stepping back or restarting shortens the curve, as the trails do.
#include "spt/plot/chart.hpp"
#include <QWidget>
#include <vector>

namespace spt::editor {

/// A small chart of mechanical energy against scene time, up to the state shown.
class EnergyPlot : public QWidget {
    Q_OBJECT
public:
    /// An empty plot.
    explicit EnergyPlot(QWidget* parent = nullptr);
    /// Shows `energies` (states 0..k, one a step of `dt` seconds) on a time axis spanning the
    /// scene's `duration` seconds, so the curve grows across a fixed axis while playing.
    void show_energies(const std::vector<double>& energies, double dt, double duration);
    /// Shows no curve (no scene).
    void clear();
    /// The points drawn: (scene time in seconds, energy), one a state.
    const std::vector<QPointF>& points() const { return chart_.steps.front().points; }
    /// The size the dock gives it unless stretched.
    QSize sizeHint() const override { return {280, 180}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    plot::Chart chart_;
};

} // namespace spt::editor
