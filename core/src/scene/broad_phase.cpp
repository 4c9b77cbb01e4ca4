// Sort and sweep over bounding spheres; insertion sort on last step's order.
#include "spt/broad_phase.hpp"
#include <algorithm>
#include <cmath>
#include <numeric>

namespace spt {

const std::vector<CandidatePair>& BroadPhase::find(const std::vector<BroadSphere>& s) {
    const size_t n = s.size();
    pairs_.clear();
    if (order_.size() != n) {
        order_.resize(n);
        std::iota(order_.begin(), order_.end(), 0u);
    }
    // Sweep along the axis where the centres spread most: fewest intervals overlap there.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero(), sq = Eigen::Vector3d::Zero();
    for (const BroadSphere& b : s) mean += b.center, sq += b.center.cwiseProduct(b.center);
    int axis = 0;
    if (n) {
        const Eigen::Vector3d var = sq / double(n) - (mean / double(n)).cwiseProduct(mean / double(n));
        var.maxCoeff(&axis);
    }
    lo_.resize(n);
    for (size_t i = 0; i < n; ++i) lo_[i] = s[i].center[axis] - s[i].radius; // by object index here
    // Insertion sort: last step's order is nearly right when objects move a little.
    for (size_t i = 1; i < n; ++i) {
        const uint32_t v = order_[i];
        const double key = lo_[v];
        size_t j = i;
        while (j > 0 && lo_[order_[j - 1]] > key) order_[j] = order_[j - 1], --j;
        order_[j] = v;
    }
    hi_.resize(n), x_.resize(n), y_.resize(n), z_.resize(n), r_.resize(n), static_.resize(n);
    std::vector<double>& lo_sorted = lo_; // reuse: fill sorted values into the other arrays first
    for (size_t k = 0; k < n; ++k) {
        const BroadSphere& b = s[order_[k]];
        x_[k] = b.center.x(), y_[k] = b.center.y(), z_[k] = b.center.z(), r_[k] = b.radius;
        static_[k] = b.is_static;
    }
    for (size_t k = 0; k < n; ++k) {
        const double c = s[order_[k]].center[axis];
        lo_sorted[k] = c - r_[k];
        // A relative margin: the sweep may only keep more pairs than the exact test below.
        hi_[k] = c + r_[k] + 1e-12 * (std::abs(c) + r_[k]);
    }
    for (size_t k = 0; k < n; ++k) {
        const double xk = x_[k], yk = y_[k], zk = z_[k], rk = r_[k], hk = hi_[k];
        const bool sk = static_[k];
        for (size_t m = k + 1; m < n && lo_sorted[m] < hk; ++m) {
            if (sk && static_[m]) continue;
            const double dx = x_[m] - xk, dy = y_[m] - yk, dz = z_[m] - zk, rr = r_[m] + rk;
            if (dx * dx + dy * dy + dz * dz < rr * rr) {
                const uint32_t a = order_[k], b = order_[m];
                pairs_.push_back(a < b ? CandidatePair{a, b} : CandidatePair{b, a});
            }
        }
    }
    std::sort(pairs_.begin(), pairs_.end());
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
