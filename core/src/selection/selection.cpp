// Rectangle selection of a node's samples: projection, the through test, combining with a selection.
#include "spt/selection.hpp"
#include <algorithm>
#include <cmath>
#include <iterator>

namespace spt {

Eigen::Vector3f project_to_window(const ViewProjection& view, const Eigen::Vector3d& p) {
    const Eigen::Vector4f eye = view.view * Eigen::Vector4f(float(p.x()), float(p.y()), float(p.z()), 1.0f);
    const Eigen::Vector4f clip = view.projection * eye;
    const float w = view.perspective ? clip.w() : 1.0f;
    const float x = (clip.x() / w + 1.0f) * 0.5f * float(std::max(view.width, 1));
    const float y = (clip.y() / w + 1.0f) * 0.5f * float(std::max(view.height, 1));
    return {x, y, -eye.z()};
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
    bool contains(const Eigen::Vector3f& w) const { return w.x() >= x0 && w.x() <= x1 && w.y() >= y0 && w.y() <= y1; }
};

// A point behind the eye projects through it mirrored: it is never inside the rectangle.
bool selectable(const ViewProjection& view, const Eigen::Vector3f& w) { return !view.perspective || w.z() > 0; }

} // namespace

std::vector<uint32_t> samples_in_rect(const SampleSet& samples, const SamplingTree& tree, NodeId id,
                                      const ViewProjection& view, const PixelRect& rect) {
    const Box box(rect);
    std::vector<uint32_t> out;
    for (uint32_t s : samples_below(tree, id)) {
        const Eigen::Vector3f w = project_to_window(view, samples.position(s));
        if (selectable(view, w) && box.contains(w)) out.push_back(s);
    }
    return out;
}

float DepthMap::at(int x, int y) const {
    if (x < 0 || y < 0 || x >= width || y >= height) return INFINITY;
    return depth[size_t(y) * size_t(width) + size_t(x)];
}

std::vector<uint32_t> visible_samples_in_rect(const SampleSet& samples, const SamplingTree& tree, NodeId id,
                                              const ViewProjection& view, const PixelRect& rect,
                                              const DepthMap& depth, float tolerance) {
    const Box box(rect);
    std::vector<uint32_t> out;
    for (uint32_t s : samples_below(tree, id)) {
        const Eigen::Vector3f w = project_to_window(view, samples.position(s));
        if (!selectable(view, w) || !box.contains(w)) continue;
        const int px = int(std::floor(w.x())), py = int(std::floor(w.y()));
        float farthest = -INFINITY;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) farthest = std::max(farthest, depth.at(px + dx, py + dy));
        if (w.z() <= farthest + tolerance) out.push_back(s);
    }
    return out;
}

float visible_tolerance(const TriangleMesh& mesh) { return float(0.005 * mesh.diagonal()); }

std::vector<uint32_t> apply_stroke(const SampleSet& samples, const SamplingTree& tree, NodeId id,
                                   const std::vector<uint32_t>& current, const RecipeStroke& stroke,
                                   const TriangleMesh* mesh) {
    const std::vector<uint32_t> hits =
        stroke.visible_only && mesh
            ? visible_samples_in_rect(samples, tree, id, stroke.view, stroke.rect, render_depth(*mesh, stroke.view, stroke.rect),
                                      visible_tolerance(*mesh))
            : samples_in_rect(samples, tree, id, stroke.view, stroke.rect);
    return combine_selection(current, hits, stroke.mode);
}

std::vector<uint32_t> select_strokes(const SampleSet& samples, const SamplingTree& tree, const RecipeStep& step,
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
