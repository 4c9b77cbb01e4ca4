// Rectangle selection of a node's samples: projection, the through test, combining with a selection.
#include "spt/selection.hpp"
#include "selection/window_point.hpp"
#include "base/parallel.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <cmath>
#include <iterator>

namespace spt {

Eigen::Vector3f project_to_window(const ViewProjection& view, const Eigen::Vector3d& p) {
    return detail::WindowMap(view)(p);
}

std::vector<uint32_t> samples_below(const SamplingTree& tree, NodeId id) {
    std::vector<uint32_t> out;
    if (!tree.find(id)) return out;
    for (const TreeNode* n : tree.active_nodes()) {
        NodeId a = n->id;
        while (a > id) a = parent_of(a);
        if (a == id) out.insert(out.end(), n->samples.begin(), n->samples.end());
    }
    if (!std::is_sorted(out.begin(), out.end())) std::sort(out.begin(), out.end());
    return out;
}

namespace {

struct Box {
    float x0, y0, x1, y1;
    explicit Box(const PixelRect& r)
        : x0(std::min(r.x0, r.x1)), y0(std::min(r.y0, r.y1)), x1(std::max(r.x0, r.x1)), y1(std::max(r.y0, r.y1)) {}
    // `&`, not `&&`: samples fall in and out of a rectangle in no order a branch predicts.
    bool contains(const Eigen::Vector3f& w) const {
        return (w.x() >= x0) & (w.x() <= x1) & (w.y() >= y0) & (w.y() <= y1);
    }
};

// A point behind the eye projects through it mirrored: it is never inside the rectangle.
bool selectable(const ViewProjection& view, const Eigen::Vector3f& w) { return !view.perspective | (w.z() > 0); }

// Samples a thread takes at a time: below a few of these, threads cost more than they save.
constexpr size_t kChunk = size_t(1) << 16;

// The samples below `id` whose window point passes `keep(window point)`, with the view's kind
// fixed. Chunks of the sorted id list are filtered in place on the machine's threads (an id is
// read before its slot is written), then closed up in order: the result does not depend on
// the thread count.
template <bool Perspective, class Keep>
std::vector<uint32_t> kept_samples(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                   const detail::WindowMap& window, const Keep& keep) {
    std::vector<uint32_t> out = samples_below(tree, id);
    // Sorted: the last index is the largest. Points of another sample set (a pose of another
    // mesh) would be read past their end.
    if (!out.empty() && out.back() >= samples.points.size())
        throw Error(ErrorKind::Usage, "selection: " + std::to_string(samples.points.size()) +
                                          " sample points for a tree over sample " + std::to_string(out.back()));
    const double ox = samples.origin.x(), oy = samples.origin.y(), oz = samples.origin.z();
    const size_t chunks = (out.size() + kChunk - 1) / kChunk;
    std::vector<size_t> kept(chunks);
    detail::parallel_for(chunks, detail::machine_threads(), [&](size_t c, int) {
        const size_t b = c * kChunk, e = std::min(out.size(), b + kChunk);
        size_t n = b;
        for (size_t k = b; k < e; ++k) {
            const uint32_t s = out[k];
            const Eigen::Vector3f& q = samples.points[s]; // origin + point (SampleSet::position), unrolled
            const Eigen::Vector3f w = window.map<Perspective>(ox + double(q.x()), oy + double(q.y()), oz + double(q.z()));
            out[n] = s;
            n += size_t(keep(w));
        }
        kept[c] = n - b;
    });
    size_t total = 0;
    for (size_t c = 0; c < chunks; ++c) {
        if (total != c * kChunk) // already in place otherwise
            std::copy(out.begin() + long(c * kChunk), out.begin() + long(c * kChunk + kept[c]), out.begin() + long(total));
        total += kept[c];
    }
    out.resize(total);
    return out;
}

template <class Keep>
std::vector<uint32_t> kept_samples(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                   const detail::WindowMap& window, const Keep& keep) {
    return window.perspective() ? kept_samples<true>(samples, tree, id, window, keep)
                                : kept_samples<false>(samples, tree, id, window, keep);
}

} // namespace

std::vector<uint32_t> samples_in_rect(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                      const ViewProjection& view, const PixelRect& rect) {
    const Box box(rect);
    return kept_samples(samples, tree, id, detail::WindowMap(view),
                        [&](const Eigen::Vector3f& w) { return selectable(view, w) & box.contains(w); });
}

float DepthMap::at(int x, int y) const {
    if (x < 0 || y < 0 || x >= width || y >= height) return INFINITY;
    return depth[size_t(y) * size_t(width) + size_t(x)];
}

namespace {

// The farthest depth among the 3x3 pixels around each pixel of the rectangle, made once for
// all its samples instead of nine reads a sample; +infinity where one of the nine lies outside
// the map, that is around every pixel but those in [1, width - 2] x [1, height - 2].
class FarthestAround {
public:
    FarthestAround(const DepthMap& depth, const Box& box) {
        x0_ = std::max(1.0f, std::floor(box.x0)), x1_ = std::min(float(depth.width - 2), std::floor(box.x1));
        y0_ = std::max(1.0f, std::floor(box.y0)), y1_ = std::min(float(depth.height - 2), std::floor(box.y1));
        if (!(x0_ <= x1_ && y0_ <= y1_)) return; // no such pixel (or NaN corners)
        w_ = int(x1_ - x0_) + 1;
        const int h = int(y1_ - y0_) + 1, ix0 = int(x0_), iy0 = int(y0_);
        std::vector<float> rows(size_t(w_) * size_t(h + 2)); // the maxima across, rows y0 - 1 to y1 + 1
        for (int r = 0; r < h + 2; ++r) {
            const float* d = depth.depth.data() + size_t(iy0 - 1 + r) * size_t(depth.width) + size_t(ix0);
            for (int i = 0; i < w_; ++i) rows[size_t(r) * size_t(w_) + size_t(i)] = std::max({d[i - 1], d[i], d[i + 1]});
        }
        farthest_.resize(size_t(w_) * size_t(h));
        for (int r = 0; r < h; ++r)
            for (int i = 0; i < w_; ++i) {
                const size_t k = size_t(r) * size_t(w_) + size_t(i);
                farthest_[k] = std::max({rows[k], rows[k + size_t(w_)], rows[k + 2 * size_t(w_)]});
            }
    }

    /// The farthest depth around the pixel holding window point (x, y).
    float at(float x, float y) const {
        if (!(x >= x0_ && x < x1_ + 1.0f && y >= y0_ && y < y1_ + 1.0f)) return INFINITY;
        return farthest_[size_t(int(y - y0_)) * size_t(w_) + size_t(int(x - x0_))];
    }

private:
    float x0_ = 0, x1_ = -1, y0_ = 0, y1_ = -1; // pixel range held, whole pixels
    int w_ = 0;
    std::vector<float> farthest_;
};

} // namespace

std::vector<uint32_t> visible_samples_in_rect(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                              const ViewProjection& view, const PixelRect& rect,
                                              const DepthMap& depth, float tolerance) {
    const Box box(rect);
    const FarthestAround farthest(depth, box);
    return kept_samples(samples, tree, id, detail::WindowMap(view), [&](const Eigen::Vector3f& w) {
        return selectable(view, w) & box.contains(w) && w.z() <= farthest.at(w.x(), w.y()) + tolerance;
    });
}

float visible_tolerance(const TriangleMesh& mesh) { return float(0.005 * mesh.diagonal()); }

std::vector<uint32_t> apply_stroke(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                   const std::vector<uint32_t>& current, const RecipeStroke& stroke,
                                   const TriangleMesh* mesh) {
    const std::vector<uint32_t> hits =
        stroke.visible_only && mesh
            ? visible_samples_in_rect(samples, tree, id, stroke.view, stroke.rect, render_depth(*mesh, stroke.view, stroke.rect),
                                      visible_tolerance(*mesh))
            : samples_in_rect(samples, tree, id, stroke.view, stroke.rect);
    return combine_selection(current, hits, stroke.mode);
}

std::vector<uint32_t> select_strokes(const SamplePoints& samples, const SamplingTree& tree, const RecipeStep& step,
                                     const TriangleMesh* mesh) {
    std::vector<uint32_t> selection;
    for (const RecipeStroke& s : step.strokes) selection = apply_stroke(samples, tree, step.node, selection, s, mesh);
    return selection;
}

std::vector<uint32_t> combine_selection(const std::vector<uint32_t>& current, const std::vector<uint32_t>& hits,
                                        SelectionMode mode) {
    std::vector<uint32_t> out;
    switch (mode) {
    case SelectionMode::Replace: return hits;
    case SelectionMode::Add:
        std::set_union(current.begin(), current.end(), hits.begin(), hits.end(), std::back_inserter(out));
        break;
    case SelectionMode::Subtract:
        std::set_difference(current.begin(), current.end(), hits.begin(), hits.end(), std::back_inserter(out));
        break;
    }
    return out;
}

} // namespace spt
