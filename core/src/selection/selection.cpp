// Rectangle selection of a node's samples: projection, the through test, combining with a selection.
#include "spt/selection.hpp"
#include "selection/window_point.hpp"
#include "base/parallel.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <string>

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

namespace {

void check_window_points(const std::vector<Eigen::Vector2f>& points, const char* what) {
    for (size_t k = 0; k < points.size(); ++k)
        if (!points[k].allFinite())
            throw Error(ErrorKind::Usage, std::string("selection: ") + what + " point " + std::to_string(k) +
                                              " is not finite");
}

PixelRect bounds_of(const std::vector<Eigen::Vector2f>& points, float grow) {
    PixelRect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const Eigen::Vector2f& p : points) {
        r.x0 = std::min(r.x0, p.x()), r.y0 = std::min(r.y0, p.y());
        r.x1 = std::max(r.x1, p.x()), r.y1 = std::max(r.y1, p.y());
    }
    if (points.empty()) return {};
    return {r.x0 - grow, r.y0 - grow, r.x1 + grow, r.y1 + grow};
}

// The samples below `id` inside `box` for which `inside(window x, y)` holds, visible only with a
// depth map: the rectangle's test with another shape inside the box.
template <class Inside>
std::vector<uint32_t> samples_in_shape(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                       const ViewProjection& view, const PixelRect& window, const DepthMap* depth,
                                       float tolerance, const Inside& inside) {
    const Box box(window);
    const detail::WindowMap map(view);
    if (!depth)
        return kept_samples(samples, tree, id, map, [&](const Eigen::Vector3f& w) {
            return selectable(view, w) & box.contains(w) && inside(w.x(), w.y());
        });
    const FarthestAround farthest(*depth, box);
    return kept_samples(samples, tree, id, map, [&](const Eigen::Vector3f& w) {
        return selectable(view, w) & box.contains(w) && inside(w.x(), w.y()) &&
               w.z() <= farthest.at(w.x(), w.y()) + tolerance;
    });
}

// Squared distance from (x, y) to the segment a-b, in double so long segments keep their pixels.
double segment_d2(double x, double y, const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
    const double ax = a.x(), ay = a.y(), dx = double(b.x()) - ax, dy = double(b.y()) - ay;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    const double ex = ax + t * dx - x, ey = ay + t * dy - y;
    return ex * ex + ey * ey;
}

} // namespace

std::vector<uint32_t> samples_in_polygon(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                         const ViewProjection& view, const std::vector<Eigen::Vector2f>& polygon,
                                         const DepthMap* depth, float tolerance) {
    check_window_points(polygon, "lasso");
    if (polygon.size() < 3) return {};
    const size_t n = polygon.size();
    // Even-odd: a horizontal ray to the right crosses the edges an odd number of times.
    return samples_in_shape(samples, tree, id, view, bounds_of(polygon, 0), depth, tolerance, [&](float x, float y) {
        bool in = false;
        for (size_t i = 0, j = n - 1; i < n; j = i++) {
            const Eigen::Vector2f &a = polygon[i], &b = polygon[j];
            if ((a.y() > y) != (b.y() > y)) {
                const double cross = double(b.x() - a.x()) * double(y - a.y()) / double(b.y() - a.y()) + double(a.x());
                if (double(x) < cross) in = !in;
            }
        }
        return in;
    });
}

std::vector<uint32_t> samples_in_brush(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                       const ViewProjection& view, const std::vector<Eigen::Vector2f>& path,
                                       float radius, const DepthMap* depth, float tolerance) {
    check_window_points(path, "brush path");
    if (!std::isfinite(radius) || radius < 0)
        throw Error(ErrorKind::Usage, "selection: brush radius " + std::to_string(radius) + " is not a finite size >= 0");
    if (path.empty()) return {};
    const double r2 = double(radius) * double(radius);
    return samples_in_shape(samples, tree, id, view, bounds_of(path, radius), depth, tolerance, [&](float x, float y) {
        if (path.size() == 1) return segment_d2(x, y, path[0], path[0]) <= r2;
        for (size_t k = 1; k < path.size(); ++k)
            if (segment_d2(x, y, path[k - 1], path[k]) <= r2) return true;
        return false;
    });
}

PixelRect stroke_window(const RecipeStroke& stroke) {
    switch (stroke.kind) {
    case StrokeKind::Lasso: return bounds_of(stroke.points, 0);
    case StrokeKind::Brush: return bounds_of(stroke.points, stroke.radius);
    default: return stroke.rect;
    }
}

int64_t pick_sample(const SamplePoints& samples, const SamplingTree& tree, NodeId id, const ViewProjection& view,
                    const Eigen::Vector2f& window, float max_pixels, const DepthMap* depth, float tolerance) {
    const std::vector<Eigen::Vector2f> circle{window};
    const std::vector<uint32_t> near = samples_in_brush(samples, tree, id, view, circle, max_pixels, depth, tolerance);
    const detail::WindowMap map(view);
    int64_t best = -1;
    double best_d2 = INFINITY, best_z = INFINITY;
    for (uint32_t s : near) { // sorted: the first of equals is the lowest index
        const Eigen::Vector3f w = map(samples.origin + samples.points[s].cast<double>());
        const double dx = double(w.x()) - window.x(), dy = double(w.y()) - window.y(), d2 = dx * dx + dy * dy;
        if (d2 < best_d2 || (d2 == best_d2 && double(w.z()) < best_z)) best = s, best_d2 = d2, best_z = w.z();
    }
    return best;
}

int64_t nearest_sample(const SamplePoints& samples, const SamplingTree& tree, NodeId id, const Eigen::Vector3d& p) {
    int64_t best = -1;
    double best_d2 = INFINITY;
    for (uint32_t s : samples_below(tree, id)) {
        if (s >= samples.points.size())
            throw Error(ErrorKind::Usage, "selection: " + std::to_string(samples.points.size()) +
                                              " sample points for a tree over sample " + std::to_string(s));
        const double d2 = (samples.origin + samples.points[s].cast<double>() - p).squaredNorm();
        if (d2 < best_d2) best = s, best_d2 = d2;
    }
    return best;
}

std::vector<uint32_t> stroke_hits(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                  const RecipeStroke& stroke, const TriangleMesh* mesh,
                                  const SampleAdjacency* adjacency) {
    std::optional<DepthMap> depth;
    float tolerance = 0;
    if (stroke.visible_only && mesh && !stroke.is_operation() && stroke.kind != StrokeKind::Linked) {
        depth = render_depth(*mesh, stroke.view, stroke_window(stroke));
        tolerance = visible_tolerance(*mesh);
    }
    const DepthMap* d = depth ? &*depth : nullptr;
    switch (stroke.kind) {
    case StrokeKind::Rect:
        return d ? visible_samples_in_rect(samples, tree, id, stroke.view, stroke.rect, *d, tolerance)
                 : samples_in_rect(samples, tree, id, stroke.view, stroke.rect);
    case StrokeKind::Lasso: return samples_in_polygon(samples, tree, id, stroke.view, stroke.points, d, tolerance);
    case StrokeKind::Brush:
        return samples_in_brush(samples, tree, id, stroke.view, stroke.points, stroke.radius, d, tolerance);
    case StrokeKind::Linked: {
        if (!adjacency) throw Error(ErrorKind::Usage, "selection: select linked needs the mesh's adjacency");
        const int64_t seed = nearest_sample(samples, tree, id, stroke.pick);
        if (seed < 0) return {};
        return linked_samples(*adjacency, tree, id, uint32_t(seed));
    }
    default: return {};
    }
}

std::vector<uint32_t> apply_stroke(const SamplePoints& samples, const SamplingTree& tree, NodeId id,
                                   const std::vector<uint32_t>& current, const RecipeStroke& stroke,
                                   const TriangleMesh* mesh, const SampleAdjacency* adjacency) {
    if (stroke.needs_adjacency() && !adjacency)
        throw Error(ErrorKind::Usage, "selection: linked, grow and shrink need the mesh's adjacency");
    switch (stroke.kind) {
    case StrokeKind::Invert: return invert_selection(tree, id, current);
    case StrokeKind::Grow: return grow_selection(*adjacency, tree, id, current);
    case StrokeKind::Shrink: return shrink_selection(*adjacency, tree, id, current);
    default: return combine_selection(current, stroke_hits(samples, tree, id, stroke, mesh, adjacency), stroke.mode);
    }
}

std::vector<uint32_t> select_strokes(const SamplePoints& samples, const SamplingTree& tree, const RecipeStep& step,
                                     const TriangleMesh* mesh, const SampleAdjacency* adjacency) {
    std::vector<uint32_t> selection;
    for (const RecipeStroke& s : step.strokes)
        selection = apply_stroke(samples, tree, step.node, selection, s, mesh, adjacency);
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
