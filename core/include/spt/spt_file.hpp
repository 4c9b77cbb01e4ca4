#pragma once
/// The .spt file: samples of one mesh and any number of named sampling trees over
/// them. Format in docs/spt-format.md.
#include "spt/sampling_tree.hpp"
#include <cstdint>
#include <string>
#include <vector>

namespace spt {

/// Identity of the mesh a document was made from.
struct MeshInfo {
    std::string name;          ///< source file name
    uint32_t vertex_count = 0; ///< welded vertex count
    uint32_t triangle_count = 0; ///< triangle count
    uint64_t hash = 0;         ///< TriangleMesh::content_hash()
    double diagonal = 0;       ///< bounding-box diagonal, model units
};

/// Everything a .spt file holds.
struct SptDocument {
    MeshInfo mesh;                   ///< the mesh the samples were taken from
    SampleSet samples;               ///< every sample, local frame (SampleSet::origin)
    std::vector<SamplingTree> trees; ///< named trees over the samples, names unique

    /// Tree by name, or nullptr.
    const SamplingTree* tree(const std::string& name) const;
    /// Problems with the document as a whole (duplicate names, invalid trees); empty if valid.
    std::string validate() const;
};

/// Newest format version this build reads and writes. encode_spt writes the oldest version
/// that holds the document (1 when the local origin is zero and no tree has a recipe, 2 with
/// a local origin, 3 with authoring recipes, 4 when a recipe step was made at a clip's pose, 5 when a
/// recipe has a lasso, brush, linked, invert, grow or shrink stroke, 6 when a tree records a build
/// from motion), so an old file saved again without edits stays byte-identical.
constexpr uint32_t kSptVersion = 6;

/// The format version encode_spt writes for `doc`.
uint32_t spt_version_for(const SptDocument& doc);

/// Serialises a document to bytes (little-endian, checksummed).
std::vector<uint8_t> encode_spt(const SptDocument& doc);
/// Parses and validates bytes; throws Error(BadInput) "path: byte N: problem".
SptDocument decode_spt(const std::vector<uint8_t>& bytes, const std::string& path = "");
/// Writes atomically (temporary file, then rename). Throws Error(CannotWrite).
void save_spt(const SptDocument& doc, const std::string& path);
/// True when the file at `path` starts as an .spt file does; false for any other file or none.
bool is_spt_file(const std::string& path);
/// Reads and validates a file. Throws Error(BadInput) naming the file and byte offset.
SptDocument load_spt(const std::string& path);

/// Checks that `mesh` is the mesh `info` describes; empty if it is, else the mismatch.
std::string check_mesh_matches(const MeshInfo& info, const TriangleMesh& mesh);

} // namespace spt
