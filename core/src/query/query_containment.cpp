// Containment: after a walk that found no meeting surfaces, is a piece of one model inside a
// closed part of the other? Each piece is asked by one anchor point (docs/queries.md).
#include "query/model_access.hpp"
#include "query/exact_data.hpp"
#include "query/query_run.hpp"
#include "query/solid.hpp"

namespace spt {

void QueryRun::check_containment() {
    if (!o.solids || res.collide || !roots_overlap) return;
    const SolidData &sa = detail::solid_of(A), &sb = detail::solid_of(B);
    // Records a containment: depth 0, the contained anchor (A's local frame) as the point.
    auto contain = [&](const Eigen::Vector3d& point_in_a) {
        res.collide = true;
        if (o.mode != QueryMode::All) {
            res.deepest = Contact{};
            res.deepest.point = A.origin() + point_in_a;
        }
    };
    // Is local point p (holder's frame) inside `holder`? `exact_p()` gives the same point in
    // double, asked only where the triangles must answer: most anchors fall outside the grid's
    // box, and moving each in double first was 4% of env/rob's exact walk.
    // A posed holder has no grid: its posed triangles answer.
    auto inside = [&](const SolidGrid& grid, bool posed, const ExactData& holder, const Eigen::Vector3f& p,
                      auto&& exact_p) {
        if (posed) {
            ++res.counters.bound_tests;
            return inside_closed_parts(holder, exact_p());
        }
        if (!grid.solid_box().contains(p)) return false;
        ++res.counters.bound_tests;
        switch (grid.at(p)) {
        case SolidGrid::Cell::Inside: return true;
        case SolidGrid::Cell::Outside: return false;
        case SolidGrid::Cell::Boundary: return exact && inside_closed_parts(holder, exact_p());
        }
        return false;
    };
    const SolidGrid& grid_a = exact ? sa.of_triangles : sa.of_spheres;
    const SolidGrid& grid_b = exact ? sb.of_triangles : sb.of_spheres;
    // B's pieces in A: B's anchors moved into A's frame as B's vertices are.
    if (grid_a.has_solid() || sa.posed)
        for (size_t k = 0; k < sb.anchors.size(); ++k) {
            const Eigen::Vector3f p = f.R * sb.anchors[k] + f.t;
            auto pd = [&]() -> Eigen::Vector3d { return exact ? b_vertex(sb.anchor_vertex[k]) : p.cast<double>(); };
            if (inside(grid_a, sa.posed, EA, p, pd)) return contain(pd());
        }
    // A's pieces in B: A's anchors moved into B's frame by the inverse placement.
    if (grid_b.has_solid() || sb.posed)
        for (size_t k = 0; k < sa.anchors.size(); ++k) {
            const Eigen::Vector3f p = f.R.transpose() * (sa.anchors[k] - f.t);
            auto pd = [&]() -> Eigen::Vector3d {
                return exact ? Eigen::Vector3d(f.Rd.transpose() * (EA.positions[sa.anchor_vertex[k]] - f.td))
                             : p.cast<double>();
            };
            if (inside(grid_b, sb.posed, EB, p, pd))
                return contain(exact ? EA.positions[sa.anchor_vertex[k]] : sa.anchors[k].cast<double>());
        }
}

} // namespace spt
