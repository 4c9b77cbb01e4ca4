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
    std::string path, tree, mesh;
    int64_t mtime = 0;
    uintmax_t size = 0;
    double scale = 1;
    bool animated = false; // read with its rig and clips, the document kept
    bool operator<(const CacheKey& o) const {
        return std::tie(path, tree, mesh, mtime, size, scale, animated) <
               std::tie(o.path, o.tree, o.mesh, o.mtime, o.size, o.scale, o.animated);
    }
};

struct Cached {
    std::shared_ptr<const CollisionModel> model;
    Eigen::Vector3d center;
    double radius = 0;
    std::shared_ptr<const AnimatedMesh> animated; // animated objects: the mesh, rig and clips
    std::shared_ptr<const SptDocument> document;  // animated objects: what their DeformingModel binds
    std::shared_ptr<const SolidMass> solid;       // a closed mesh's mass properties
};

// The mass properties of a closed mesh (null for an open one, or one that encloses no volume).
std::shared_ptr<const SolidMass> solid_of(const ImportedMesh& im) {
    if (!im.report.closed) return nullptr;
    try {
        return std::make_shared<const SolidMass>(mass_properties(im.mesh));
    } catch (const Error&) {
        return nullptr;
    }
}

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

// The mesh at `path`, with its rig and clips when the object is animated.
std::shared_ptr<AnimatedMesh> read_mesh(const SceneObject& o, const std::string& path, const std::atomic<bool>* cancel) {
    ImportOptions reading;
    reading.cancel = cancel;
    auto mesh = std::make_shared<AnimatedMesh>();
    if (o.animated) *mesh = import_animated_mesh(path, reading);
    else mesh->imported = import_mesh(path, reading);
    return mesh;
}

Cached load_one(const SceneObject& o, const std::string& where, const std::atomic<bool>* cancel) {
    if (is_spt_file(o.model_path)) {
        if (o.animated && o.mesh_path.empty())
            throw Error(ErrorKind::BadInput, where + ": an animated object needs its mesh file (glTF, FBX, ...): a .spt file "
                                                     "holds no skin or clips; give it as 'mesh' beside the .spt model");
        if (o.scale != 1)
            throw Error(ErrorKind::BadInput,
                        where + ": 'scale' applies to meshes; a .spt file is used at the scale it was made");
        auto doc = std::make_shared<SptDocument>(load_spt(o.model_path));
        if (!o.tree.empty() && !doc->tree(o.tree))
            throw Error(ErrorKind::BadInput, where + ": " + o.model_path + " has no tree named '" + o.tree + "'");
        Cached c;
        if (o.mesh_path.empty()) {
            auto model = std::make_shared<CollisionModel>(*doc, o.tree);
            bound(*model, nullptr, c);
            c.model = std::move(model);
            return c;
        }
        // The mesh it was made from: the exact level's triangles, an animated object's skin and clips.
        std::shared_ptr<AnimatedMesh> animated = read_mesh(o, o.mesh_path, cancel);
        auto model = std::make_shared<CollisionModel>(*doc, animated->imported.mesh, o.tree); // refuses another mesh
        bound(*model, &animated->imported.mesh, c);
        c.model = std::move(model);
        c.solid = solid_of(animated->imported);
        if (o.animated) c.animated = std::move(animated), c.document = std::move(doc);
        return c;
    }
    std::shared_ptr<AnimatedMesh> animated = read_mesh(o, o.model_path, cancel);
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
    c.solid = solid_of(im);
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
        if (!o.mesh_path.empty() && !fs::is_regular_file(o.mesh_path, ec))
            throw Error(ErrorKind::BadInput, scene.file + ": at /objects/" + std::to_string(i) + "/mesh: mesh file '" +
                                                 o.mesh_path + "' not found");
        if (!o.mesh_path.empty() && !is_spt_file(o.model_path))
            throw Error(ErrorKind::BadInput, scene.file + ": at /objects/" + std::to_string(i) +
                                                 "/mesh: 'mesh' goes with a .spt model (the model is the mesh already)");
        CacheKey key{fs::weakly_canonical(o.model_path, ec).string(), o.tree,
                     o.mesh_path.empty() ? std::string() : fs::weakly_canonical(o.mesh_path, ec).string(), 0,
                     fs::file_size(o.model_path, ec), o.scale, o.animated};
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
                                                     "triangles, and a .spt file holds none: give the mesh as the model, or as 'mesh' beside it");
        o.model = c.model;
        o.solid = c.solid;
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

void set_object_model(SceneObject& o, std::shared_ptr<const SptDocument> doc, const std::string& tree,
                      std::shared_ptr<const AnimatedMesh> mesh) {
    const std::string where = "object '" + o.name + "'";
    if (!doc) throw Error(ErrorKind::BadInput, where + ": no document given");
    if (!tree.empty() && !doc->tree(tree))
        throw Error(ErrorKind::BadInput, where + ": the document has no tree named '" + tree + "'");
    if (doc->trees.empty()) throw Error(ErrorKind::BadInput, where + ": the document has no tree");
    const std::string name = tree.empty() ? doc->trees.front().name() : tree;
    if (!mesh && o.animated) mesh = o.animated_mesh;
    std::shared_ptr<CollisionModel> model;
    try {
        model = mesh ? std::make_shared<CollisionModel>(*doc, mesh->imported.mesh, name)
                     : std::make_shared<CollisionModel>(*doc, name);
    } catch (const Error& e) {
        throw Error(ErrorKind::BadInput, where + ": " + e.what());
    }
    Cached c;
    bound(*model, mesh ? &mesh->imported.mesh : nullptr, c);
    o.model = std::move(model);
    o.tree = name;
    o.bound_center = c.center;
    o.bound_radius = c.radius;
    if (o.animated && mesh) {
        try {
            o.clip = mesh->find_clip(o.animation.clip);
        } catch (const Error& e) {
            throw Error(ErrorKind::BadInput, where + ": " + e.what());
        }
        o.animated_mesh = std::move(mesh);
        o.document = std::move(doc);
    }
}

} // namespace spt
