#pragma once
// Where a model is solid: a coarse grid over its local bounding box whose cells are outside
// (reached from the border without crossing a wall), boundary (a wall passes through) or
// inside (walled in). Walls are the sampling spheres, or the triangles of closed parts.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <vector>

namespace spt {

class CompactTree;
struct ExactData;

class SolidGrid {
public:
    enum class Cell : uint8_t { Outside = 0, Boundary = 1, Inside = 2 };

    /// A grid with nothing inside.
    SolidGrid() = default;
    /// Walls are the sampling spheres of `tree` for which `wall` (per sphere, compact order) is
    /// 1, every sphere if it is empty: the spheres of closed parts when the mesh is known, since
    /// an open part's shell with a slit narrower than a cell would enclose a solid of its own.
    static SolidGrid of_spheres(const CompactTree& tree, const std::vector<uint8_t>& wall = {});
    /// Walls are the triangles of closed parts (ExactData::closed); open parts enclose nothing.
    static SolidGrid of_triangles(const ExactData& e);

    /// True if the grid has any wall (boundary cells) left: a point can be in the solid.
    bool has_solid() const { return !cells_.empty(); }
    /// True if some cell is inside.
    bool has_inside() const { return has_inside_; }
    /// Box (local frame) around every cell that is not outside; empty if none.
    const Eigen::AlignedBox3f& solid_box() const { return solid_box_; }
    /// The cell holding local point p; Outside beyond the grid.
    Cell at(const Eigen::Vector3f& p) const;
    /// Bytes held.
    size_t memory_bytes() const { return cells_.capacity(); }

private:
    // Sizes the grid around `box` (two free cells of padding on every side).
    void init(const Eigen::AlignedBox3d& box);
    // Marks as boundary every cell whose box `touches`, among those of the box [lo, hi].
    template <class Touches> void mark(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, Touches touches);
    // Outside: every cell reached from the corner through non-boundary cells. Each walled-in
    // region is a solid or a cavity (a hollow part's inside): `solid(cell centre)` of a few of
    // its cells decides by majority, once a region. Without inside cells the grid is dropped unless `keep_walls` (the exact
    // level still decides boundary cells by rays).
    void flood(bool keep_walls, const std::function<bool(const Eigen::Vector3d&)>& solid);
    // Marks every cell connected to `start` through cells of state `from` as `to`; returns them.
    std::vector<uint32_t> fill(uint32_t start, uint8_t from, uint8_t to);
    size_t index(int x, int y, int z) const { return (size_t(z) * size_t(n_[1]) + size_t(y)) * size_t(n_[0]) + size_t(x); }

    Eigen::Vector3d lo_ = Eigen::Vector3d::Zero();
    double cell_ = 1;
    int n_[3] = {0, 0, 0};
    std::vector<uint8_t> cells_;
    bool has_inside_ = false;
    Eigen::AlignedBox3f solid_box_;
};

} // namespace spt
