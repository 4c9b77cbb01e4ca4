// Reading mesh files through assimp: every mesh of the scene, node transforms applied.
#include "base/cancel.hpp"
#include "mesh/cancellable_io.hpp"
#include "mesh/recentre.hpp"
#include "io/gltf_file.hpp"
#include "spt/error.hpp"
#include "spt/mesh.hpp"
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <filesystem>
#include <fstream>
#include <optional>

namespace spt {
namespace {

// Every mesh of the scene in world coordinates; `origin` (in the file's frame, before the node
// transforms) is added to every vertex in double.
void gather(const aiScene* scene, const aiNode* node, const aiMatrix4x4& parent, const Eigen::Vector3d& origin,
            std::vector<Eigen::Vector3d>& positions, std::vector<Triangle>& triangles, size_t& skipped, int depth) {
    if (depth > 1000) return; // a cyclic or absurd node graph in a corrupt file
    const aiMatrix4x4 world = parent * node->mTransformation;
    Eigen::Matrix3d linear;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) linear(r, c) = world[r][c];
    const Eigen::Vector3d shift = linear * origin;
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
        if (node->mMeshes[i] >= scene->mNumMeshes) continue;
        const aiMesh* mesh = scene->mMeshes[node->mMeshes[i]];
        const uint32_t base = uint32_t(positions.size());
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
            const aiVector3D p = world * mesh->mVertices[v];
            positions.emplace_back(Eigen::Vector3d(p.x, p.y, p.z) + shift);
        }
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) {
                ++skipped;
                continue;
            }
            bool ok = true;
            for (int k = 0; k < 3; ++k) ok = ok && face.mIndices[k] < mesh->mNumVertices;
            if (!ok) {
                ++skipped;
                continue;
            }
            triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
        }
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c)
        gather(scene, node->mChildren[c], world, origin, positions, triangles, skipped, depth + 1);
}

// What assimp read: positions (world, double) and triangles.
struct RawMesh {
    std::vector<Eigen::Vector3d> positions;
    std::vector<Triangle> triangles;
    size_t skipped = 0;
};

// Reads `path` through assimp; with `recentred`, from its bytes, adding back its origin.
RawMesh read_raw(const std::string& path, const ImportOptions& options, std::optional<detail::RecentredFile> recentred) {
    detail::stop_if_cancelled(options.cancel, "importing", path);
    Assimp::Importer importer;
    const Eigen::Vector3d origin = recentred ? recentred->origin : Eigen::Vector3d::Zero();
    if (options.cancel || recentred) {
        auto* io = new detail::CancellableIOSystem(options.cancel);
        if (recentred) io->serve(path, std::move(recentred->bytes));
        importer.SetIOHandler(io); // the importer owns it
    }
    // No vertex joining here: assimp keeps seams split by normals, so we weld by position ourselves.
    // No aiProcess_FindInvalidData: it drops a mesh with one NaN position ("No meshes remaining"),
    // where prepare_mesh names the vertex; the normals and UVs it mends are not read.
    const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_ValidateDataStructure);
    // A cancelled read looks like a truncated file to the loader: the flag says which it was.
    detail::stop_if_cancelled(options.cancel, "importing", path);
    if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode) {
        std::string why = importer.GetErrorString();
        throw_bad_input(path, "cannot be read as a mesh: " + (why.empty() ? std::string("unknown format") : why));
    }
    RawMesh raw;
    size_t vertex_count = 0, face_count = 0; // every mesh once, as if each node held it once
    for (unsigned i = 0; i < scene->mNumMeshes; ++i)
        vertex_count += scene->mMeshes[i]->mNumVertices, face_count += scene->mMeshes[i]->mNumFaces;
    raw.positions.reserve(vertex_count), raw.triangles.reserve(face_count);
    gather(scene, scene->mRootNode, aiMatrix4x4(), origin, raw.positions, raw.triangles, raw.skipped, 0);
    return raw;
}

} // namespace

ImportedMesh import_mesh(const std::string& path, const ImportOptions& options) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw_bad_input(path, "no such file");
    if (std::filesystem::is_directory(path, ec)) throw_bad_input(path, "is a directory, not a mesh file");
    if (!std::ifstream(path).good()) throw_bad_input(path, "cannot be opened for reading");
    if (std::filesystem::file_size(path, ec) == 0) throw_bad_input(path, "is empty");

    detail::check_gltf_references(path); // assimp follows some of a glTF's indices unchecked
    RawMesh raw = read_raw(path, options, std::nullopt);
    // Far from the origin assimp's floats lose the mesh's detail: read again from the file's own
    // digits made relative (OBJ, PLY), when the file carries them.
    if (!raw.positions.empty()) {
        Eigen::Vector3d lo = raw.positions[0], hi = raw.positions[0];
        for (const Eigen::Vector3d& p : raw.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
        if (detail::far_for_float(lo, hi))
            if (std::optional<detail::RecentredFile> r = detail::recentre_positions(path, options.cancel)) {
                try {
                    raw = read_raw(path, options, std::move(r));
                } catch (const Error&) {
                    // Read once already: the rewritten bytes failing is ours, not the file's. Keep float.
                }
            }
    }
    std::vector<Eigen::Vector3d>& positions = raw.positions;
    std::vector<Triangle>& triangles = raw.triangles;
    const size_t skipped = raw.skipped;
    if (triangles.empty()) throw_bad_input(path, "contains no triangles");
    ImportedMesh out = prepare_mesh(path, std::move(positions), std::move(triangles), options);
    out.mesh.name = std::filesystem::path(path).filename().string();
    out.report.skipped_primitives = skipped;
    if (skipped) out.report.warnings.push_back(std::to_string(skipped) + " point or line primitives skipped");
    return out;
}

} // namespace spt
