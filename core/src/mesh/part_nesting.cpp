// Which closed parts are the inner walls of hollows: nesting by exact ray parity, for parts
// wholly inside others (no faces meeting, by exact triangle tests).
#include "mesh/part_nesting.hpp"
#include "geometry/ray_parity.hpp"
#include "geometry/tri_tri.hpp"
#include <algorithm>
#include <cmath>
#include <utility>

namespace spt::detail {
namespace {

// True if a face of part `a` shares a point with a face of part `b` (exact triangle tests on
// the pairs whose boxes overlap, found through a grid over a's box of about one cell a face).
bool surfaces_meet(const TriangleMesh& m, const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
    auto box_of = [&](uint32_t f) {
        Eigen::AlignedBox3d box;
        for (uint32_t v : m.triangles[f]) box.extend(m.positions[v]);
        return box;
    };
    Eigen::AlignedBox3d region;
    for (uint32_t f : a) region.extend(box_of(f));
    // Only b's faces that reach a's box can meet a face of a.
    std::vector<uint32_t> near;
    std::vector<Eigen::AlignedBox3d> near_box;
    for (uint32_t f : b) {
        const Eigen::AlignedBox3d box = box_of(f);
        if (box.intersects(region)) near.push_back(f), near_box.push_back(box);
    }
    if (near.empty()) return false;
    int n = std::clamp(int(std::cbrt(double(a.size() + near.size()))), 1, 128);
    const Eigen::Vector3d lo = region.min();
    const Eigen::Vector3d size = region.sizes().cwiseMax(1e-300);
    auto cells = [&](const Eigen::AlignedBox3d& box, int axis) {
        auto at = [&](double x) { return std::clamp(int(std::floor((x - lo[axis]) / size[axis] * n)), 0, n - 1); };
        return std::pair<int, int>(at(box.min()[axis]), at(box.max()[axis]));
    };
    // Each near face listed in every cell its box overlaps (counted, then placed).
    auto for_cells = [&](const Eigen::AlignedBox3d& box, auto&& visit) {
        const auto [x0, x1] = cells(box, 0);
        const auto [y0, y1] = cells(box, 1);
        const auto [z0, z1] = cells(box, 2);
        for (int z = z0; z <= z1; ++z)
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) visit((size_t(z) * size_t(n) + size_t(y)) * size_t(n) + size_t(x));
    };
    // Faces far larger than a cell (slivers across the box) would be listed in thousands of
    // cells each: a coarser grid keeps the lists within a budget.
    const double budget = 16.0 * double(a.size() + near.size()) + double(1 << 20);
    for (; n > 1; n = std::max(1, n / 2)) {
        double entries = 0;
        for (const Eigen::AlignedBox3d& box : near_box) {
            double spans = 1;
            for (int axis = 0; axis < 3; ++axis) spans *= cells(box, axis).second - cells(box, axis).first + 1;
            entries += spans;
        }
        if (entries <= budget) break;
    }
    std::vector<uint32_t> start(size_t(n) * size_t(n) * size_t(n) + 1, 0);
    for (const Eigen::AlignedBox3d& box : near_box) for_cells(box, [&](size_t c) { ++start[c + 1]; });
    for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    std::vector<uint32_t> listed(start.back()), fill(start.begin(), start.end() - 1);
    for (uint32_t k = 0; k < near.size(); ++k) for_cells(near_box[k], [&](size_t c) { listed[fill[c]++] = k; });
    for (uint32_t f : a) {
        const Eigen::AlignedBox3d box = box_of(f);
        const auto& t = m.triangles[f];
        bool met = false;
        for_cells(box, [&](size_t c) {
            for (uint32_t i = start[c]; i < start[c + 1] && !met; ++i) {
                const uint32_t k = listed[i];
                if (!box.intersects(near_box[k])) continue;
                const auto& u = m.triangles[near[k]];
                met = triangles_intersect(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]], m.positions[u[0]],
                                          m.positions[u[1]], m.positions[u[2]]);
            }
        });
        if (met) return true;
    }
    return false;
}

} // namespace

std::vector<int> nesting_depths(const TriangleMesh& m, const std::vector<std::vector<uint32_t>>& components) {
    std::vector<int> depth(components.size(), 0);
    std::vector<Eigen::AlignedBox3d> box(components.size());
    std::vector<size_t> closed;
    for (size_t c = 0; c < components.size(); ++c) {
        if (m.on_open_part[components[c][0]]) continue;
        closed.push_back(c);
        for (uint32_t f : components[c])
            for (uint32_t v : m.triangles[f]) box[c].extend(m.positions[v]);
    }
    for (size_t i : closed)
        for (size_t j : closed)
            if (i != j && box[j].contains(box[i]) &&
                inside_by_parity(m.positions, m.triangles, components[j], m.positions[m.triangles[components[i][0]][0]]) &&
                !surfaces_meet(m, components[i], components[j]))
                ++depth[i];
    return depth;
}

} // namespace spt::detail
