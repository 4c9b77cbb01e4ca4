// SolidGrid: conservative voxelisation of walls, then a flood fill from the border.
#include "query/solid_grid.hpp"
#include "query/exact_data.hpp"
#include "query/solid.hpp"
#include "spt/compact_tree.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace spt {
namespace {

// Cells along the longest side: fine enough to find the inside of a part a few cells
// thick, coarse enough that a tolerance-sampled sphere shell has no hole a cell wide.
constexpr int kCells = 64;

// Cell states while building, apart from the three final ones: not yet reached by a flood,
// and reached by the flood of a region not yet classified.
constexpr uint8_t kFree = 3, kPending = 4;

// Triangle against an axis-aligned box (centre c, half size h), separating axes
// (Akenine-Moller 2001), grown by `grow` so rounding can only add cells.
bool triangle_touches_box(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0, const Eigen::Vector3d& c0,
                          const Eigen::Vector3d& c, double h, double grow) {
    const Eigen::Vector3d v[3] = {a0 - c, b0 - c, c0 - c};
    const double r = h + grow;
    for (int k = 0; k < 3; ++k) {
        const double lo = std::min({v[0][k], v[1][k], v[2][k]}), hi = std::max({v[0][k], v[1][k], v[2][k]});
        if (lo > r || hi < -r) return false;
    }
    const Eigen::Vector3d e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    const Eigen::Vector3d n = e[0].cross(e[1]);
    if (std::abs(n.dot(v[0])) > r * n.cwiseAbs().sum()) return false;
    for (const auto& edge : e)
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d axis = Eigen::Vector3d::Unit(k).cross(edge);
            const double p0 = axis.dot(v[0]), p1 = axis.dot(v[1]), p2 = axis.dot(v[2]);
            const double rad = r * axis.cwiseAbs().sum();
            if (std::min({p0, p1, p2}) > rad || std::max({p0, p1, p2}) < -rad) return false;
        }
    return true;
}

// Sphere model's side of point q: the nearest sample point (where a sampling sphere touches
// the surface) and its outward normal. Not the nearest sphere: across a wall thinner than two
// radii the spheres of both sides coincide, and the tie would pick a side at random.
bool inside_by_nearest_sample(const CompactTree& tree, const std::vector<uint8_t>& wall, const Eigen::Vector3d& q) {
    const auto& nodes = tree.nodes();
    double best = std::numeric_limits<double>::infinity();
    bool inside = false;
    std::vector<uint32_t> stack{0};
    const Eigen::Vector3f qf = q.cast<float>();
    while (!stack.empty()) {
        const CompactNode& n = nodes[stack.back()];
        const uint32_t self = stack.back();
        stack.pop_back();
        // Every sample point lies on its sphere, so inside its node's bounding sphere.
        const Eigen::Vector3f c(n.center[0], n.center[1], n.center[2]);
        if (double((qf - c).norm()) - n.bv_radius > best) continue;
        if (!n.is_active()) {
            stack.push_back(n.first), stack.push_back(self + 1);
            continue;
        }
        for (uint32_t k = n.first; k < n.first + n.count; ++k) {
            if (!wall.empty() && !wall[k]) continue;
            const Eigen::Vector3f normal =
                Eigen::Vector3f(tree.nx()[k], tree.ny()[k], tree.nz()[k]).normalized();
            const Eigen::Vector3f point = tree.sphere_center(n, k) + n.ss_radius * normal;
            const double d = (qf - point).norm();
            if (d >= best) continue;
            best = d;
            inside = (qf - point).dot(normal) < 0;
        }
    }
    return inside;
}

} // namespace

void SolidGrid::init(const Eigen::AlignedBox3d& box) {
    const Eigen::Vector3d size = box.sizes();
    // Two cells of padding: a wall on the box's face touches the first, never the second,
    // so the outer layer is free and connected and the flood from its corner goes all round.
    cell_ = std::max(size.maxCoeff() / (kCells - 4), 1e-300);
    for (int k = 0; k < 3; ++k) n_[k] = std::min(kCells, int(std::ceil(size[k] / cell_)) + 4);
    lo_ = box.min() - Eigen::Vector3d::Constant(2 * cell_);
    cells_.assign(size_t(n_[0]) * size_t(n_[1]) * size_t(n_[2]), kFree);
}

template <class Touches> void SolidGrid::mark(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, Touches touches) {
    int a[3], b[3];
    for (int k = 0; k < 3; ++k) {
        a[k] = std::clamp(int(std::floor((lo[k] - lo_[k]) / cell_)), 0, n_[k] - 1);
        b[k] = std::clamp(int(std::floor((hi[k] - lo_[k]) / cell_)), 0, n_[k] - 1);
    }
    for (int z = a[2]; z <= b[2]; ++z)
        for (int y = a[1]; y <= b[1]; ++y)
            for (int x = a[0]; x <= b[0]; ++x) {
                uint8_t& cell = cells_[index(x, y, z)];
                if (cell == uint8_t(Cell::Boundary)) continue;
                const Eigen::Vector3d centre = lo_ + (Eigen::Vector3d(x, y, z) + Eigen::Vector3d::Constant(0.5)) * cell_;
                if (touches(centre, 0.5 * cell_)) cell = uint8_t(Cell::Boundary);
            }
}

std::vector<uint32_t> SolidGrid::fill(uint32_t start, uint8_t from, uint8_t to) {
    std::vector<uint32_t> stack{start}, out{start};
    cells_[start] = to;
    while (!stack.empty()) {
        const uint32_t i = stack.back();
        stack.pop_back();
        const int x = int(i % uint32_t(n_[0])), y = int(i / uint32_t(n_[0]) % uint32_t(n_[1])),
                  z = int(i / (uint32_t(n_[0]) * uint32_t(n_[1])));
        const int nb[6][3] = {{x - 1, y, z}, {x + 1, y, z}, {x, y - 1, z}, {x, y + 1, z}, {x, y, z - 1}, {x, y, z + 1}};
        for (const auto& q : nb) {
            if (q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= n_[0] || q[1] >= n_[1] || q[2] >= n_[2]) continue;
            const uint32_t k = uint32_t(index(q[0], q[1], q[2]));
            if (cells_[k] != from) continue;
            cells_[k] = to;
            stack.push_back(k), out.push_back(k);
        }
    }
    return out;
}

void SolidGrid::flood(bool keep_walls, const std::function<bool(const Eigen::Vector3d&)>& solid) {
    fill(0, kFree, uint8_t(Cell::Outside)); // the corner cell lies in the padding: free
    // Every other free region: a solid, or a cavity walled in by the inner surface of a hollow part.
    for (uint32_t i = 0; i < cells_.size(); ++i) {
        if (cells_[i] != kFree) continue;
        const std::vector<uint32_t> region = fill(i, kFree, kPending);
        // A majority of up to 9 cells spread over the region, so that one cell in a corner,
        // where an approximate side test is least sure, cannot decide alone.
        const size_t votes = std::min<size_t>(9, region.size());
        size_t solid_votes = 0;
        for (size_t v = 0; v < votes; ++v) {
            const uint32_t c = region[v * region.size() / votes];
            const int x = int(c % uint32_t(n_[0])), y = int(c / uint32_t(n_[0]) % uint32_t(n_[1])),
                      z = int(c / (uint32_t(n_[0]) * uint32_t(n_[1])));
            solid_votes += solid(lo_ + (Eigen::Vector3d(x, y, z) + Eigen::Vector3d::Constant(0.5)) * cell_);
        }
        const uint8_t state = 2 * solid_votes > votes ? uint8_t(Cell::Inside) : uint8_t(Cell::Outside);
        for (uint32_t k : region) cells_[k] = state;
    }
    solid_box_.setEmpty();
    has_inside_ = false;
    for (int z = 0; z < n_[2]; ++z)
        for (int y = 0; y < n_[1]; ++y)
            for (int x = 0; x < n_[0]; ++x)
                if (const uint8_t c = cells_[index(x, y, z)]; c != uint8_t(Cell::Outside)) {
                    has_inside_ = has_inside_ || c == uint8_t(Cell::Inside);
                    const Eigen::Vector3d lo = lo_ + Eigen::Vector3d(x, y, z) * cell_;
                    solid_box_.extend(lo.cast<float>());
                    solid_box_.extend((lo + Eigen::Vector3d::Constant(cell_)).cast<float>());
                }
    if (!has_inside_ && !keep_walls) cells_.clear(), cells_.shrink_to_fit(), n_[0] = n_[1] = n_[2] = 0, solid_box_.setEmpty();
}

SolidGrid::Cell SolidGrid::at(const Eigen::Vector3f& p) const {
    if (cells_.empty()) return Cell::Outside;
    int q[3];
    for (int k = 0; k < 3; ++k) {
        const double v = std::floor((double(p[k]) - lo_[k]) / cell_);
        if (!(v >= 0 && v < n_[k])) return Cell::Outside;
        q[k] = int(v);
    }
    return Cell(cells_[index(q[0], q[1], q[2])]);
}

SolidGrid SolidGrid::of_spheres(const CompactTree& tree, const std::vector<uint8_t>& wall) {
    SolidGrid g;
    Eigen::AlignedBox3d box;
    auto is_wall = [&](uint32_t k) { return wall.empty() || wall[k]; };
    for (const CompactNode& n : tree.nodes())
        for (uint32_t k = n.first; n.is_active() && k < n.first + n.count; ++k) {
            if (!is_wall(k)) continue;
            const Eigen::Vector3d c = tree.sphere_center(n, k).cast<double>();
            box.extend(c - Eigen::Vector3d::Constant(n.ss_radius)), box.extend(c + Eigen::Vector3d::Constant(n.ss_radius));
        }
    if (box.isEmpty()) return g;
    g.init(box);
    for (const CompactNode& n : tree.nodes())
        for (uint32_t k = n.first; n.is_active() && k < n.first + n.count; ++k) {
            if (!is_wall(k)) continue;
            const Eigen::Vector3d c = tree.sphere_center(n, k).cast<double>();
            const double r = n.ss_radius;
            g.mark(c - Eigen::Vector3d::Constant(r), c + Eigen::Vector3d::Constant(r),
                   [&](const Eigen::Vector3d& centre, double h) {
                       // Distance from the sphere's centre to the cell's box, grown for rounding.
                       const Eigen::Vector3d d = ((c - centre).cwiseAbs() - Eigen::Vector3d::Constant(h)).cwiseMax(0.0);
                       return d.norm() <= r * (1 + 1e-6) + 1e-4 * h;
                   });
        }
    g.flood(false, [&](const Eigen::Vector3d& q) { return inside_by_nearest_sample(tree, wall, q); });
    return g;
}

SolidGrid SolidGrid::of_triangles(const ExactData& e) {
    SolidGrid g;
    Eigen::AlignedBox3d box;
    for (size_t f = 0; f < e.triangles.size(); ++f)
        if (e.closed[f])
            for (uint32_t v : e.triangles[f]) box.extend(e.positions[v]);
    if (box.isEmpty()) return g;
    g.init(box);
    for (size_t f = 0; f < e.triangles.size(); ++f) {
        if (!e.closed[f]) continue;
        const auto& t = e.triangles[f];
        const Eigen::Vector3d &a = e.positions[t[0]], &b = e.positions[t[1]], &c = e.positions[t[2]];
        g.mark(a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c), [&](const Eigen::Vector3d& centre, double h) {
            // Grown by far more than a float lookup can be off, so a point read into a
            // neighbouring cell is on the same side of every wall as that cell.
            return triangle_touches_box(a, b, c, centre, h, 1e-4 * h);
        });
    }
    g.flood(true, [&](const Eigen::Vector3d& q) { return inside_closed_parts(e, q); });
    return g;
}

} // namespace spt
