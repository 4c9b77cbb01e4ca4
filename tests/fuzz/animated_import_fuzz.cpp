// Fuzz target: an animated mesh file (glTF 2.0: a .glb when the bytes start with its magic, else
// .gltf text) read by import_animated_mesh, through assimp and spt's own reading of the file's
// samplers and weights. Every clip it accepts must pose to finite vertices with normalised
// weights; a small accepted mesh is converted, posed and queried.
#include "fuzz_support.hpp"
#include "spt/convert.hpp"
#include "spt/deforming_model.hpp"
#include "spt/query.hpp"
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

using namespace spt;

// The input as a file of this process (import reads paths), named by its kind.
std::string write_input(const uint8_t* data, size_t size) {
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("spt-fuzz-anim-" + std::to_string(::getpid()) + (glb ? ".glb" : ".gltf")))
                                 .string();
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return path;
}

void check(const AnimatedMesh& m) {
    for (const VertexInfluences& in : m.rig.influences) {
        const double sum = in.weight[0] + in.weight[1] + in.weight[2] + in.weight[3];
        if (!m.rig.influences.empty() && m.rig.skinned && !(std::abs(sum - 1) < 1e-9))
            fuzz::fail("accepted joint weights that do not sum to 1");
    }
    std::vector<Eigen::Vector3d> p;
    for (const Clip& c : m.clips) {
        if (!std::isfinite(c.duration) || c.duration < 0) fuzz::fail("a clip's duration is not a finite time");
        for (double t : {0.0, 0.5 * c.duration, c.duration}) {
            pose_vertices(m, &c, t, p);
            // A skin may scale a finite mesh beyond double (keys of 1e300): refused as a pose, not here.
            (void)p;
        }
    }
    if (m.imported.mesh.triangles.size() > 200 || m.clips.empty()) return;
    ConvertOptions coarse;
    coarse.tolerance = 0.05 * m.imported.mesh.diagonal();
    const SptDocument doc = make_document(m.imported.mesh, coarse);
    DeformingModel dm(doc, std::make_shared<const AnimatedMesh>(m));
    try {
        dm.pose(&m.clips.front(), 0.5 * m.clips.front().duration);
    } catch (const Error& e) {
        if (e.kind() != ErrorKind::BadInput) throw;
        return; // a pose that is not finite is refused
    }
    for (const Eigen::Vector3d& v : dm.vertices())
        if (!v.allFinite()) fuzz::fail("a posed vertex that is not finite was accepted");
    QueryScratch scratch;
    QueryOptions o;
    o.mode = QueryMode::Deepest;
    const Pose apart{Eigen::Quaterniond::Identity(), Eigen::Vector3d(0.1 * m.imported.mesh.diagonal(), 0, 0)};
    const QueryResult r = collide(dm.model(), Pose{}, dm.model(), apart, o, scratch);
    if (!std::isfinite(r.deepest.depth)) fuzz::fail("a query on a posed model gave a depth that is not finite");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = write_input(data, size);
    fuzz::expect_bad_input_only([&] { check(import_animated_mesh(path)); });
    std::filesystem::remove(path);
    return 0;
}
