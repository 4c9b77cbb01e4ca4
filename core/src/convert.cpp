#include "spt/convert.hpp"
#include "spt/error.hpp"
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>

namespace spt {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

MeshInfo info_of(const TriangleMesh& mesh) {
    return {mesh.name, uint32_t(mesh.positions.size()), uint32_t(mesh.triangles.size()), mesh.content_hash(),
            mesh.diagonal()};
}

double mean_edge(const TriangleMesh& m, uint32_t f) {
    const auto& t = m.triangles[f];
    const auto &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
    return ((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3.0;
}

// Radius each face sample's leaf actually uses.
std::vector<float> leaf_radius_of_samples(const SamplingTree& tree, size_t n) {
    std::vector<float> r(n, 0);
    for (const TreeNode* node : tree.active_nodes())
        for (uint32_t s : node->samples) r[s] = node->ss_radius;
    return r;
}

} // namespace

SptDocument make_document(const TriangleMesh& mesh, const ConvertOptions& options, ConvertStats* stats) {
    ConvertStats local;
    ConvertStats& st = stats ? *stats : local;
    auto t0 = Clock::now();
    const SampleSet vertex_samples = sample_vertices(mesh);
    if (vertex_samples.size() == 0) throw_bad_input(mesh.name, "no vertex has a computable normal; nothing to sample");
    st.vertex_samples = vertex_samples.size();
    const RadiusRule& rule = options.build.radius;

    SptDocument doc;
    doc.mesh = info_of(mesh);
    if (!options.tolerance) {
        doc.samples = vertex_samples;
        st.sample_seconds = seconds_since(t0);
        t0 = Clock::now();
        doc.trees.push_back(build_tree(options.tree_name, doc.samples, options.build));
        st.build_seconds = seconds_since(t0);
        return doc;
    }

    const double eps = *options.tolerance;
    if (!(eps > 0) || !std::isfinite(eps)) throw Error(ErrorKind::Usage, "--tolerance must be a positive length");
    const size_t nt = mesh.triangles.size();
    std::vector<uint32_t> all(nt);
    std::vector<double> gap(nt);
    for (uint32_t f = 0; f < nt; ++f) {
        all[f] = f;
        // First guess of the radius a face will get: what the rule gives its own spacing.
        const double r = rule.fixed > 0 ? rule.fixed : rule.scale * mean_edge(mesh, f);
        gap[f] = max_face_sample_gap(r, eps);
    }
    // A node's radius depends on which samples share it, so check the radii the tree
    // really gave and densify the faces that got a smaller one; a few rounds settle it.
    constexpr int kMaxRounds = 6;
    SamplingTree tree(options.tree_name, 0u);
    for (int round = 1;; ++round) {
        SampleSet s = vertex_samples;
        add_face_samples(s, mesh, all, gap);
        st.sample_seconds += seconds_since(t0);
        t0 = Clock::now();
        tree = build_tree(options.tree_name, s, options.build);
        st.build_seconds += seconds_since(t0);
        t0 = Clock::now();
        st.tolerance_rounds = round;
        const std::vector<float> radius = leaf_radius_of_samples(tree, s.size());
        std::vector<double> used(nt, INFINITY);
        for (size_t i = 0; i < s.size(); ++i)
            if (s.is_face_sample(i)) used[s.source_index(i)] = std::min<double>(used[s.source_index(i)], radius[i]);
        bool changed = false;
        st.worst_predicted_gap = 0;
        for (uint32_t f = 0; f < nt; ++f) {
            if (!std::isfinite(used[f])) continue; // degenerate face: no samples
            const double need = max_face_sample_gap(used[f], eps);
            if (gap[f] > need * (1 + 1e-9)) {
                gap[f] = need * 0.95;
                changed = true;
            }
            st.worst_predicted_gap =
                std::max(st.worst_predicted_gap, std::sqrt(gap[f] * gap[f] + used[f] * used[f]) - used[f]);
        }
        doc.samples = std::move(s);
        if (!changed || round == kMaxRounds) break;
    }
    st.vertex_samples = vertex_samples.size();
    st.face_samples = doc.samples.size() - vertex_samples.size();
    doc.trees.push_back(std::move(tree));
    return doc;
}

SptDocument load_or_convert(const std::string& path, const ConvertOptions& options) {
    char magic[6] = {};
    std::ifstream(path, std::ios::binary).read(magic, 6);
    if (std::memcmp(magic, "SPTREE", 6) == 0) return load_spt(path);
    const ImportedMesh m = import_mesh(path);
    return make_document(m.mesh, options);
}

} // namespace spt
