#pragma once
// The rig and clips of a file as assimp reads them (rig_import.cpp); import_animated_mesh adds
// to it what assimp loses of glTF files (gltf_animation.hpp).
#include "spt/animation.hpp"

namespace spt::detail {

// The morph targets of one mesh as a rig node holds it (one per assimp mesh: a glTF mesh of
// several primitives is several, each with the glTF mesh's targets).
struct MorphMesh {
    uint32_t node = 0;
    uint32_t first_target = 0, target_count = 0;
};

// Fills out.rig and out.clips from `path` as assimp 5.2.5 reads it, in the vertex order of
// out.imported (import_mesh's reading of the same file); `morphs` gets each mesh instance that
// has targets. Throws BadInput naming the file as import_animated_mesh says.
void read_assimp_rig(const std::string& path, AnimatedMesh& out, std::vector<MorphMesh>& morphs);

} // namespace spt::detail
