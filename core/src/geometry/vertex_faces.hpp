#pragma once
// The faces around each vertex of a triangle list, as one array with an offset per vertex.
#include "spt/mesh.hpp"
#include <cstdint>
#include <vector>

namespace spt::detail {

/// Faces around vertex v: faces[start[v], start[v + 1]), in increasing face order.
struct VertexFaces {
    std::vector<uint32_t> start; ///< vertices + 1 offsets into faces
    std::vector<uint32_t> faces; ///< face indices
};

/// The faces f of `triangles` with keep(f) true, around each of `vertices` vertices (counted,
/// then filled).
template <class Keep>
VertexFaces vertex_faces(size_t vertices, const std::vector<Triangle>& triangles, Keep&& keep) {
    VertexFaces out;
    out.start.assign(vertices + 1, 0);
    for (uint32_t f = 0; f < triangles.size(); ++f)
        if (keep(f))
            for (uint32_t v : triangles[f]) ++out.start[v + 1];
    for (size_t v = 0; v < vertices; ++v) out.start[v + 1] += out.start[v];
    out.faces.resize(out.start[vertices]);
    std::vector<uint32_t> fill(out.start.begin(), out.start.end() - 1);
    for (uint32_t f = 0; f < triangles.size(); ++f)
        if (keep(f))
            for (uint32_t v : triangles[f]) out.faces[fill[v]++] = f;
    return out;
}

/// Every face around each vertex.
inline VertexFaces vertex_faces(size_t vertices, const std::vector<Triangle>& triangles) {
    return vertex_faces(vertices, triangles, [](uint32_t) { return true; });
}

} // namespace spt::detail
