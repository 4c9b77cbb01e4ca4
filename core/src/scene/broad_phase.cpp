// Broad phase on a uniform grid: each sphere in the cell of its centre, neighbouring cells
// paired; spheres larger than half a cell tested against every other sphere.
#include "spt/broad_phase.hpp"
#include <algorithm>
#include <cmath>

namespace spt {
namespace {

constexpr uint64_t kMask = (1ull << 21) - 1;

// Cell coordinates packed 21 bits an axis; far coordinates wrap, which only adds candidates
// that the exact test then drops (and duplicates that the final unique removes).
uint64_t pack(int64_t x, int64_t y, int64_t z) {
    return ((uint64_t(x) & kMask) << 42) | ((uint64_t(y) & kMask) << 21) | (uint64_t(z) & kMask);
}

int64_t cell_of(double v, double inv) {
    const double c = std::floor(v * inv);
    return int64_t(std::clamp(c, -4.0e18, 4.0e18));
}

} // namespace

const std::vector<CandidatePair>& BroadPhase::find(const std::vector<BroadSphere>& s) {
    const size_t n = s.size();
    pairs_.clear();
    if (n < 2) return pairs_;
    auto test = [&](uint32_t a, uint32_t b) {
        if (s[a].is_static && s[b].is_static) return;
        if (spheres_overlap(s[a], s[b])) pairs_.push_back(a < b ? CandidatePair{a, b} : CandidatePair{b, a});
    };
    // Spheres up to 4 times the median radius go in cells twice the largest of them, so a sphere
    // meets only its 26 neighbour cells; the few larger ones (floors, walls) are tested against all.
    radii_.resize(n);
    for (size_t i = 0; i < n; ++i) radii_[i] = s[i].radius;
    std::nth_element(radii_.begin(), radii_.begin() + long(n / 2), radii_.end());
    const double limit = 4 * radii_[n / 2];
    double r_small = 0;
    for (const BroadSphere& b : s)
        if (b.radius <= limit) r_small = std::max(r_small, b.radius);
    const double h = r_small > 0 ? 2 * r_small : 1.0, inv = 1 / h;
    big_.clear();
    cells_.clear();
    for (uint32_t i = 0; i < n; ++i) {
        if (!(s[i].radius <= 0.5 * h)) {
            big_.push_back(i);
            continue;
        }
        const Eigen::Vector3d& c = s[i].center;
        cells_.push_back({{cell_of(c.x(), inv), cell_of(c.y(), inv), cell_of(c.z(), inv)}, 0, i});
        Cell& e = cells_.back();
        e.key = pack(e.xyz[0], e.xyz[1], e.xyz[2]);
    }
    std::sort(cells_.begin(), cells_.end(),
              [](const Cell& a, const Cell& b) { return a.key != b.key ? a.key < b.key : a.index < b.index; });
    // Two small spheres overlap only if |c1 - c2| < h: their cells differ by at most 1 an axis.
    static const int kForward[13][3] = {{0, 0, 1},  {0, 1, -1},  {0, 1, 0},  {0, 1, 1},  {1, -1, -1},
                                        {1, -1, 0}, {1, -1, 1},  {1, 0, -1}, {1, 0, 0},  {1, 0, 1},
                                        {1, 1, -1}, {1, 1, 0},   {1, 1, 1}};
    // Runs of one cell: their keys in one small array for the neighbour searches.
    keys_.clear();
    starts_.clear();
    for (size_t i = 0; i < cells_.size(); ++i)
        if (i == 0 || cells_[i].key != cells_[i - 1].key) keys_.push_back(cells_[i].key), starts_.push_back(uint32_t(i));
    starts_.push_back(uint32_t(cells_.size()));
    for (size_t r = 0; r < keys_.size(); ++r) {
        const size_t a0 = starts_[r], a1 = starts_[r + 1];
        for (size_t i = a0; i < a1; ++i)
            for (size_t j = i + 1; j < a1; ++j) test(cells_[i].index, cells_[j].index);
        const int64_t* xyz = cells_[a0].xyz;
        for (const auto& d : kForward) {
            const uint64_t key = pack(xyz[0] + d[0], xyz[1] + d[1], xyz[2] + d[2]);
            const auto it = std::lower_bound(keys_.begin(), keys_.end(), key);
            if (it == keys_.end() || *it != key) continue;
            const size_t other = size_t(it - keys_.begin());
            for (size_t j = starts_[other]; j < starts_[other + 1]; ++j)
                for (size_t i = a0; i < a1; ++i) test(cells_[i].index, cells_[j].index);
        }
    }
    for (size_t k = 0; k < big_.size(); ++k) {
        for (const Cell& c : cells_) test(big_[k], c.index);
        for (size_t m = k + 1; m < big_.size(); ++m) test(big_[k], big_[m]);
    }
    std::sort(pairs_.begin(), pairs_.end());
    pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
    return pairs_;
}

std::vector<CandidatePair> all_overlapping_pairs(const std::vector<BroadSphere>& s) {
    std::vector<CandidatePair> out;
    for (uint32_t a = 0; a < s.size(); ++a)
        for (uint32_t b = a + 1; b < s.size(); ++b)
            if (!(s[a].is_static && s[b].is_static) && spheres_overlap(s[a], s[b])) out.push_back({a, b});
    return out;
}

} // namespace spt
