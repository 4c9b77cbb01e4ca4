// Bullet's world of a scene's objects (dynamics_world.hpp).
#include "dynamics/dynamics_world.hpp"
#include "dynamics/parallel_dispatcher.hpp"
#include "dynamics/rigid_mass.hpp"
#include "dynamics/sampled_shape.hpp"
#include "spt/error.hpp"
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <algorithm>
#include <chrono>
#include <sstream>

namespace spt::detail {
namespace {

using Clock = std::chrono::steady_clock;
int64_t elapsed_ns(Clock::time_point t0) {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count();
}

// `v` as a message writes it (shortest of fixed or exponent).
std::string message_number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

} // namespace

// Bullet's world with the broad phase timed apart from the rest.
class TimedWorld : public btDiscreteDynamicsWorld {
public:
    using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
    int64_t ns_broad = 0;
    void performDiscreteCollisionDetection() override {
        const auto t0 = Clock::now();
        updateAabbs();
        computeOverlappingPairs();
        ns_broad += elapsed_ns(t0);
        getDispatcher()->dispatchAllCollisionPairs(m_broadphasePairCache->getOverlappingPairCache(), getDispatchInfo(),
                                                   m_dispatcher1);
    }
};

struct DynamicsWorld::Impl {
    const Scene* scene = nullptr;
    NarrowContext context;
    std::unique_ptr<ManifoldAlgorithmCreator> creator;
    std::unique_ptr<btDefaultCollisionConfiguration> configuration;
    std::unique_ptr<ParallelDispatcher> dispatcher;
    std::unique_ptr<btDbvtBroadphase> broadphase;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver;
    std::unique_ptr<TimedWorld> world;
    std::vector<std::unique_ptr<BodyInfo>> infos;
    std::vector<std::unique_ptr<SampledShape>> shapes;
    std::vector<std::unique_ptr<btRigidBody>> bodies;
    std::vector<Eigen::Matrix3d> body_inertia; // per body, body axes (zero unless it moves)

    ~Impl() {
        if (world)
            for (auto& b : bodies) world->removeRigidBody(b.get());
    }
};

void configure_solver(btContactSolverInfo& solving, const Scene& scene, double gravity) {
    solving.m_numIterations = scene.dynamics.iterations;
    // Every overlap is pushed out by the split impulse, which moves positions and adds no
    // velocity: with restitution 0 no contact adds energy (docs/scenes.md, "Dynamics").
    solving.m_splitImpulse = 1;
    solving.m_splitImpulsePenetrationThreshold = 0;
    solving.m_erp2 = 0.8;
    solving.m_warmstartingFactor = 1;
    // A contact bounces only when it closes faster than gravity alone makes it in two steps: a
    // resting contact never does, whatever the scene's units.
    solving.m_restitutionVelocityThreshold = btScalar(2 * gravity * scene.dt);
    solving.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
}

DynamicsWorld::DynamicsWorld(const Scene& scene, bool gravity, bool keep_pairs, int threads, TaskSystem* tasks,
                             std::vector<QueryScratch>* scratch)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.scene = &scene;
    // Bullet works in float: what one step can add must stay far below float's range, or a step
    // would carry a body to infinity inside Bullet before spt could refuse it (docs/scenes.md).
    const double limit = 1e15;
    auto refuse = [&](const std::string& what) {
        throw Error(ErrorKind::BadInput, scene.file + ": " + what + ": the solver (float) takes speeds, gravity and their "
                                                                  "change in a step up to 1e15");
    };
    if (gravity && !(scene.gravity.stableNorm() <= limit && scene.gravity.stableNorm() * scene.dt <= limit))
        refuse("gravity of " + message_number(scene.gravity.stableNorm()) + " with dt " + message_number(scene.dt));
    if (!(scene.dt <= limit)) refuse("dt of " + message_number(scene.dt));
    // Bullet takes a step shorter than float's epsilon for none at all: the scene would stand still.
    if (!(scene.dt >= 1e-6))
        throw Error(ErrorKind::BadInput, scene.file + ": dt of " + message_number(scene.dt) +
                                             " s: the solver (float) takes steps from 1e-6 s; shorter ones it skips");
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        if (o.motion == MotionKind::Velocity &&
            !(o.velocity.stableNorm() * std::max(1.0, scene.dt) <= limit && o.angular_velocity.stableNorm() <= limit))
            refuse("at /objects/" + std::to_string(i) + ": object '" + o.name + "' moves too fast");
    }
    m.context.dt = scene.dt;
    m.context.gravity = gravity ? scene.gravity.stableNorm() : 0.0;
    m.context.settings = scene.dynamics;
    m.context.keep_pairs = keep_pairs;
    btDefaultCollisionConstructionInfo construction;
    construction.m_customCollisionAlgorithmMaxElementSize = int(sizeof(ManifoldAlgorithm));
    m.configuration = std::make_unique<btDefaultCollisionConfiguration>(construction);
    m.dispatcher = std::make_unique<ParallelDispatcher>(m.configuration.get(), threads, tasks, scratch);
    m.creator = std::make_unique<ManifoldAlgorithmCreator>(&m.context);
    m.dispatcher->registerCollisionCreateFunc(CUSTOM_CONCAVE_SHAPE_TYPE, CUSTOM_CONCAVE_SHAPE_TYPE, m.creator.get());
    m.broadphase = std::make_unique<btDbvtBroadphase>();
    m.solver = std::make_unique<btSequentialImpulseConstraintSolver>();
    m.world = std::make_unique<TimedWorld>(m.dispatcher.get(), m.broadphase.get(), m.solver.get(), m.configuration.get());
    m.world->setGravity(to_bt(gravity ? scene.gravity : Eigen::Vector3d::Zero()));
    configure_solver(m.world->getSolverInfo(), scene, m.context.gravity);

    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        auto info = std::make_unique<BodyInfo>();
        info->index = uint32_t(i);
        info->object = &o;
        info->size = o.model->diagonal();
        RigidMass rm;
        if (o.motion == MotionKind::Velocity) {
            rm = rigid_mass(o, scene.file, i);
            // Float's limits again: the solver's inverse masses and impulses must stay far from them.
            if (!(rm.mass >= 1e-12 && rm.mass <= 1e12) || !rm.principal_moments.allFinite())
                throw Error(ErrorKind::BadInput, scene.file + ": at /objects/" + std::to_string(i) + ": object '" + o.name +
                                                     "' has a mass of " + message_number(rm.mass) +
                                                     ": the solver (float) takes masses from 1e-12 to 1e12");
            info->moves = true;
            info->mass = rm.mass;
            info->inertia = rm.principal_moments;
            info->body_from_object = rm.object_from_body.inverse();
        }
        info->reach = o.model->reach() + info->body_from_object.translation.norm();
        auto shape = std::make_unique<SampledShape>(info.get(), 0.005 * info->size);
        const Pose body_pose = o.pose * info->body_from_object.inverse();
        btRigidBody::btRigidBodyConstructionInfo ci(btScalar(info->mass), nullptr, shape.get(), to_bt(info->inertia));
        ci.m_startWorldTransform = to_bt(body_pose);
        ci.m_friction = btScalar(o.friction >= 0 ? o.friction : scene.dynamics.friction);
        ci.m_restitution = btScalar(o.restitution >= 0 ? o.restitution : scene.dynamics.restitution);
        auto body = std::make_unique<btRigidBody>(ci);
        body->setUserPointer(info.get());
        body->setUserIndex(int(i));
        if (o.motion == MotionKind::Velocity) {
            // The scene gives the velocity of the object's origin; Bullet's is its centre of mass's.
            const Eigen::Vector3d arm = body_pose.translation - o.pose.translation;
            body->setLinearVelocity(to_bt(o.velocity + o.angular_velocity.cross(arm)));
            body->setAngularVelocity(to_bt(o.angular_velocity));
            // Asleep after 2 s slower than these (Bullet's rule); scaled to the object, not metres.
            body->setSleepingThresholds(btScalar(0.02 * info->size), btScalar(0.05));
        } else if (o.motion == MotionKind::Path) {
            body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
            body->setActivationState(DISABLE_DEACTIVATION);
        }
        m.world->addRigidBody(body.get());
        m.infos.push_back(std::move(info));
        m.shapes.push_back(std::move(shape));
        m.bodies.push_back(std::move(body));
    }
}

DynamicsWorld::~DynamicsWorld() = default;

void DynamicsWorld::step(double t1, bool depth, const std::function<void(const std::vector<CandidatePair>&)>& before_narrow,
                         StepCounters& c, std::vector<PairContact>& contacts) {
    Impl& m = *impl_;
    const auto t0 = Clock::now();
    for (size_t i = 0; i < m.bodies.size(); ++i) {
        const SceneObject& o = m.scene->objects[i];
        if (o.motion == MotionKind::Path) m.bodies[i]->setWorldTransform(to_bt(path_pose(o.path, t1)));
    }
    m.dispatcher->before = before_narrow;
    m.world->ns_broad = 0;
    // One step of exactly dt: no sub-steps, no interpolation.
    m.world->stepSimulation(btScalar(m.scene->dt), 0, btScalar(m.scene->dt));
    const int64_t total = elapsed_ns(t0);
    c.ns_broad = m.world->ns_broad;
    c.ns_narrow = m.dispatcher->ns_narrow;
    c.ns_dynamics = std::max<int64_t>(0, total - c.ns_broad - c.ns_narrow);
    c.candidate_pairs = m.dispatcher->tested().size();
    for (const ManifoldAlgorithm* a : m.dispatcher->tested()) {
        c.node_pairs += a->found().counters.node_pairs;
        c.sphere_tests += a->found().counters.sphere_tests;
    }

    // Every pair in contact, tested this step or asleep, in (a, b) order.
    std::vector<const ManifoldAlgorithm*> touching;
    btBroadphasePairArray& listed = m.world->getPairCache()->getOverlappingPairArray();
    for (int i = 0; i < listed.size(); ++i)
        if (const auto* a = static_cast<const ManifoldAlgorithm*>(listed[i].m_algorithm); a && a->manifold()->getNumContacts() > 0)
            touching.push_back(a);
    std::sort(touching.begin(), touching.end(), [](const ManifoldAlgorithm* x, const ManifoldAlgorithm* y) {
        return x->a() != y->a() ? x->a() < y->a() : x->b() < y->b();
    });
    c.colliding_pairs = touching.size();
    for (const ManifoldAlgorithm* a : touching) {
        const btPersistentManifold& mf = *a->manifold();
        const bool a_first = static_cast<const BodyInfo*>(mf.getBody0()->getUserPointer())->index == a->a();
        const btTransform& tb = (a_first ? mf.getBody1() : mf.getBody0())->getWorldTransform();
        PairContact pc;
        pc.a = a->a(), pc.b = a->b();
        for (int k = 0; k < mf.getNumContacts(); ++k) {
            const btManifoldPoint& p = mf.getContactPoint(k);
            ContactPoint cp;
            // Where the point now lies on b, after the step moved it.
            cp.point = from_bt(tb * (a_first ? p.m_localPointB : p.m_localPointA));
            cp.normal = from_bt(a_first ? -p.m_normalWorldOnB : p.m_normalWorldOnB);
            cp.depth = -double(p.m_distance1);
            cp.impulse = double(p.m_appliedImpulse);
            cp.age = p.m_lifeTime;
            pc.manifold.push_back(cp);
        }
        if (depth) {
            const auto deepest = std::max_element(pc.manifold.begin(), pc.manifold.end(),
                                                  [](const ContactPoint& x, const ContactPoint& y) { return x.depth < y.depth; });
            pc.has_depth = true;
            pc.depth = std::max(0.0, deepest->depth);
            pc.point = deepest->point + 0.5 * deepest->depth * deepest->normal;
            pc.normal = deepest->normal;
        }
        if (m.context.keep_pairs) pc.pairs = a->found().pairs;
        contacts.push_back(std::move(pc));
    }
}

Pose DynamicsWorld::pose(size_t i) const {
    return from_bt(impl_->bodies[i]->getWorldTransform()) * impl_->infos[i]->body_from_object;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> DynamicsWorld::velocity(size_t i) const {
    const btRigidBody& b = *impl_->bodies[i];
    if (!impl_->infos[i]->moves) return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    const Eigen::Vector3d w = from_bt(b.getAngularVelocity());
    const Eigen::Vector3d arm = pose(i).translation - from_bt(b.getWorldTransform().getOrigin());
    return {from_bt(b.getLinearVelocity()) + w.cross(arm), w};
}

double DynamicsWorld::mass(size_t i) const { return impl_->infos[i]->mass; }

double DynamicsWorld::energy(const Eigen::Vector3d& gravity) const {
    double e = 0;
    for (size_t i = 0; i < impl_->bodies.size(); ++i) {
        const BodyInfo& info = *impl_->infos[i];
        if (!info.moves) continue;
        const btRigidBody& b = *impl_->bodies[i];
        const Eigen::Vector3d v = from_bt(b.getLinearVelocity());
        const Eigen::Matrix3d r = from_bt(b.getWorldTransform()).rotation.toRotationMatrix();
        const Eigen::Vector3d w = r.transpose() * from_bt(b.getAngularVelocity()); // body axes
        e += 0.5 * info.mass * v.squaredNorm() + 0.5 * w.dot(info.inertia.cwiseProduct(w)) -
             info.mass * gravity.dot(from_bt(b.getWorldTransform().getOrigin()));
    }
    return e;
}

} // namespace spt::detail
