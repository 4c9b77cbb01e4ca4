// Loads the collision models of a scene (meshes converted with default options), cached
// process-wide by file, modification time, size, scale and tree.
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "spt/scene.hpp"
#include <algorithm>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>
#include <tuple>

namespace spt {
namespace {

namespace fs = std::filesystem;

struct CacheKey {
    std::string path, tree;
    int64_t mtime = 0;
    uintmax_t size = 0;
    double scale = 1;
    bool animated = false; // read with its rig and clips, the document kept
    bool operator<(const CacheKey& o) const {
        return std::tie(path, tree, mtime, size, scale, animated) <
               std::tie(o.path, o.tree, o.mtime, o.size, o.scale, o.animated);
    }
};

struct Cached {
    std::shared_ptr<const CollisionModel> model;
    Eigen::Vector3d center;
    double radius = 0;
    std::shared_ptr<const AnimatedMesh> animated; // animated objects: the mesh, rig and clips
    std::shared_ptr<const SptDocument> document;  // animated objects: what their DeformingModel binds
};

std::mutex cache_mutex;
std::map<CacheKey, Cached> cache;

// A sphere around the model's root bounding-sphere centre holding every sampling sphere
// and every mesh vertex, so it bounds whatever any query level can report.
void bound(const CollisionModel& m, const TriangleMesh* mesh, Cached& c) {
    const CompactTree& t = m.tree();
    c.center = m.origin();
    if (!t.nodes().empty())
        c.center += Eigen::Vector3d(t.nodes()[0].center[0], t.nodes()[0].center[1], t.nodes()[0].center[2]);
    double r = 0;
    for (const CompactNode& n : t.nodes()) {
        if (n.count == 0) continue;
        for (uint32_t k = n.first; k < n.first + n.count; ++k)
            r = std::max(r, (t.sphere_center(n, k).cast<double>() + m.origin() - c.center).norm() + n.ss_radius);
    }
    if (mesh)
        for (const Eigen::Vector3d& v : mesh->positions) r = std::max(r, (v - c.center).norm());
    // Float storage of the layout: a relative margin keeps the sphere conservative.
    c.radius = r * (1 + 1e-6) + 1e-6 * c.center.norm();
}

Cached load_one(const SceneObject& o, const std::string& where, const std::atomic<bool>* cancel) {
    if (o.animated && is_spt_file(o.model_path))
        throw Error(ErrorKind::BadInput, where + ": an animated object needs its mesh file (glTF, FBX, ...): a .spt file "
                                                 "holds no skin or clips");
    if (is_spt_file(o.model_path)) {
        if (o.scale != 1)
            throw Error(ErrorKind::BadInput,
                        where + ": 'scale' applies to meshes; a .spt file is used at the scale it was made");
        const SptDocument doc = load_spt(o.model_path);
        if (!o.tree.empty() && !doc.tree(o.tree))
            throw Error(ErrorKind::BadInput, where + ": " + o.model_path + " has no tree named '" + o.tree + "'");
        Cached c;
        auto model = std::make_shared<CollisionModel>(doc, o.tree);
        bound(*model, nullptr, c);
        c.model = std::move(model);
        return c;
    }
    ImportOptions reading;
    reading.cancel = cancel;
    auto animated = std::make_shared<AnimatedMesh>();
    if (o.animated) *animated = import_animated_mesh(o.model_path, reading);
    else animated->imported = import_mesh(o.model_path, reading);
    ImportedMesh& im = animated->imported;
    for (Eigen::Vector3d& p : im.mesh.positions) p *= o.scale;
    animated->rig.scale = o.scale;
    // Import checked the mesh's size as read; scaled, it must still fit what import accepts.
    double far = 0;
    for (const Eigen::Vector3d& p : im.mesh.positions) far = std::max(far, p.cwiseAbs().maxCoeff());
    const double diagonal = im.mesh.diagonal();
    if (!(far <= kMaxMeshCoordinate) || !(diagonal >= kMinMeshDiagonal)) {
        std::ostringstream why;
        why << where << ": 'scale' " << o.scale << " makes " << o.model_path << " "
            << (far <= kMaxMeshCoordinate ? "smaller than 1e-15 across" : "reach beyond 1e16 from the origin")
            << " (its diagonal would be " << diagonal << ")";
        throw Error(ErrorKind::BadInput, why.str());
    }
    ConvertOptions converting;
    converting.cancel = cancel;
    const SptDocument doc = make_document(im.mesh, converting);
    if (!o.tree.empty() && !doc.tree(o.tree))
        throw Error(ErrorKind::BadInput, where + ": a mesh converted with default options has one tree, 'default', not '" +
                                             o.tree + "'");
    Cached c;
    auto model = std::make_shared<CollisionModel>(doc, im.mesh, o.tree);
    bound(*model, &im.mesh, c);
    c.model = std::move(model);
    if (o.animated) {
        c.animated = std::move(animated);
        c.document = std::make_shared<const SptDocument>(doc);
    }
    return c;
}

} // namespace

void load_models(Scene& scene, const std::atomic<bool>* cancel) {
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        SceneObject& o = scene.objects[i];
        const std::string where = scene.file + ": at /objects/" + std::to_string(i) + "/model";
        std::error_code ec;
        if (!fs::is_regular_file(o.model_path, ec))
            throw Error(ErrorKind::BadInput, where + ": model file '" + o.model_path + "' not found");
        CacheKey key{fs::weakly_canonical(o.model_path, ec).string(), o.tree, 0, fs::file_size(o.model_path, ec), o.scale,
                     o.animated};
        key.mtime = int64_t(fs::last_write_time(o.model_path, ec).time_since_epoch().count());
        Cached c;
        {
            std::lock_guard<std::mutex> lock(cache_mutex);
            auto it = cache.find(key);
            if (it != cache.end()) c = it->second;
        }
        if (!c.model) {
            try {
                c = load_one(o, where, cancel);
            } catch (const Error& e) {
                const std::string msg = e.what();
                if (msg.rfind(where, 0) == 0) throw;
                throw Error(e.kind() == ErrorKind::Usage ? ErrorKind::BadInput : e.kind(), where + ": " + msg);
            }
            std::lock_guard<std::mutex> lock(cache_mutex);
            cache.emplace(key, c);
        }
        const bool exact = scene.effects.has(Effect::Exact) || scene.level == QueryLevel::Exact;
        if (exact && !c.model->has_mesh())
            throw Error(ErrorKind::BadInput, where + ": the exact level (effect 'exact' or level 'exact') tests "
                                                     "triangles, and a .spt file holds none: give the mesh as the model");
        o.model = c.model;
        o.bound_center = c.center;
        o.bound_radius = c.radius;
        if (o.animated) {
            o.animated_mesh = c.animated;
            o.document = c.document;
            try {
                o.clip = c.animated->find_clip(o.animation.clip);
            } catch (const Error& e) {
                throw Error(ErrorKind::BadInput, scene.file + ": at /objects/" + std::to_string(i) + "/animation/clip: " + e.what());
            }
        }
    }
}

} // namespace spt
