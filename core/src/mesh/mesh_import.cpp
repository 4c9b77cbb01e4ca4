// Reading mesh files through assimp: every mesh of the scene, node transforms applied.
#include "base/cancel.hpp"
#include "mesh/cancellable_io.hpp"
#include "spt/error.hpp"
#include "spt/mesh.hpp"
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <filesystem>
#include <fstream>

namespace spt {
namespace {

void gather(const aiScene* scene, const aiNode* node, const aiMatrix4x4& parent, std::vector<Eigen::Vector3d>& positions,
            std::vector<Triangle>& triangles, size_t& skipped, int depth) {
    if (depth > 1000) return; // a cyclic or absurd node graph in a corrupt file
    const aiMatrix4x4 world = parent * node->mTransformation;
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
        if (node->mMeshes[i] >= scene->mNumMeshes) continue;
        const aiMesh* mesh = scene->mMeshes[node->mMeshes[i]];
        const uint32_t base = uint32_t(positions.size());
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
            const aiVector3D p = world * mesh->mVertices[v];
            positions.emplace_back(p.x, p.y, p.z);
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
        gather(scene, node->mChildren[c], world, positions, triangles, skipped, depth + 1);
}

} // namespace

ImportedMesh import_mesh(const std::string& path, const ImportOptions& options) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw_bad_input(path, "no such file");
    if (std::filesystem::is_directory(path, ec)) throw_bad_input(path, "is a directory, not a mesh file");
    if (!std::ifstream(path).good()) throw_bad_input(path, "cannot be opened for reading");
    if (std::filesystem::file_size(path, ec) == 0) throw_bad_input(path, "is empty");

    detail::stop_if_cancelled(options.cancel, "importing", path);
    Assimp::Importer importer;
    if (options.cancel) importer.SetIOHandler(new detail::CancellableIOSystem(*options.cancel)); // the importer owns it
    // No vertex joining here: assimp keeps seams split by normals, so we weld by position ourselves.
    const aiScene* scene = importer.ReadFile(
        path, aiProcess_Triangulate | aiProcess_ValidateDataStructure | aiProcess_FindInvalidData);
    // A cancelled read looks like a truncated file to the loader: the flag says which it was.
    detail::stop_if_cancelled(options.cancel, "importing", path);
    if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode) {
        std::string why = importer.GetErrorString();
        throw_bad_input(path, "cannot be read as a mesh: " + (why.empty() ? std::string("unknown format") : why));
    }
    std::vector<Eigen::Vector3d> positions;
    std::vector<Triangle> triangles;
    size_t vertex_count = 0, face_count = 0; // every mesh once, as if each node held it once
    for (unsigned i = 0; i < scene->mNumMeshes; ++i)
        vertex_count += scene->mMeshes[i]->mNumVertices, face_count += scene->mMeshes[i]->mNumFaces;
    positions.reserve(vertex_count), triangles.reserve(face_count);
    size_t skipped = 0;
    gather(scene, scene->mRootNode, aiMatrix4x4(), positions, triangles, skipped, 0);
    if (triangles.empty()) throw_bad_input(path, "contains no triangles");
    ImportedMesh out = prepare_mesh(path, std::move(positions), std::move(triangles), options);
    out.mesh.name = std::filesystem::path(path).filename().string();
    out.report.skipped_primitives = skipped;
    if (skipped) out.report.warnings.push_back(std::to_string(skipped) + " point or line primitives skipped");
    return out;
}

} // namespace spt
