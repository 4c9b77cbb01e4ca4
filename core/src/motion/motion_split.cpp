// The split chooser of a build from motion: binned planes scored by how often the recorded
// motion enters each child, plus a volume term for the poses it did not record.
#include "motion/motion_split.hpp"
#include <algorithm>
#include <array>
#include <cmath>

namespace spt::detail {
namespace {

constexpr int kMotionBins = 16;
// Nodes of at most this many leaves' worth of samples are left to the automatic builder.
constexpr size_t kMotionLeaves = 32;
// A node looks at no more entries than this (an even subsample beyond): the top levels of a
// large model would otherwise dominate the build while their choice barely changes.
constexpr size_t kMaxEntries = 1 << 12;
// All nodes together read no more entries than this: beyond it, only every k-th recorded step is
// read (a large model near a partner at every step would otherwise make the build slower than
// the recording).
constexpr size_t kMaxTotalEntries = size_t(1) << 21;
// A node's box comes from an even subsample of at most this many samples (the partition is exact).
constexpr size_t kMaxBoxSamples = 1 << 12;

struct Box {
    float lo[3] = {INFINITY, INFINITY, INFINITY};
    float hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    void add(const Eigen::Vector3f& p) {
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
    }
    void add(const Box& b) {
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
    }
    bool empty() const { return lo[0] > hi[0]; }
    Eigen::Vector3f centre() const { return {0.5f * (lo[0] + hi[0]), 0.5f * (lo[1] + hi[1]), 0.5f * (lo[2] + hi[2])}; }
    float radius() const {
        if (empty()) return 0;
        return 0.5f * Eigen::Vector3f(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]).norm();
    }
};

struct Entry {
    uint32_t member; // index into the node's members
    uint32_t step;   // index into the reaches
    float gap;       // model units
};

size_t count_bits(const std::vector<uint64_t>& bits, size_t at, size_t words) {
    size_t n = 0;
    for (size_t w = 0; w < words; ++w) n += size_t(__builtin_popcountll(bits[at + w]));
    return n;
}

} // namespace

MotionSplit::MotionSplit(const SampleSet& samples, const MotionRecording& rec, double random_weight, uint32_t leaf_size)
    : samples_(samples), random_weight_(random_weight), leaf_size_(std::max<uint32_t>(1, leaf_size)) {
    // build_best checked that the recording is over these samples.
    size_t total = 0;
    for (const MotionReach& r : rec.reaches) total += r.near.size();
    const size_t every = std::max<size_t>(1, (total + kMaxTotalEntries - 1) / kMaxTotalEntries);
    std::vector<const MotionReach*> read;
    for (size_t k = 0; k < rec.reaches.size(); k += every) read.push_back(&rec.reaches[k]);
    steps_ = uint32_t(read.size());
    first_.assign(samples.size() + 1, 0);
    for (const MotionReach* r : read)
        for (const auto& [s, g] : r->near) ++first_[s + 1];
    for (size_t i = 0; i < samples.size(); ++i) first_[i + 1] += first_[i];
    entry_step_.resize(first_.back());
    entry_gap_.resize(first_.back());
    std::vector<uint32_t> at(first_.begin(), first_.end() - 1);
    for (uint32_t k = 0; k < read.size(); ++k)
        for (const auto& [s, g] : read[k]->near) {
            entry_step_[at[s]] = k;
            entry_gap_[at[s]++] = g;
        }
}

MotionSplit::Answer MotionSplit::choose(const uint32_t* members, size_t n, NodeId, std::vector<uint8_t>& left) const {
    if (n < 2 || steps_ == 0) return Answer::NotBelow;
    // Below a few leaves' worth the automatic split is as good, and the motion's entries are many
    // a sample there: the build's time would go to the nodes that matter least.
    if (n <= kMotionLeaves * leaf_size_) return Answer::NotBelow;
    std::vector<Entry> entries;
    for (size_t m = 0; m < n; ++m)
        for (uint32_t e = first_[members[m]]; e < first_[members[m] + 1]; ++e)
            entries.push_back({uint32_t(m), entry_step_[e], entry_gap_[e]});
    if (entries.empty()) return Answer::NotBelow; // nor has any node below
    if (entries.size() > kMaxEntries) {
        const size_t stride = (entries.size() + kMaxEntries - 1) / kMaxEntries;
        size_t k = 0;
        for (size_t i = 0; i < entries.size(); i += stride) entries[k++] = entries[i];
        entries.resize(k);
    }
    const std::vector<Eigen::Vector3f>& p = samples_.points;
    const size_t box_stride = std::max<size_t>(1, n / kMaxBoxSamples);
    Box node;
    for (size_t m = 0; m < n; m += box_stride) node.add(p[members[m]]);
    for (const Entry& e : entries) node.add(p[members[e.member]]); // the near samples exactly
    const float node_r = node.radius();
    if (!(node_r > 0)) return Answer::Builder;
    // Is the node itself entered at any recorded step? If not, the motion says nothing about it.
    {
        const Eigen::Vector3f c = node.centre();
        bool entered = false;
        for (const Entry& e : entries)
            if (e.gap + (p[members[e.member]] - c).norm() < node_r) {
                entered = true;
                break;
            }
        if (!entered) return Answer::Builder;
    }
    const size_t words = (steps_ + 63) / 64;
    const double K = double(steps_);
    double best_cost = INFINITY;
    int best_axis = -1, best_plane = 0;
    std::array<float, 3> scale{};
    for (int a = 0; a < 3; ++a) {
        const float extent = node.hi[a] - node.lo[a];
        if (!(extent > 0)) continue;
        scale[size_t(a)] = kMotionBins / extent;
        auto bin_of = [&](const Eigen::Vector3f& q) {
            return std::clamp(int((q[a] - node.lo[a]) * scale[size_t(a)]), 0, kMotionBins - 1);
        };
        std::array<Box, kMotionBins> bins;
        std::array<double, kMotionBins> counts{};
        for (size_t m = 0; m < n; m += box_stride) {
            const int b = bin_of(p[members[m]]);
            bins[size_t(b)].add(p[members[m]]);
            counts[size_t(b)] += double(box_stride);
        }
        for (const Entry& e : entries) bins[size_t(bin_of(p[members[e.member]]))].add(p[members[e.member]]);
        // Children of plane j (1..bins-1): bins below j left, the rest right.
        std::array<Box, kMotionBins> lbox, rbox;
        std::array<double, kMotionBins> ln{}, rn{};
        Box acc;
        double cn = 0;
        for (int j = 1; j < kMotionBins; ++j) {
            acc.add(bins[size_t(j - 1)]), cn += counts[size_t(j - 1)];
            lbox[size_t(j)] = acc, ln[size_t(j)] = cn;
        }
        acc = Box(), cn = 0;
        for (int j = kMotionBins - 1; j >= 1; --j) {
            acc.add(bins[size_t(j)]), cn += counts[size_t(j)];
            rbox[size_t(j)] = acc, rn[size_t(j)] = cn;
        }
        std::array<Eigen::Vector3f, kMotionBins> lc, rc;
        std::array<float, kMotionBins> lr{}, rr{};
        for (int j = 1; j < kMotionBins; ++j) {
            lc[size_t(j)] = lbox[size_t(j)].centre(), lr[size_t(j)] = lbox[size_t(j)].radius();
            rc[size_t(j)] = rbox[size_t(j)].centre(), rr[size_t(j)] = rbox[size_t(j)].radius();
        }
        // Steps at which each candidate's children are entered, one bit a step.
        std::vector<uint64_t> lhit(size_t(kMotionBins) * words, 0), rhit(size_t(kMotionBins) * words, 0);
        for (const Entry& e : entries) {
            const Eigen::Vector3f& q = p[members[e.member]];
            const int b = bin_of(q);
            const uint64_t bit = uint64_t(1) << (e.step & 63);
            const size_t word = e.step >> 6;
            for (int j = b + 1; j < kMotionBins; ++j)
                if (e.gap + (q - lc[size_t(j)]).norm() < lr[size_t(j)]) lhit[size_t(j) * words + word] |= bit;
            for (int j = 1; j <= b; ++j)
                if (e.gap + (q - rc[size_t(j)]).norm() < rr[size_t(j)]) rhit[size_t(j) * words + word] |= bit;
        }
        for (int j = 1; j < kMotionBins; ++j) {
            if (lbox[size_t(j)].empty() || rbox[size_t(j)].empty()) continue;
            const double l_vol = std::pow(double(lr[size_t(j)]) / node_r, 3.0);
            const double r_vol = std::pow(double(rr[size_t(j)]) / node_r, 3.0);
            const double cost =
                (double(count_bits(lhit, size_t(j) * words, words)) / K + random_weight_ * l_vol) * ln[size_t(j)] +
                (double(count_bits(rhit, size_t(j) * words, words)) / K + random_weight_ * r_vol) * rn[size_t(j)];
            if (cost < best_cost) best_cost = cost, best_axis = a, best_plane = j;
        }
    }
    if (best_axis < 0) return Answer::Builder;
    left.assign(n, 0);
    size_t nl = 0;
    for (size_t m = 0; m < n; ++m) {
        const float t = (p[members[m]][best_axis] - node.lo[best_axis]) * scale[size_t(best_axis)];
        const int b = std::clamp(int(t), 0, kMotionBins - 1);
        left[m] = b < best_plane;
        nl += left[m];
    }
    return nl > 0 && nl < n ? Answer::Split : Answer::Builder;
}

} // namespace spt::detail
