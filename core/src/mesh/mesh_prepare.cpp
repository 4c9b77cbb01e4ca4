// Turns raw triangles into a TriangleMesh: weld, topology report, orientation fix, normals.
#include "spt/error.hpp"
#include "spt/mesh.hpp"
#include "mesh/vertex_normals.hpp"
#include "mesh/part_nesting.hpp"
#include "mesh/weld.hpp"
#include "base/cancel.hpp"
#include "base/parallel.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <queue>
#include <sstream>

namespace spt {
namespace {

struct HalfEdge {
    uint64_t key;  // (min << 32) | max
    uint32_t face;
    bool forward;  // face walks min -> max
};

// Faces in disjoint sets (union-find with path halving).
class DisjointFaces {
public:
    explicit DisjointFaces(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    uint32_t find(uint32_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void join(uint32_t a, uint32_t b) { parent_[find(a)] = find(b); }
    // Number of sets.
    size_t count() {
        size_t n = 0;
        for (uint32_t f = 0; f < parent_.size(); ++f) n += find(f) == f;
        return n;
    }
    // The faces of each set, sets in the order of their first face, faces ascending.
    std::vector<std::vector<uint32_t>> groups() {
        std::vector<std::vector<uint32_t>> out;
        std::vector<int64_t> index_of_root(parent_.size(), -1);
        for (uint32_t f = 0; f < parent_.size(); ++f) {
            const uint32_t root = find(f);
            if (index_of_root[root] < 0) index_of_root[root] = int64_t(out.size()), out.emplace_back();
            out[size_t(index_of_root[root])].push_back(f);
        }
        return out;
    }

private:
    std::vector<uint32_t> parent_;
};

// Offsets of a counting sort by `bucket` (values below `buckets`): out[b] is where bucket b
// starts, out[buckets] the total.
template <class Bucket> std::vector<uint32_t> bucket_starts(size_t count, size_t buckets, Bucket bucket) {
    std::vector<uint32_t> start(buckets + 1, 0);
    for (size_t i = 0; i < count; ++i) ++start[bucket(i) + 1];
    for (size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
    return start;
}

// Half-edges of every face but those `skip` marks (empty: none), in (key, face) order: a
// counting sort by the smaller vertex, then a small sort within each vertex's run (a few
// edges), instead of one sort of them all.
std::vector<HalfEdge> collect_edges(const std::vector<Triangle>& tris, size_t vertex_count,
                                    const std::vector<uint8_t>& skip) {
    std::vector<uint32_t> live; // the faces kept, when some are skipped
    if (!skip.empty())
        for (uint32_t f = 0; f < tris.size(); ++f)
            if (!skip[f]) live.push_back(f);
    const size_t faces = skip.empty() ? tris.size() : live.size();
    auto face_at = [&](size_t i) { return skip.empty() ? uint32_t(i) : live[i]; };
    const size_t n = faces * 3;
    auto lo_of = [&](size_t i) {
        const Triangle& t = tris[face_at(i / 3)];
        return std::min(t[i % 3], t[(i % 3 + 1) % 3]);
    };
    std::vector<uint32_t> start = bucket_starts(n, vertex_count, lo_of);
    std::vector<HalfEdge> edges(n);
    for (size_t i = 0; i < faces; ++i) {
        const uint32_t f = face_at(i);
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = tris[f][k], b = tris[f][(k + 1) % 3];
            const uint64_t lo = std::min(a, b), hi = std::max(a, b);
            edges[start[lo]++] = {(lo << 32) | hi, f, a < b};
        }
    }
    auto before = [](const HalfEdge& x, const HalfEdge& y) { return x.key != y.key ? x.key < y.key : x.face < y.face; };
    // start[v] is now where vertex v's run ends.
    for (size_t v = 0, b = 0; v < vertex_count; b = start[v++])
        if (start[v] - b > 1) std::sort(edges.begin() + long(b), edges.begin() + long(start[v]), before);
    return edges;
}

// End of the run of half-edges that share edges[i]'s key (edges sorted by key).
size_t run_end(const std::vector<HalfEdge>& edges, size_t i) {
    size_t j = i;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    return j;
}

double signed_volume(const TriangleMesh& m, const std::vector<uint32_t>& faces) {
    // Relative to the first vertex, so far-from-origin parts keep precision.
    const Eigen::Vector3d o = m.positions[m.triangles[faces[0]][0]];
    double v = 0;
    for (uint32_t f : faces) {
        const auto& t = m.triangles[f];
        v += (m.positions[t[0]] - o).dot((m.positions[t[1]] - o).cross(m.positions[t[2]] - o));
    }
    return v / 6.0;
}

// A closed part whose walls lie on one another (a sheet modelled as a flat closed shell: assimp's
// OBJ/regr01.obj's trims, their walls 3e-5 apart) encloses no volume and has no inside to fill:
// each of its faces would hang its spheres on whichever side its winding says, outside the part
// on one wall or the other. Such a part is marked open, so that it is sampled as a sheet
// (two-sided spheres) and walls in no solid. "No volume": a mean thickness, twice the volume
// over the area, below kFlatPartThickness of the mesh's diagonal, far below anything a float
// layout resolves.
constexpr double kFlatPartThickness = 1e-6;

void mark_flat_parts_open(TriangleMesh& m, const std::vector<std::vector<uint32_t>>& part_faces,
                          const std::vector<double>& volume, const std::vector<uint32_t>& copy_of, double diagonal,
                          ImportReport& r) {
    for (size_t c = 0; c < part_faces.size(); ++c) {
        const std::vector<uint32_t>& part = part_faces[c];
        if (m.on_open_part[part[0]]) continue;
        double area = 0;
        for (uint32_t f : part) {
            const auto& t = m.triangles[f];
            area += 0.5 * (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm();
        }
        if (!(2 * std::abs(volume[c]) < kFlatPartThickness * diagonal * area)) continue;
        for (uint32_t f : part) m.on_open_part[f] = 1;
        ++r.flat_closed_parts;
    }
    if (r.flat_closed_parts == 0) return;
    for (uint32_t f = 0; f < copy_of.size(); ++f) m.on_open_part[f] = m.on_open_part[copy_of[f]];
    r.warnings.push_back(std::to_string(r.flat_closed_parts) +
                         " closed part(s) enclose no volume (walls on one another): sampled as open sheets");
}

// Per face, the first face with the same three vertices (either winding): itself for all
// but the later copies. Counts the copies and the vertices no face uses into `r`.
std::vector<uint32_t> find_duplicates(const TriangleMesh& m, ImportReport& r) {
    std::vector<uint32_t> copy_of(m.triangles.size());
    std::iota(copy_of.begin(), copy_of.end(), 0u);
    // Faces by their sorted vertices, then by index: a counting sort by the smallest vertex,
    // then a small sort within each vertex's run.
    auto sorted_face = [&](size_t f) {
        Triangle t = m.triangles[f];
        std::sort(t.begin(), t.end());
        return t;
    };
    std::vector<uint32_t> start =
        bucket_starts(m.triangles.size(), m.positions.size(), [&](size_t f) { return sorted_face(f)[0]; });
    std::vector<std::pair<Triangle, uint32_t>> sorted(m.triangles.size());
    for (uint32_t f = 0; f < m.triangles.size(); ++f) {
        const Triangle t = sorted_face(f);
        sorted[start[t[0]]++] = {t, f};
    }
    for (size_t v = 0, b = 0; v < m.positions.size(); b = start[v++])
        if (start[v] - b > 1) std::sort(sorted.begin() + long(b), sorted.begin() + long(start[v]));
    for (size_t i = 1; i < sorted.size(); ++i)
        if (sorted[i].first == sorted[i - 1].first) copy_of[sorted[i].second] = copy_of[sorted[i - 1].second], ++r.duplicate_faces;
    std::vector<uint8_t> used(m.positions.size(), 0);
    for (const auto& t : m.triangles)
        for (uint32_t v : t) used[v] = 1;
    r.unreferenced_vertices = size_t(std::count(used.begin(), used.end(), 0));
    return copy_of;
}

// `skip`: per face, 1 for the later copies of duplicate faces (wound the other way, a copy
// would cancel the normal it duplicates); empty: none is skipped.
void compute_normals(TriangleMesh& m, ImportReport& report, double area_eps, const std::vector<uint8_t>& skip) {
    detail::angle_weighted_normals(m.positions, m.triangles, area_eps, skip, m.normals, m.normal_valid);
    report.vertices_without_normal = size_t(std::count(m.normal_valid.begin(), m.normal_valid.end(), 0));
}

} // namespace

ImportedMesh prepare_mesh(std::string name, std::vector<Eigen::Vector3d> positions, std::vector<Triangle> triangles,
                          const ImportOptions& options) {
    ImportedMesh out;
    TriangleMesh& m = out.mesh;
    ImportReport& r = out.report;
    m.name = std::move(name);
    r.file_vertices = positions.size();
    // Looked at after each step that takes time (import_mesh looks before reading the file).
    const auto stop_if_cancelled = [&] { detail::stop_if_cancelled(options.cancel, "importing", m.name); };
    if (positions.size() > size_t(INT32_MAX)) // welding numbers vertices in int32
        throw_bad_input(m.name, "more than 2^31 - 1 vertices");

    // The index counts vertices as the reader made them (an OBJ's corners in face order), which
    // need not be the file's numbering; a finite vertex's coordinates say which it is (a node's
    // transform has already turned one infinity into NaNs).
    auto bad_vertex = [&](size_t i, bool with_coordinates, const char* what) {
        std::ostringstream os;
        os << "vertex " << i << " (counting from 0 as read)";
        if (with_coordinates) os << " at (" << positions[i].x() << ", " << positions[i].y() << ", " << positions[i].z() << ")";
        os << ": " << what;
        throw_bad_input(m.name, os.str());
    };
    for (size_t i = 0; i < positions.size(); ++i) {
        if (!positions[i].allFinite()) bad_vertex(i, false, "a coordinate is not finite (NaN or infinity)");
        if (positions[i].cwiseAbs().maxCoeff() > kMaxMeshCoordinate)
            bad_vertex(i, true, "a coordinate is beyond 1e16 in magnitude");
    }
    for (size_t f = 0; f < triangles.size(); ++f)
        for (uint32_t v : triangles[f])
            if (v >= positions.size())
                throw_bad_input(m.name, "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                            " of " + std::to_string(positions.size()));
    if (triangles.empty()) throw_bad_input(m.name, "no triangles (points, lines or an empty file)");

    // Weld by position: files often split vertices at seams, and STL is unindexed.
    Eigen::Vector3d lo = positions[0], hi = positions[0];
    for (const auto& p : positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double diag = (hi - lo).norm();
    if (!(diag >= kMinMeshDiagonal))
        throw_bad_input(m.name, "the mesh is too small: its bounding-box diagonal is below 1e-15 (float cannot "
                                "hold its squared distances)");
    m.welded_index = detail::weld_positions(positions, options.weld_tolerance * diag, m.positions, options.cancel);
    stop_if_cancelled();
    r.vertices = m.positions.size();
    r.welded = r.file_vertices - r.vertices;
    if (r.welded)
        r.fixes.push_back("welded " + std::to_string(r.welded) + " duplicated vertices (closer than " +
                          std::to_string(options.weld_tolerance) + " of the diagonal)");

    // Faces that collapse to a point or a segment after welding cannot be triangles.
    const double area_eps = detail::degenerate_twice_area(diag);
    m.triangles.reserve(triangles.size());
    for (const auto& t : triangles) {
        const Triangle w{m.welded_index[t[0]], m.welded_index[t[1]], m.welded_index[t[2]]};
        if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) {
            ++r.degenerate_faces;
            continue;
        }
        const double area2 = (m.positions[w[1]] - m.positions[w[0]]).cross(m.positions[w[2]] - m.positions[w[0]]).norm();
        if (!(area2 > area_eps)) {
            ++r.degenerate_faces; // kept for topology, ignored for normals
        } else {
            // A needle: height over longest edge (area2 / longest^2) below 1e-6.
            double longest2 = 0;
            for (int k = 0; k < 3; ++k)
                longest2 = std::max(longest2, (m.positions[w[(k + 1) % 3]] - m.positions[w[k]]).squaredNorm());
            if (area2 < 1e-6 * longest2) ++r.needle_faces;
        }
        m.triangles.push_back(w);
    }
    if (m.triangles.empty()) throw_bad_input(m.name, "every face is degenerate");
    r.faces = m.triangles.size();
    stop_if_cancelled();
    std::vector<uint32_t> copy_of;  // per face: the first face with its three vertices (itself if none)

    // Topology from sorted half-edges. A later copy of a face adds no surface: it is left out,
    // or a closed body exported with its faces twice would be all non-manifold edges, open, and
    // sampled as a thin shell (35 times the samples of the box it is), with no inside.
    std::vector<HalfEdge> edges;
    // Parts: faces connected across manifold edges only. A part is closed when each edge of its
    // faces is used by exactly two of them: a closed body that a flap or fin touches along a
    // non-manifold edge stays a solid, and only the flap is open.
    DisjointFaces parts(m.triangles.size());
    size_t inconsistent = 0; // manifold edges whose two faces walk it the same way
    auto topology = [&](const std::vector<uint8_t>& skip) {
        r.boundary_edges = r.nonmanifold_edges = 0, inconsistent = 0;
        parts = DisjointFaces(m.triangles.size());
        edges = collect_edges(m.triangles, m.positions.size(), skip);
        std::vector<size_t> unpaired; // where the runs of edges used other than twice start
        for (size_t i = 0; i < edges.size();) {
            const size_t j = run_end(edges, i);
            const size_t uses = j - i;
            if (uses == 1) ++r.boundary_edges;
            if (uses >= 3) ++r.nonmanifold_edges;
            if (uses != 2) unpaired.push_back(i);
            if (uses == 2) {
                parts.join(edges[i].face, edges[i + 1].face);
                inconsistent += edges[i].forward == edges[i + 1].forward;
            }
            i = j;
        }
        // Components join faces across every shared edge: the parts, and across non-manifold
        // edges; a copy belongs to its face's.
        DisjointFaces components = parts;
        for (const size_t i : unpaired)
            for (size_t k = i + 1, j = run_end(edges, i); k < j; ++k)
                components.join(edges[k].face, edges[i].face);
        if (!skip.empty())
            for (uint32_t f = 0; f < m.triangles.size(); ++f)
                if (skip[f]) components.join(f, copy_of[f]);
        r.components = components.count();
        r.closed = r.boundary_edges == 0 && r.nonmanifold_edges == 0;
        // A part using an edge other than twice is open. An edge used twice joined its two faces
        // into one part, which uses it twice: only the other runs can open a part.
        std::vector<uint8_t> part_open(m.triangles.size(), 0); // by part root
        for (const size_t i : unpaired) {
            const size_t j = run_end(edges, i);
            for (size_t k = i; k < j; ++k) {
                const uint32_t part = parts.find(edges[k].face);
                size_t own = 0;
                for (size_t l = i; l < j; ++l) own += parts.find(edges[l].face) == part;
                if (own != 2) part_open[part] = 1;
            }
        }
        m.on_open_part.assign(m.triangles.size(), 0);
        for (uint32_t f = 0; f < m.triangles.size(); ++f) m.on_open_part[f] = part_open[parts.find(f)];
        if (!skip.empty()) // a copy lies on its face's part (copies come after the face they copy)
            for (uint32_t f = 0; f < m.triangles.size(); ++f) m.on_open_part[f] = m.on_open_part[copy_of[f]];
    };
    // The topology and the copies only read the windings, so on two threads the normals are
    // computed beside them, from the windings as they are and counting every face; again below
    // only if a face was re-wound or a copy of another (rare: the file is then fixed or reported),
    // and the topology again, without the copies, if there are any.
    const int threads = options.threads > 0 ? options.threads : detail::machine_threads();
    const bool early_normals = threads > 1;
    auto mark_copies = [&] { // m.is_copy stays empty without copies
        if (r.duplicate_faces == 0) return;
        m.is_copy.assign(m.triangles.size(), 0);
        for (uint32_t f = 0; f < m.triangles.size(); ++f) m.is_copy[f] = copy_of[f] != f;
    };
    if (early_normals) {
        detail::parallel_for(3, std::min(threads, 3), [&](size_t k, int) {
            if (k == 0) topology({}); // the longest first
            else if (k == 1) compute_normals(m, r, area_eps, {});
            else copy_of = find_duplicates(m, r);
        }, options.tasks);
        mark_copies();
        if (r.duplicate_faces > 0) topology(m.is_copy);
    } else {
        copy_of = find_duplicates(m, r);
        mark_copies();
        topology(m.is_copy);
    }
    stop_if_cancelled();

    if (options.fix_orientation && inconsistent > 0) {
        // Per face, its neighbours across manifold edges (face, same_direction): at most one an edge.
        struct Neighbours {
            std::array<std::pair<uint32_t, bool>, 3> face;
            uint8_t count = 0;
            void push_back(std::pair<uint32_t, bool> g) { face[count++] = g; }
            const std::pair<uint32_t, bool>* begin() const { return face.data(); }
            const std::pair<uint32_t, bool>* end() const { return face.data() + count; }
        };
        std::vector<Neighbours> manifold_nbrs(m.triangles.size());
        for (size_t i = 0; i < edges.size();) {
            const size_t j = run_end(edges, i);
            if (j - i == 2) {
                const bool same = edges[i].forward == edges[i + 1].forward; // same direction: inconsistent
                manifold_nbrs[edges[i].face].push_back({edges[i + 1].face, same});
                manifold_nbrs[edges[i + 1].face].push_back({edges[i].face, same});
            }
            i = j;
        }
        // Breadth-first over manifold edges: a neighbour walking the shared edge the same
        // way is wound the other way round. Keep whichever orientation flips fewer faces.
        // (Without an inconsistent edge every face keeps its winding: no walk is needed.)
        std::vector<int8_t> flip(m.triangles.size(), -1);
        size_t non_orientable = 0;
        for (uint32_t seed = 0; seed < m.triangles.size(); ++seed) {
            if (flip[seed] >= 0) continue;
            std::vector<uint32_t> patch{seed};
            flip[seed] = 0;
            std::queue<uint32_t> q;
            q.push(seed);
            while (!q.empty()) {
                const uint32_t f = q.front();
                q.pop();
                for (auto [g, same] : manifold_nbrs[f]) {
                    const int8_t want = int8_t(flip[f] ^ (same ? 1 : 0));
                    if (flip[g] < 0) {
                        flip[g] = want;
                        patch.push_back(g);
                        q.push(g);
                    } else if (flip[g] != want) {
                        ++non_orientable;
                    }
                }
            }
            const size_t flips = size_t(std::count_if(patch.begin(), patch.end(), [&](uint32_t f) { return flip[f] == 1; }));
            const bool invert = flips * 2 > patch.size();
            for (uint32_t f : patch)
                if ((flip[f] == 1) != invert) {
                    std::swap(m.triangles[f][1], m.triangles[f][2]);
                    ++r.flipped_faces;
                }
        }
        if (r.flipped_faces)
            r.fixes.push_back("re-wound " + std::to_string(r.flipped_faces) + " faces to agree with their neighbours");
        if (non_orientable)
            r.warnings.push_back("surface is not orientable (" + std::to_string(non_orientable / 2) +
                                 " edges disagree after re-winding)");
    }
    stop_if_cancelled();
    // The parts (a copy is a part of its own, with no edges: its face's part decides) and each
    // closed one's signed volume, summed once for the flat check and the orientation step. (A
    // volume is read only from windings that agree: a part left with disagreeing ones can sum to none.)
    std::vector<std::vector<uint32_t>> part_faces;
    std::vector<double> volume;
    if (options.fix_orientation || inconsistent == 0) {
        part_faces = parts.groups();
        part_faces.erase(std::remove_if(part_faces.begin(), part_faces.end(),
                                        [&](const std::vector<uint32_t>& p) { return m.copies_earlier_face(p[0]); }),
                         part_faces.end());
        volume.resize(part_faces.size());
        for (size_t c = 0; c < part_faces.size(); ++c)
            volume[c] = m.on_open_part[part_faces[c][0]] ? 0 : signed_volume(m, part_faces[c]);
        mark_flat_parts_open(m, part_faces, volume, copy_of, diag, r);
    }
    if (options.fix_orientation) {
        // A closed part faces out of the solid: positive volume, unless it is the inner wall
        // of a hollow (inside an odd number of other closed parts), which faces the cavity.
        const std::vector<int> nesting = detail::nesting_depths(m, part_faces);
        for (size_t c = 0; c < part_faces.size(); ++c) {
            const auto& comp = part_faces[c];
            if (!m.on_open_part[comp[0]] && (volume[c] < 0) != (nesting[c] % 2 == 1)) {
                for (uint32_t f : comp) std::swap(m.triangles[f][1], m.triangles[f][2]);
                ++r.inverted_components;
            }
        }
        if (r.inverted_components)
            r.fixes.push_back("turned " + std::to_string(r.inverted_components) + " inside-out closed part(s) right side out");
    }
    if (r.boundary_edges)
        r.warnings.push_back("mesh is open: " + std::to_string(r.boundary_edges) +
                             " boundary edges (inside/outside of open parts is a guess)");
    if (r.nonmanifold_edges)
        r.warnings.push_back("mesh is non-manifold: " + std::to_string(r.nonmanifold_edges) + " edges have 3 or more faces");
    if (r.degenerate_faces)
        r.warnings.push_back(std::to_string(r.degenerate_faces) +
                             " degenerate faces (zero area, or collapsed by welding and dropped) ignored for normals");
    if (r.needle_faces)
        r.warnings.push_back(std::to_string(r.needle_faces) + " needle faces (narrower than 1e-6 of their length)");
    if (r.duplicate_faces)
        r.warnings.push_back(std::to_string(r.duplicate_faces) +
                             " duplicate faces (the same three vertices as another face) left out of the topology, normals and samples");
    if (r.unreferenced_vertices)
        r.warnings.push_back(std::to_string(r.unreferenced_vertices) + " vertices are used by no face and are left out");

    stop_if_cancelled();
    if (!early_normals || r.flipped_faces > 0 || r.inverted_components > 0 || r.duplicate_faces > 0)
        compute_normals(m, r, area_eps, m.is_copy);
    // Unreferenced vertices have no normal either; they are reported above.
    if (r.vertices_without_normal > r.unreferenced_vertices)
        r.warnings.push_back(std::to_string(r.vertices_without_normal - r.unreferenced_vertices) +
                             " vertices have no computable normal and are left out of sampling");
    return out;
}

} // namespace spt
