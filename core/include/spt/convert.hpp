#pragma once
/// Mesh to sampling-tree document in one call: what `spt convert` and tools that
/// accept a mesh in place of a .spt file do.
#include "spt/spt_file.hpp"
#include "spt/tree_builder.hpp"
#include <optional>

namespace spt {

/// Options for make_document.
struct ConvertOptions {
    BuildOptions build;              ///< tree shape, radius rule, bounds
    std::optional<double> tolerance; ///< model units; adds face samples so no gap is deeper
    std::string tree_name = "default";
};

/// What make_document did beyond the document itself.
struct ConvertStats {
    size_t vertex_samples = 0;
    size_t face_samples = 0;
    int tolerance_rounds = 0;        ///< sampling rounds needed to meet the tolerance
    double worst_predicted_gap = 0;  ///< largest flat-face gap the final radii allow (tolerance mode)
    double sample_seconds = 0;
    double build_seconds = 0;
};

/// Samples `mesh` and builds one tree over the samples.
SptDocument make_document(const TriangleMesh& mesh, const ConvertOptions& options = {},
                          ConvertStats* stats = nullptr);

/// Reads a .spt file, or imports a mesh and converts it with default options.
SptDocument load_or_convert(const std::string& path, const ConvertOptions& options = {});

} // namespace spt
