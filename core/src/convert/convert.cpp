// Mesh to document: vertex samples, tolerance-driven face samples, one built tree.
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "base/cancel.hpp"
#include "base/parallel.hpp"
#include "sampling/radius_class.hpp"
#include "sampling/surface_samples.hpp"
#include <chrono>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

namespace spt {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

MeshInfo info_of(const TriangleMesh& mesh) {
    return {mesh.name, uint32_t(mesh.positions.size()), uint32_t(mesh.triangles.size()), mesh.content_hash(),
            mesh.diagonal()};
}

// Radius each sample's active node actually uses.
std::vector<float> radius_in_use(const SamplingTree& tree, size_t n) {
    std::vector<float> r(n, 0);
    for (const TreeNode* node : tree.active_nodes())
        for (uint32_t s : node->samples) r[s] = node->ss_radius;
    return r;
}

struct VertexOnlyGaps {
    double worst = 0;             // largest uncovered depth on a face, model units
    size_t uncovered_open = 0;    // faces of open parts not held by their corners' spheres
};

// What vertex samples alone leave uncovered: every point of a face is within
// (longest edge)/sqrt(3) of a corner, whose sphere lies flat under it, or on an open part is
// centred on it and must hold it (within kTwoSidedCoverage of its radius, as face sampling asks).
VertexOnlyGaps vertex_only_gaps(const RadiusLimiter& limiter, const SampleSet& s, const std::vector<float>& radius) {
    const TriangleMesh& mesh = limiter.mesh();
    std::vector<float> at_vertex(mesh.positions.size(), 0);
    for (size_t i = 0; i < s.size(); ++i) at_vertex[s.source_index(i)] = radius[i];
    VertexOnlyGaps g;
    for (uint32_t f = 0; f < mesh.triangles.size(); ++f) {
        const auto& t = mesh.triangles[f];
        const auto &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        const double rho = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()}) / std::sqrt(3.0);
        const double r = std::min({at_vertex[t[0]], at_vertex[t[1]], at_vertex[t[2]]});
        if (limiter.face_on_open_part(f)) {
            g.worst = std::max(g.worst, rho - r);
            g.uncovered_open += rho > kTwoSidedCoverage * r;
        } else {
            g.worst = std::max(g.worst, std::sqrt(rho * rho + r * r) - r);
        }
    }
    return g;
}

// Names the stage starting and stops here if the caller asked to.
void stage(const ConvertOptions& o, const TriangleMesh& mesh, const char* name) {
    detail::stop_if_cancelled(o.cancel, "converting", mesh.name);
    if (name && o.on_stage) o.on_stage(name);
}

// make_document; `two_sided_share` of a tolerance is the two-sided radius (see below); `tolerance`
// stands for options.tolerance, so that the automatic tolerance's pass needs no copy of the options
// (their poses may be large).
SptDocument convert(const TriangleMesh& mesh, const ConvertOptions& options, const std::optional<double>& tolerance,
                    ConvertStats* stats, double two_sided_share) {
    ConvertStats local;
    ConvertStats& st = stats ? *stats : local;
    if (tolerance && (!(*tolerance > 0) || !std::isfinite(*tolerance)))
        throw Error(ErrorKind::Usage, "--tolerance must be a positive length");
    // Two objects meet: their errors add. Within a tolerance each object keeps its gaps to
    // half of it and its protrusion to an eighth, so a pair stays well within it.
    const double protrusion =
        options.protrusion ? *options.protrusion
                           : (tolerance ? *tolerance / 8 : kDefaultProtrusion * mesh.diagonal());
    if (!(protrusion > 0) || !std::isfinite(protrusion)) throw Error(ErrorKind::Usage, "protrusion must be positive");
    // A two-sided sphere (open part) pokes out of either side of the surface by exactly its
    // radius, with no edge or thin wall to pass: a quarter of a tolerance the caller gives, so
    // that two shells together take half of it and surfaces a tolerance apart are not reported
    // as touching; without one, the default allowance (the automatic tolerance's half).
    const double two_sided_radius =
        options.protrusion ? *options.protrusion
                           : (tolerance ? *tolerance * two_sided_share : protrusion);

    if (mesh.positions.size() > kMaxSourceIndex || mesh.triangles.size() > kMaxSourceIndex)
        throw_bad_input(mesh.name, "more than " + std::to_string(kMaxSourceIndex) + " vertices or triangles");

    stage(options, mesh, "sampling vertices");
    auto t0 = Clock::now();
    const int threads = options.threads > 0 ? options.threads : detail::machine_threads();
    // The limiter's triangle tree and the mesh's hash (for the file) both only read the mesh.
    std::unique_ptr<RadiusLimiter> limiter_made;
    MeshInfo info;
    detail::parallel_for(2, threads, [&](size_t k, int) {
        if (k == 0) limiter_made = std::make_unique<RadiusLimiter>(mesh, protrusion, two_sided_radius);
        else info = info_of(mesh);
    }, options.tasks);
    for (const TriangleMesh& pose : options.poses) limiter_made->add_pose(pose);
    const RadiusLimiter& limiter = *limiter_made;
    stage(options, mesh, nullptr);
    const SampleSet vertex_samples = sample_vertices(mesh, limiter, options.build.radius, threads, options.cancel, options.tasks);
    if (vertex_samples.size() == 0) throw_bad_input(mesh.name, "no vertex has a computable normal; nothing to sample");
    st.vertex_samples = vertex_samples.size();
    const RadiusRule& rule = options.build.radius;

    SptDocument doc;
    doc.mesh = info;
    if (!tolerance) {
        doc.samples = vertex_samples;
        st.sample_seconds = seconds_since(t0);
        stage(options, mesh, "building the tree");
        t0 = Clock::now();
        BuildOptions build = options.build;
        build.threads = threads;
        if (options.tasks) build.tasks = options.tasks;
        if (options.cancel) build.cancel = options.cancel;
        doc.trees.push_back(build_tree(options.tree_name, doc.samples, build));
        st.build_seconds = seconds_since(t0);
        const VertexOnlyGaps gaps = vertex_only_gaps(limiter, doc.samples, radius_in_use(doc.trees[0], doc.samples.size()));
        st.worst_predicted_gap = std::max(0.0, gaps.worst);
        st.uncovered_open_faces = gaps.uncovered_open;
        const double automatic = kAutoTolerance * mesh.diagonal();
        if (!options.auto_tolerance || (st.worst_predicted_gap <= automatic && gaps.uncovered_open == 0)) return doc;
        // Vertices alone leave holes (large flat faces), or leave faces of open parts outside
        // their spheres (two open sheets crossing there could pass between them): sample the faces too.
        limiter_made.reset(); // the pass below makes its own, with as many trees over the poses
        ConvertStats again;
        SptDocument sampled = convert(mesh, options, automatic, &again, 0.5); // two-sided radius: the allowance
        again.automatic_tolerance = automatic;
        again.uncovered_open_faces = gaps.uncovered_open;
        again.sample_seconds += st.sample_seconds, again.build_seconds += st.build_seconds;
        st = again;
        return sampled;
    }

    // The builder keeps active nodes radius-coherent, so a node's radius is at least
    // 1/kRadiusClassRatio of each member's own radius: faces are sampled for that radius.
    const double eps = *tolerance / 2;
    SampleSet s = vertex_samples;
    // A tolerance far below the mesh's detail (model units mistaken for a fraction of the
    // diagonal, say) would sample for hours into all memory: refused up front from a lower
    // bound on the count, or as soon as the samples pass the limit.
    const auto too_many = [&](const std::string& count) {
        std::ostringstream why;
        why << "a tolerance of " << *tolerance << " (" << *tolerance / mesh.diagonal()
            << " of the diagonal " << mesh.diagonal() << ") needs " << count << " samples; at most " << kMaxSamples
            << " are made: give a larger --tolerance";
        throw_bad_input(mesh.name, why.str());
    };
    const double least = least_face_samples(limiter, eps, rule, 1.0f / kRadiusClassRatio);
    if (double(s.size()) + least > double(kMaxSamples)) {
        std::ostringstream count;
        count << "at least " << std::setprecision(3) << double(s.size()) + least;
        too_many(count.str());
    }
    stage(options, mesh, "sampling faces");
    try {
        s.append(face_samples(limiter, s.origin, eps, rule, 1.0f / kRadiusClassRatio, threads, options.cancel,
                              kMaxSamples - s.size(), options.tasks));
    } catch (const TooManySamples&) {
        too_many("more than " + std::to_string(kMaxSamples));
    }
    stage(options, mesh, nullptr); // a cancel during face sampling left it unfinished
    st.sample_seconds = seconds_since(t0);
    stage(options, mesh, "building the tree");
    t0 = Clock::now();
    BuildOptions coherent = options.build;
    coherent.radius_coherent = true;
    coherent.threads = threads;
    if (options.tasks) coherent.tasks = options.tasks;
    if (options.cancel) coherent.cancel = options.cancel;
    SamplingTree tree = build_tree(options.tree_name, s, coherent);
    st.build_seconds = seconds_since(t0);
    // Check the assumption against the radii the tree gave.
    const std::vector<float> used = radius_in_use(tree, s.size());
    bool holds = true;
    for (size_t i = vertex_samples.size(); i < s.size(); ++i)
        // Two-sided samples keep their own radius, up to the bfloat16 rounding of a spacing
        // that ties with it (the 10% margin of kTwoSidedCoverage absorbs that).
        holds = holds && used[i] >= rule.for_sample(s.spacing[i], s.max_radius[i]) *
                                        (s.is_two_sided(i) ? 0.99f : (1 - 1e-6f) / kRadiusClassRatio);
    st.worst_predicted_gap = holds ? eps : INFINITY;
    doc.samples = std::move(s);
    st.face_samples = doc.samples.size() - vertex_samples.size();
    doc.trees.push_back(std::move(tree));
    return doc;
}

} // namespace

SptDocument make_document(const TriangleMesh& mesh, const ConvertOptions& options, ConvertStats* stats) {
    return convert(mesh, options, options.tolerance, stats, 0.25);
}

SptDocument load_or_convert(const std::string& path, const ConvertOptions& options) {
    if (is_spt_file(path)) return load_spt(path);
    const ImportedMesh m = import_mesh(path);
    return make_document(m.mesh, options);
}

} // namespace spt
