// The scene as a plain Bullet world with GImpact (gimpact_world.hpp). What it shares with spt's
// world (core/src/dynamics/) is taken from there, so that only the collision detection differs:
// the solver settings (configure_solver), mass and inertia (rigid_mass), how two objects'
// friction and restitution combine (combined_setting), the sleeping thresholds.
#include "gimpact_world.hpp"
#include "dynamics/dynamics_world.hpp"
#include "dynamics/manifold_algorithm.hpp"
#include "dynamics/rigid_mass.hpp"
#include "dynamics/sampled_shape.hpp"
#include "meshgen.hpp"
#include "spt/collision_model.hpp"
#include "spt/error.hpp"
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <btBulletDynamicsCommon.h>
#include <array>
#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

namespace bench {

using spt::detail::from_bt;
using spt::detail::to_bt;

namespace gimpact {

// What the combine callbacks and the energy read of a body (its user pointer).
struct Body {
    const spt::SceneObject* object = nullptr;
    const spt::DynamicsSettings* settings = nullptr;
    size_t index = 0;
    bool moves = false;
    double mass = 0;
    Eigen::Vector3d inertia = Eigen::Vector3d::Zero(); // principal moments, body axes
    spt::Pose body_from_object;
};

const Body& body_of(const btCollisionObject* o) { return *static_cast<const Body*>(o->getUserPointer()); }

// Bullet multiplies two bodies' values; spt's rule (a pair that sets neither gets the scene's
// value exactly) is installed instead, so both worlds solve the same coefficients.
btScalar combined_friction(const btCollisionObject* a, const btCollisionObject* b) {
    const Body &x = body_of(a), &y = body_of(b);
    return btScalar(spt::detail::combined_setting(x.object->friction, y.object->friction, x.settings->friction, true));
}
btScalar combined_restitution(const btCollisionObject* a, const btCollisionObject* b) {
    const Body &x = body_of(a), &y = body_of(b);
    return btScalar(spt::detail::combined_setting(x.object->restitution, y.object->restitution, x.settings->restitution, false));
}
btScalar combined_rolling(const btCollisionObject* a, const btCollisionObject* b) {
    const Body &x = body_of(a), &y = body_of(b);
    return btScalar(spt::detail::combined_setting(x.object->rolling_friction, y.object->rolling_friction,
                                                  x.settings->rolling_friction, false));
}

// One mesh's triangles as Bullet reads them (it keeps pointers into the arrays), in the body frame.
struct Shape {
    std::vector<btScalar> vertices;
    std::vector<int> indices;
    std::unique_ptr<btTriangleIndexVertexArray> array;
    std::unique_ptr<btCollisionShape> shape;
};

// A moving object's triangles as GImpact's shape; a static one's as `gimpact` says.
std::unique_ptr<Shape> make_shape(const spt::TriangleMesh& mesh, const spt::Pose& body_from_object, bool gimpact, double margin) {
    auto s = std::make_unique<Shape>();
    for (const Eigen::Vector3d& p : mesh.positions) {
        const Eigen::Vector3d q = body_from_object.apply(p);
        s->vertices.insert(s->vertices.end(), {btScalar(q.x()), btScalar(q.y()), btScalar(q.z())});
    }
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        if (!mesh.copies_earlier_face(f)) s->indices.insert(s->indices.end(), {int(mesh.triangles[f][0]), int(mesh.triangles[f][1]), int(mesh.triangles[f][2])});
    s->array = std::make_unique<btTriangleIndexVertexArray>(int(s->indices.size() / 3), s->indices.data(), 3 * int(sizeof(int)),
                                                            int(mesh.positions.size()), s->vertices.data(),
                                                            3 * int(sizeof(btScalar)));
    if (gimpact) {
        auto g = std::make_unique<btGImpactMeshShape>(s->array.get());
        if (margin >= 0) g->setMargin(btScalar(margin)); // else its triangles keep Bullet's 0.01
        g->updateBound();
        s->shape = std::move(g);
    } else {
        s->shape = std::make_unique<btBvhTriangleMeshShape>(s->array.get(), true);
    }
    return s;
}

// Bullet's world with its collision detection (broad and narrow phase) timed.
class TimedWorld final : public btDiscreteDynamicsWorld {
public:
    using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
    int64_t ns = 0;
    void performDiscreteCollisionDetection() override {
        const auto t0 = std::chrono::steady_clock::now();
        btDiscreteDynamicsWorld::performDiscreteCollisionDetection();
        ns = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
    }
};

// A .spt-only model of the pile: the icosphere tools/scenegen made it from (make_scenes.cpp, pile()).
spt::TriangleMesh pebble_mesh(const spt::SceneObject& o) {
    const std::string stem = std::filesystem::path(o.model_path).stem().string();
    const double radius = stem == "pebble" ? 0.4 : stem == "grit" ? 0.3 : 0;
    if (radius == 0)
        throw spt::Error(spt::ErrorKind::BadInput, o.model_path + ": a .spt model without 'mesh'; only the pile's pebble.spt "
                                                                  "and grit.spt are known to this benchmark");
    spt::TriangleMesh mesh = spt::meshgen::prepare(spt::meshgen::icosphere(radius, 2), stem).mesh;
    const spt::CollisionModel check(spt::load_spt(o.model_path), mesh); // throws unless the file was made from it
    return mesh;
}

spt::TriangleMesh read_mesh(const spt::SceneObject& o) {
    if (spt::is_spt_file(o.model_path))
        return o.mesh_path.empty() ? pebble_mesh(o) : spt::import_mesh(o.mesh_path).mesh;
    spt::TriangleMesh mesh = spt::import_mesh(o.model_path).mesh;
    for (Eigen::Vector3d& p : mesh.positions) p *= o.scale; // as the scene loader scales it
    return mesh;
}

} // namespace gimpact

std::vector<std::shared_ptr<const spt::TriangleMesh>> object_meshes(const spt::Scene& scene) {
    std::map<std::tuple<std::string, std::string, double>, std::shared_ptr<const spt::TriangleMesh>> read;
    std::vector<std::shared_ptr<const spt::TriangleMesh>> out;
    for (const spt::SceneObject& o : scene.objects) {
        auto& m = read[{o.model_path, o.mesh_path, o.scale}];
        if (!m) m = std::make_shared<const spt::TriangleMesh>(gimpact::read_mesh(o));
        out.push_back(m);
    }
    return out;
}

struct GImpactWorld::Impl {
    btScalar dt = 0.01;
    btDefaultCollisionConfiguration configuration;
    std::unique_ptr<btCollisionDispatcher> dispatcher;
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    std::unique_ptr<gimpact::TimedWorld> world;
    // Keyed by mesh, body frame and kind: objects of one model share a shape.
    std::map<std::tuple<const spt::TriangleMesh*, std::array<double, 7>, bool>, std::unique_ptr<gimpact::Shape>> shapes;
    std::vector<std::unique_ptr<gimpact::Body>> infos;
    std::vector<std::unique_ptr<btRigidBody>> bodies;

    ~Impl() {
        for (auto& b : bodies) world->removeRigidBody(b.get());
        // Bullet's own rules back: the callbacks are process-wide and read our user pointers.
        gCalculateCombinedFrictionCallback = btManifoldResult::calculateCombinedFriction;
        gCalculateCombinedRestitutionCallback = btManifoldResult::calculateCombinedRestitution;
        gCalculateCombinedRollingFrictionCallback = btManifoldResult::calculateCombinedRollingFriction;
    }
};

GImpactWorld::GImpactWorld(const spt::Scene& scene, const std::vector<std::shared_ptr<const spt::TriangleMesh>>& meshes,
                           const GImpactOptions& options)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.dt = btScalar(scene.dt);
    m.dispatcher = std::make_unique<btCollisionDispatcher>(&m.configuration);
    btGImpactCollisionAlgorithm::registerAlgorithm(m.dispatcher.get());
    m.world = std::make_unique<gimpact::TimedWorld>(m.dispatcher.get(), &m.broadphase, &m.solver, &m.configuration);
    const bool gravity = scene.effects.has(spt::Effect::Gravity);
    m.world->setGravity(to_bt(gravity ? scene.gravity : Eigen::Vector3d::Zero()));
    if (options.bullet_solver) m.world->getSolverInfo().m_numIterations = scene.dynamics.iterations;
    else spt::detail::configure_solver(m.world->getSolverInfo(), scene, gravity ? scene.gravity.norm() : 0.0);
    gCalculateCombinedFrictionCallback = gimpact::combined_friction;
    gCalculateCombinedRestitutionCallback = gimpact::combined_restitution;
    gCalculateCombinedRollingFrictionCallback = gimpact::combined_rolling;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const spt::SceneObject& o = scene.objects[i];
        if (o.motion == spt::MotionKind::Path)
            throw spt::Error(spt::ErrorKind::BadInput, scene.file + ": object '" + o.name + "' follows a path; the benchmark's GImpact world takes none");
        auto info = std::make_unique<gimpact::Body>();
        info->object = &o, info->settings = &scene.dynamics, info->index = i;
        info->moves = o.motion == spt::MotionKind::Velocity;
        if (info->moves) {
            const spt::detail::RigidMass rm = spt::detail::rigid_mass(o, scene.file, i);
            info->mass = rm.mass, info->inertia = rm.principal_moments;
            info->body_from_object = rm.object_from_body.inverse();
        }
        const spt::Pose& f = info->body_from_object;
        const std::array<double, 7> frame = {f.translation.x(), f.translation.y(), f.translation.z(), f.rotation.w(),
                                             f.rotation.x(), f.rotation.y(), f.rotation.z()};
        auto& shape = m.shapes[{meshes[i].get(), frame, info->moves}];
        if (!shape) shape = gimpact::make_shape(*meshes[i], f, info->moves || options.static_gimpact, options.margin);
        const spt::Pose body_pose = o.pose * f.inverse();
        btRigidBody::btRigidBodyConstructionInfo ci(btScalar(info->mass), nullptr, shape->shape.get(), to_bt(info->inertia));
        ci.m_startWorldTransform = to_bt(body_pose);
        auto body = std::make_unique<btRigidBody>(ci);
        body->setUserPointer(info.get());
        if (info->moves) { // the scene gives its origin's velocity; Bullet's is the centre of mass's
            body->setLinearVelocity(to_bt(o.velocity + o.angular_velocity.cross(body_pose.translation - o.pose.translation)));
            body->setAngularVelocity(to_bt(o.angular_velocity));
            body->setSleepingThresholds(btScalar(0.02 * o.model->diagonal()), btScalar(0.05)); // as spt's world
        }
        m.world->addRigidBody(body.get());
        m.infos.push_back(std::move(info));
        m.bodies.push_back(std::move(body));
    }
}

GImpactWorld::~GImpactWorld() = default;

void GImpactWorld::step() { // one step of exactly dt, as spt's world: no sub-steps, no interpolation
    impl_->world->stepSimulation(impl_->dt, 0, impl_->dt);
}

spt::Pose GImpactWorld::pose(size_t i) const {
    return from_bt(impl_->bodies[i]->getWorldTransform()) * impl_->infos[i]->body_from_object;
}

Eigen::Vector3d GImpactWorld::velocity(size_t i) const {
    const btRigidBody& b = *impl_->bodies[i];
    const Eigen::Vector3d arm = pose(i).translation - from_bt(b.getWorldTransform().getOrigin());
    return from_bt(b.getLinearVelocity()) + from_bt(b.getAngularVelocity()).cross(arm);
}

double GImpactWorld::energy() const {
    double e = 0;
    for (size_t i = 0; i < impl_->bodies.size(); ++i) {
        const gimpact::Body& info = *impl_->infos[i];
        if (!info.moves) continue;
        const btRigidBody& b = *impl_->bodies[i];
        const Eigen::Vector3d w = from_bt(b.getWorldTransform()).rotation.conjugate() * from_bt(b.getAngularVelocity());
        e += 0.5 * info.mass * from_bt(b.getLinearVelocity()).squaredNorm() + 0.5 * w.dot(info.inertia.cwiseProduct(w)) -
             info.mass * from_bt(impl_->world->getGravity()).dot(from_bt(b.getWorldTransform().getOrigin()));
    }
    return e;
}

size_t GImpactWorld::touching() const {
    std::set<std::pair<size_t, size_t>> pairs; // GImpact may keep several manifolds for one pair
    for (int k = 0; k < impl_->dispatcher->getNumManifolds(); ++k) {
        const btPersistentManifold* mf = impl_->dispatcher->getManifoldByIndexInternal(k);
        if (mf->getNumContacts() == 0) continue;
        const size_t a = gimpact::body_of(mf->getBody0()).index, b = gimpact::body_of(mf->getBody1()).index;
        pairs.emplace(std::min(a, b), std::max(a, b));
    }
    return pairs.size();
}

int64_t GImpactWorld::collision_ns() const { return impl_->world->ns; }

} // namespace bench
