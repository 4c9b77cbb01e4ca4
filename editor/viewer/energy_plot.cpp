// EnergyPlot: mechanical energy over the states played, as an spt::plot chart.
#include "energy_plot.hpp"
#include <QPainter>

namespace spt::editor {

EnergyPlot::EnergyPlot(QWidget* parent) : QWidget(parent) {
    setObjectName("energy_plot");
    setMinimumHeight(150);
    chart_.x.title = "time (s)";
    chart_.y.title = "energy";
    chart_.style.font_px = 10, chart_.style.title_px = 11; // a dock's width: small type
    // One value a step, held until the next: a staircase says exactly that.
    chart_.steps.push_back({QString(), QColor(40, 110, 220), 1.5, {}, false});
    // The state shown, so the value under the playhead is easy to find.
    chart_.series.push_back({QString(), plot::Marker::Disc, QColor(230, 120, 20), QColor(60, 60, 60), 6, {}});
    clear();
}

void EnergyPlot::show_energies(const std::vector<double>& energies, double dt, double duration) {
    std::vector<QPointF>& p = chart_.steps.front().points;
    p.resize(energies.size());
    for (size_t k = 0; k < energies.size(); ++k) p[k] = QPointF(double(k) * dt, energies[k]);
    chart_.series.front().points.assign(p.empty() ? p.end() : p.end() - 1, p.end());
    chart_.x.min = 0, chart_.x.max = duration > 0 ? duration : dt;
    chart_.title = p.empty() ? QString("kinetic + potential energy")
                             : QString("kinetic + potential energy: %1").arg(p.back().y(), 0, 'g', 6);
    update();
}

void EnergyPlot::clear() { show_energies({}, 1, 1); }

void EnergyPlot::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    plot::paint_chart(painter, chart_, size());
}

} // namespace spt::editor
