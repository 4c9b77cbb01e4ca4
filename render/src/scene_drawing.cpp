// A simulated scene as a Frame: objects at their poses and the scene overlays.
#include "spt/render/scene_drawing.hpp"
#include "spt/mesh.hpp"
#include "spt/spt_file.hpp"
#include "spt/render/renderer.hpp"
#include <map>

namespace spt::render {
namespace {

Eigen::Affine3f affine(const Pose& p) {
    Eigen::Affine3f a = Eigen::Affine3f::Identity();
    a.linear() = p.rotation.cast<float>().toRotationMatrix();
    a.translation() = p.translation.cast<float>();
    return a;
}

// Distinct colours for the objects, in order.
Color object_color(size_t i) {
    static const Color palette[] = {{0.72f, 0.74f, 0.78f, 1}, {0.85f, 0.55f, 0.35f, 1}, {0.45f, 0.68f, 0.85f, 1},
                                    {0.6f, 0.8f, 0.5f, 1},    {0.85f, 0.75f, 0.4f, 1},  {0.7f, 0.55f, 0.8f, 1}};
    return palette[i % 6];
}

// A model's spheres in its local frame (drawn with local_frame(origin, pose)).
std::vector<SphereInstance> spheres_of(const CollisionModel& m, const Color& color) {
    std::vector<SphereInstance> out;
    const CompactTree& t = m.tree();
    for (const CompactNode& n : t.nodes())
        for (uint32_t k = n.first; n.count && k < n.first + n.count; ++k)
            out.push_back({{t.sphere_center(n, k), n.ss_radius}, color});
    return out;
}

constexpr Color kBoundsColor{0.1f, 0.45f, 0.95f, 1};
constexpr Color kBroadColor{0.95f, 0.55f, 0.05f, 1};
// Manifold points: saturated cyan and magenta, unlike every object colour and the yellow contacts.
constexpr Color kNewPointColor{0.0f, 0.85f, 0.9f, 1};
constexpr Color kKeptPointColor{0.9f, 0.1f, 0.65f, 1};

} // namespace

bool* scene_overlay_flag(SceneOverlays& o, std::string_view name) {
    const std::pair<std::string_view, bool*> flags[] = {{"contacts", &o.contacts}, {"normals", &o.normals},
                                                        {"manifold", &o.manifold}, {"pairs", &o.pairs},
                                                        {"ghost", &o.ghost},       {"trails", &o.trails},
                                                        {"spheres", &o.spheres},   {"bounds", &o.bounds},
                                                        {"broad", &o.broad}};
    for (const auto& [n, flag] : flags)
        if (n == name) return flag;
    return nullptr;
}

EffectSet effects_for_overlays(EffectSet e, const SceneOverlays& o) {
    if (o.contacts || o.normals) e.add(Effect::Contacts), e.add(Effect::Depth);
    if (o.pairs) e.add(Effect::Contacts), e.add(Effect::Pairs);
    return e;
}

std::string scene_overlays_problem(EffectSet effects, const SceneOverlays& o) {
    if (!o.manifold || effects.has(Effect::Dynamics)) return {};
    const std::string names = effects.names();
    return "overlay 'manifold' draws the contact manifolds of effect 'dynamics', which this scene does not run "
           "(its effects: " + (names.empty() ? std::string("none") : names) + ")";
}

Color manifold_point_color(int age) { return age == 0 ? kNewPointColor : kKeptPointColor; }

SceneDrawing::SceneDrawing(Renderer& renderer, const Scene& scene) : scene_(scene) {
    std::map<std::pair<const CollisionModel*, bool>, std::pair<MeshHandle, SphereSetHandle>> done;
    deforming_.resize(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        const bool first = i == 0; // the first object (often the floor) keeps the neutral colour
        const Color color = object_color(first ? 0 : 1 + i % 5);
        if (o.animated && o.animated_mesh && o.document) { // its own uploads: it deforms alone
            deforming_[i] = std::make_unique<DeformingModel>(*o.document, o.animated_mesh, o.tree, false);
            mesh_.push_back(renderer.add_mesh(o.animated_mesh->imported.mesh, deforming_[i]->model().origin()));
            set_.push_back(renderer.add_spheres(spheres_of(deforming_[i]->model(), color)));
            continue;
        }
        auto key = std::make_pair(o.model.get(), first);
        auto it = done.find(key);
        if (it == done.end()) {
            MeshHandle mesh;
            const bool spt = is_spt_file(o.model_path);
            if (!spt || !o.mesh_path.empty()) {
                TriangleMesh m = import_mesh(spt ? o.mesh_path : o.model_path).mesh;
                for (Eigen::Vector3d& p : m.positions) p *= o.scale;
                mesh = renderer.add_mesh(m, o.model->origin()); // drawn in the model's local frame, as its spheres
            }
            const SphereSetHandle set = renderer.add_spheres(spheres_of(*o.model, color));
            it = done.emplace(key, std::make_pair(mesh, set)).first;
        }
        mesh_.push_back(it->second.first);
        set_.push_back(it->second.second);
    }
}

SceneDrawing::~SceneDrawing() = default;

const CollisionModel& SceneDrawing::model_of(size_t i) const {
    return deforming_[i] ? deforming_[i]->model() : *scene_.objects[i].model;
}

void SceneDrawing::show_time(Renderer& renderer, double time, bool deform) {
    for (size_t i = 0; i < deforming_.size(); ++i) {
        if (!deforming_[i]) continue;
        const SceneObject& o = scene_.objects[i];
        const Clip& clip = o.animated_mesh->clips[o.clip];
        const AnimationSettings& a = o.animation;
        if (deform) deforming_[i]->pose(&clip, clip_time(clip, time, a.speed, a.offset, a.loop));
        else deforming_[i]->pose(nullptr, 0);
        const DeformingModel& d = *deforming_[i];
        renderer.update_mesh(mesh_[i], d.vertices(), d.vertex_normals(), d.model().origin());
        renderer.update_spheres(set_[i], spheres_of(d.model(), object_color(i == 0 ? 0 : 1 + i % 5)));
    }
}

Bounds SceneDrawing::initial_bounds(const Renderer& renderer) const {
    std::vector<Pose> initial;
    for (const SceneObject& so : scene_.objects) initial.push_back(so.pose);
    Bounds b = renderer.bounds(frame(initial, nullptr, {}, {}, {}, {}));
    if (b.empty()) b.add(Eigen::Vector3f::Zero());
    return b;
}

void SceneDrawing::release(Renderer& renderer) {
    for (MeshHandle m : mesh_) renderer.remove_mesh(m);
    for (SphereSetHandle s : set_) renderer.remove_spheres(s);
    mesh_.clear(), set_.clear();
}

Frame SceneDrawing::frame(const std::vector<Pose>& poses, const StepResult* step, const std::vector<Pose>& ghost,
                          const std::vector<std::vector<Eigen::Vector3f>>& trails,
                          const std::vector<BroadSphere>& broad, const SceneOverlays& o) const {
    Frame f;
    for (size_t i = 0; i < poses.size(); ++i) {
        if (mesh_[i].id && !o.spheres) {
            MeshItem item;
            item.mesh = mesh_[i];
            item.pose = local_frame(model_of(i).origin(), affine(poses[i]));
            item.style.color = object_color(i == 0 ? 0 : 1 + i % 5);
            f.meshes.push_back(item);
        } else {
            SphereItem s;
            s.spheres = set_[i];
            s.pose = local_frame(model_of(i).origin(), affine(poses[i]));
            f.spheres.push_back(s);
        }
        if (o.ghost && i < ghost.size() && ghost[i].translation != poses[i].translation) {
            if (mesh_[i].id) {
                MeshItem g;
                g.mesh = mesh_[i];
                g.pose = local_frame(model_of(i).origin(), affine(ghost[i]));
                g.style.opacity = 0.3f;
                f.meshes.push_back(g);
            } else {
                f.wire_spheres.push_back({{ghost[i].apply(scene_.objects[i].bound_center).cast<float>(),
                                           float(scene_.objects[i].bound_radius)}});
            }
        }
        if (o.trails && i < trails.size() && trails[i].size() > 1) f.trails.push_back({trails[i], {}});
        if (o.bounds)
            f.wire_spheres.push_back({{poses[i].apply(scene_.objects[i].bound_center).cast<float>(),
                                       float(scene_.objects[i].bound_radius)},
                                      kBoundsColor});
        if (o.broad && i < broad.size())
            f.wire_spheres.push_back({{broad[i].center.cast<float>(), float(broad[i].radius)}, kBroadColor});
    }
    if (step) {
        for (const PairContact& c : step->contacts) {
            if ((o.contacts || o.normals) && c.has_depth) {
                SpherePair p; // zero spheres: the contact and its normal only
                p.a.center = p.b.center = p.contact = c.point.cast<float>();
                p.normal = c.normal.cast<float>();
                p.depth = float(c.depth);
                f.collision.pairs.push_back(p);
            }
            if (o.manifold)
                for (const ContactPoint& m : c.manifold)
                    f.collision.marks.push_back({m.point.cast<float>(), m.normal.cast<float>(), manifold_point_color(m.age)});
            if (o.pairs) {
                const CollisionModel &ma = model_of(c.a), &mb = model_of(c.b);
                for (const spt::SpherePair& sp : c.pairs) {
                    const CompactNode &na = ma.tree().nodes()[sp.node_a], &nb = mb.tree().nodes()[sp.node_b];
                    SpherePair p;
                    p.a = {poses[c.a].apply(ma.origin() + ma.tree().sphere_center(na, sp.a).cast<double>()).cast<float>(),
                           na.ss_radius};
                    p.b = {poses[c.b].apply(mb.origin() + mb.tree().sphere_center(nb, sp.b).cast<double>()).cast<float>(),
                           nb.ss_radius};
                    const Eigen::Vector3f d = p.b.center - p.a.center;
                    p.normal = d.norm() > 0 ? Eigen::Vector3f(d.normalized()) : Eigen::Vector3f::UnitY();
                    p.contact = p.a.center + p.normal * (p.a.radius - 0.5f * sp.depth);
                    p.depth = sp.depth;
                    f.collision.pairs.push_back(p);
                }
            }
        }
        if (!o.contacts) f.collision.contact_size = 0.001f;
        if (!o.normals) f.collision.normal_color.a = 0;
    }
    return f;
}

} // namespace spt::render
