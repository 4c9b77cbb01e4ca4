// Mesh adjacency of samples: neighbours, the mesh's parts (select linked), grow, shrink, invert.
#include "spt/error.hpp"
#include "spt/selection.hpp"
#include <algorithm>
#include <iterator>
#include <numeric>
#include <string>

namespace spt {
namespace {

// Compressed lists: `start` has one entry per owner plus one; owner k's items are
// items[start[k] .. start[k + 1]).
void compress(size_t owners, const std::vector<std::pair<uint32_t, uint32_t>>& pairs, std::vector<uint32_t>& start,
              std::vector<uint32_t>& items) {
    start.assign(owners + 1, 0);
    for (const auto& p : pairs) ++start[p.first + 1];
    for (size_t k = 0; k < owners; ++k) start[k + 1] += start[k];
    items.resize(pairs.size());
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (const auto& p : pairs) items[fill[p.first]++] = p.second; // pairs sorted: items sorted per owner
}

uint32_t root_of(std::vector<uint32_t>& up, uint32_t v) {
    while (up[v] != v) v = up[v] = up[up[v]];
    return v;
}

} // namespace

SampleAdjacency::SampleAdjacency(const TriangleMesh& mesh, const SampleSet& samples) {
    const size_t nv = mesh.positions.size(), nt = mesh.triangles.size();
    std::vector<std::pair<uint32_t, uint32_t>> corners; // (sample, vertex)
    corners.reserve(samples.size());
    for (size_t s = 0; s < samples.size(); ++s) {
        const uint32_t src = samples.source_index(s);
        if (samples.is_face_sample(s)) {
            if (src >= nt)
                throw Error(ErrorKind::Usage, "selection: sample " + std::to_string(s) + " lies on triangle " +
                                                  std::to_string(src) + ", beyond the mesh's " + std::to_string(nt));
            for (int c = 0; c < 3; ++c) corners.emplace_back(uint32_t(s), mesh.triangles[src][c]);
        } else {
            if (src >= nv)
                throw Error(ErrorKind::Usage, "selection: sample " + std::to_string(s) + " lies on vertex " +
                                                  std::to_string(src) + ", beyond the mesh's " + std::to_string(nv));
            corners.emplace_back(uint32_t(s), src);
        }
    }
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    compress(samples.size(), corners, corner_start_, corners_);
    first_vertex_.resize(samples.size());
    for (size_t s = 0; s < samples.size(); ++s) first_vertex_[s] = corners_[corner_start_[s]];

    std::vector<std::pair<uint32_t, uint32_t>> touch; // (vertex, sample)
    touch.reserve(corners.size());
    for (const auto& c : corners) touch.emplace_back(c.second, c.first);
    std::sort(touch.begin(), touch.end());
    compress(nv, touch, touch_start_, touching_);

    std::vector<std::pair<uint32_t, uint32_t>> edges; // both directions
    edges.reserve(6 * nt);
    std::vector<uint32_t> up(nv);
    std::iota(up.begin(), up.end(), 0u);
    for (size_t f = 0; f < nt; ++f) {
        if (mesh.copies_earlier_face(f)) continue;
        const auto& t = mesh.triangles[f];
        for (int c = 0; c < 3; ++c) {
            const uint32_t a = t[c], b = t[(c + 1) % 3];
            edges.emplace_back(a, b), edges.emplace_back(b, a);
            const uint32_t ra = root_of(up, a), rb = root_of(up, b);
            if (ra != rb) up[std::max(ra, rb)] = std::min(ra, rb); // the lowest vertex names its part
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    compress(nv, edges, edge_start_, edge_to_);
    part_.resize(nv);
    for (uint32_t v = 0; v < nv; ++v) part_[v] = root_of(up, v);
}

std::vector<uint32_t> SampleAdjacency::neighbours(uint32_t s) const {
    std::vector<uint32_t> out;
    auto add_touching = [&](uint32_t v) {
        out.insert(out.end(), touching_.begin() + touch_start_[v], touching_.begin() + touch_start_[v + 1]);
    };
    for (uint32_t k = corner_start_[s]; k < corner_start_[s + 1]; ++k) {
        const uint32_t v = corners_[k];
        add_touching(v);
        for (uint32_t e = edge_start_[v]; e < edge_start_[v + 1]; ++e) add_touching(edge_to_[e]);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    out.erase(std::remove(out.begin(), out.end(), s), out.end());
    return out;
}

std::vector<uint32_t> sample_neighbours(const SampleAdjacency& adjacency, uint32_t s) { return adjacency.neighbours(s); }

namespace {

void check_sample_count(const SampleAdjacency& adjacency, const std::vector<uint32_t>& below) {
    if (!below.empty() && below.back() >= adjacency.size())
        throw Error(ErrorKind::Usage, "selection: adjacency of " + std::to_string(adjacency.size()) +
                                          " samples for a tree over sample " + std::to_string(below.back()));
}

} // namespace

std::vector<uint32_t> linked_samples(const SampleAdjacency& adjacency, const SamplingTree& tree, NodeId id,
                                     uint32_t seed) {
    std::vector<uint32_t> out = samples_below(tree, id);
    check_sample_count(adjacency, out);
    if (seed >= adjacency.size()) return {};
    const uint32_t part = adjacency.part(seed);
    out.erase(std::remove_if(out.begin(), out.end(), [&](uint32_t s) { return adjacency.part(s) != part; }), out.end());
    return out;
}

std::vector<uint32_t> grow_selection(const SampleAdjacency& adjacency, const SamplingTree& tree, NodeId id,
                                     const std::vector<uint32_t>& selection) {
    const std::vector<uint32_t> below = samples_below(tree, id);
    check_sample_count(adjacency, below);
    std::vector<uint32_t> reached = selection;
    for (uint32_t s : selection) {
        if (s >= adjacency.size()) continue;
        const std::vector<uint32_t> n = adjacency.neighbours(s);
        reached.insert(reached.end(), n.begin(), n.end());
    }
    std::sort(reached.begin(), reached.end());
    reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
    std::vector<uint32_t> out;
    std::set_intersection(reached.begin(), reached.end(), below.begin(), below.end(), std::back_inserter(out));
    return out;
}

std::vector<uint32_t> shrink_selection(const SampleAdjacency& adjacency, const SamplingTree& tree, NodeId id,
                                       const std::vector<uint32_t>& selection) {
    const std::vector<uint32_t> below = samples_below(tree, id);
    check_sample_count(adjacency, below);
    std::vector<uint32_t> out;
    for (uint32_t s : selection) {
        if (s >= adjacency.size()) continue;
        bool inner = true;
        for (uint32_t n : adjacency.neighbours(s))
            if (std::binary_search(below.begin(), below.end(), n) &&
                !std::binary_search(selection.begin(), selection.end(), n)) {
                inner = false;
                break;
            }
        if (inner) out.push_back(s);
    }
    return out;
}

std::vector<uint32_t> invert_selection(const SamplingTree& tree, NodeId id, const std::vector<uint32_t>& selection) {
    const std::vector<uint32_t> below = samples_below(tree, id);
    std::vector<uint32_t> out;
    std::set_difference(below.begin(), below.end(), selection.begin(), selection.end(), std::back_inserter(out));
    return out;
}

} // namespace spt
