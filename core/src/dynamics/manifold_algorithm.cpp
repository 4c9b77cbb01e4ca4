// spt's contact manifolds in Bullet's persistent manifolds (manifold_algorithm.hpp).
#include "dynamics/manifold_algorithm.hpp"
#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <algorithm>
#include <array>
#include <new>

namespace spt::detail {
namespace {

const BodyInfo& info_of(const btCollisionObject* o) { return *static_cast<const BodyInfo*>(o->getUserPointer()); }

Pose object_pose(const btCollisionObject* o) { return from_bt(o->getWorldTransform()) * info_of(o).body_from_object; }

// Linear velocity of the body's point at world position p, and its angular velocity.
Eigen::Vector3d velocity_at(const btCollisionObject* o, const Eigen::Vector3d& p) {
    const btRigidBody* body = btRigidBody::upcast(o);
    if (!body) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d x = from_bt(o->getWorldTransform().getOrigin());
    return from_bt(body->getLinearVelocity()) + from_bt(body->getAngularVelocity()).cross(p - x);
}

Eigen::Vector3d linear_velocity(const btCollisionObject* o) {
    const btRigidBody* body = btRigidBody::upcast(o);
    return body ? from_bt(body->getLinearVelocity()) : Eigen::Vector3d::Zero();
}

double turn_speed(const btCollisionObject* o) {
    const btRigidBody* body = btRigidBody::upcast(o);
    return body ? double(body->getAngularVelocity().length()) * info_of(o).reach : 0.0;
}

} // namespace

double combined_setting(double a, double b, double scene, bool friction) {
    if (a < 0 && b < 0) return scene;
    if (a < 0) return b;
    if (b < 0) return a;
    return friction ? std::min(a * b, 10.0) : a * b;
}

ManifoldAlgorithm::ManifoldAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObject* body0,
                                     const btCollisionObject* body1, const NarrowContext* context)
    : btCollisionAlgorithm(ci), body0_(body0), body1_(body1), context_(context) {
    manifold_ = m_dispatcher->getNewManifold(body0, body1);
    const BodyInfo &i0 = info_of(body0), &i1 = info_of(body1);
    a_ = std::min(i0.index, i1.index), b_ = std::max(i0.index, i1.index);
    // Points closer than this to last step's are the same point, warm-started.
    manifold_->setContactBreakingThreshold(btScalar(0.02 * std::min(i0.size, i1.size)));
    const SceneObject &o0 = *i0.object, &o1 = *i1.object;
    friction_ = combined_setting(o0.friction, o1.friction, context->settings.friction, true);
    restitution_ = combined_setting(o0.restitution, o1.restitution, context->settings.restitution, false);
    rolling_ = combined_setting(o0.rolling_friction, o1.rolling_friction, context->settings.rolling_friction, false);
}

ManifoldAlgorithm::~ManifoldAlgorithm() {
    if (manifold_) m_dispatcher->releaseManifold(manifold_);
}

void ManifoldAlgorithm::processCollision(const btCollisionObjectWrapper*, const btCollisionObjectWrapper*,
                                         const btDispatcherInfo&, btManifoldResult*) {
    if (!own_scratch_) own_scratch_ = std::make_unique<QueryScratch>(), own_work_ = std::make_unique<ManifoldWork>();
    collide(*own_scratch_, *own_work_);
}

void ManifoldAlgorithm::getAllContactManifolds(btManifoldArray& manifolds) {
    if (manifold_) manifolds.push_back(manifold_);
}

void ManifoldAlgorithm::write_point(btManifoldPoint& p, const Eigen::Vector3d& on0, const Eigen::Vector3d& on1,
                                    const Eigen::Vector3d& normal_on_1, double depth, double slop,
                                    const btCollisionObject* oa, const btCollisionObject* ob,
                                    const Eigen::Vector3d& normal_ab) const {
    // Within the slop of touching counts as touching: the spheres' ripple (a sphere at a corner
    // pokes out of the face a little) must neither pull a resting body in nor push it out, which
    // would set it shivering and walk a stack sideways. Beyond it, only the excess counts.
    const double excess = std::abs(depth) > slop ? depth - std::copysign(slop, depth) : 0.0;
    p.m_positionWorldOnA = to_bt(on0);
    p.m_positionWorldOnB = to_bt(on1);
    p.m_normalWorldOnB = to_bt(normal_on_1);
    p.m_distance1 = btScalar(-excess);
    p.m_combinedFriction = btScalar(friction_);
    p.m_combinedRollingFriction = btScalar(rolling_);
    // A point still apart (speculative) that the approach closes within the step bounces from
    // where it touches: the solver aims at e v - d / dt there, so the restitution is raised by
    // d / (dt v) to give back e v; one the step does not close gets none yet.
    double e = restitution_;
    if (excess < 0 && e > 0) {
        const Eigen::Vector3d mid = 0.5 * (on0 + on1);
        const double approach = (velocity_at(oa, mid) - velocity_at(ob, mid)).dot(normal_ab);
        e = approach * context_->dt > -excess ? e + -excess / (context_->dt * approach) : 0.0;
    }
    p.m_combinedRestitution = btScalar(e);
}

void ManifoldAlgorithm::collide(QueryScratch& scratch, ManifoldWork& work) {
    const bool a_first = info_of(body0_).index == a_;
    const btCollisionObject* oa = a_first ? body0_ : body1_;
    const btCollisionObject* ob = a_first ? body1_ : body0_;
    const BodyInfo &ia = info_of(oa), &ib = info_of(ob);
    const btTransform &t0 = body0_->getWorldTransform(), &t1 = body1_->getWorldTransform();
    const double slop = 0.001 * std::min(ia.size, ib.size);
    const Pose pose_a = object_pose(oa), pose_b = object_pose(ob);
    const Pose relative = relative_pose(pose_a, pose_b);

    if (queried_) {
        // The turn's angle from its quaternion's vector part: acos of a dot near 1 would read
        // float noise in Bullet's rotations as a turn of 1e-4.
        const Eigen::Quaterniond turn = queried_at_.rotation.conjugate() * relative.rotation;
        const double angle = 2 * std::atan2(turn.vec().norm(), std::abs(turn.w()));
        const double moved = (relative.translation - queried_at_.translation).norm() + angle * ib.reach;
        if (moved < 0.25 * slop) {
            found_.counters = {};
            for (int k = 0; k < manifold_->getNumContacts(); ++k) {
                btManifoldPoint& p = manifold_->getContactPoint(k);
                const Eigen::Vector3d on0 = from_bt(t0 * p.m_localPointA), on1 = from_bt(t1 * p.m_localPointB);
                const Eigen::Vector3d n1 = from_bt(t1.getBasis() * normal_in_1_[size_t(k)]);
                const Eigen::Vector3d ab = a_first ? Eigen::Vector3d(-n1) : n1;
                const double depth = (on1 - on0).dot(n1); // body0's point past body1's, against the normal on body1
                write_point(p, on0, on1, n1, depth, slop, oa, ob, ab);
                p.m_lifeTime += 1;
            }
            return;
        }
    }

    const double dt = context_->dt;
    // Speculative margin: what the pair can close within a step, plus a sliver that keeps a resting
    // contact found from one step to the next. A pair in contact closes only along its normal: one
    // sliding or resting does not widen its band (and the pairs a wider band holds) by its speed.
    const Eigen::Vector3d relative_velocity = linear_velocity(oa) - linear_velocity(ob);
    double closing = relative_velocity.norm();
    if (manifold_->getNumContacts() > 0) {
        const Eigen::Vector3d n1 = from_bt(t1.getBasis() * normal_in_1_[0]);
        closing = std::max(0.0, relative_velocity.dot(a_first ? Eigen::Vector3d(-n1) : n1));
    }
    // At most a quarter of the smaller model: a wider band would hold nearly every sphere pair of
    // the two, and a body faster than that a step may pass through a thin one (docs/scenes.md).
    const double smaller = std::min(ia.size, ib.size);
    const double margin = std::min(0.25 * smaller, 0.005 * smaller + dt * (closing + turn_speed(oa) + turn_speed(ob) +
                                                                          context_->gravity * dt));
    contact_manifold(*ia.object->model, pose_a, *ib.object->model, pose_b, margin, ia.moves, ib.moves,
                     context_->keep_pairs, scratch, work, found_);
    queried_ = true;
    queried_at_ = relative;

    std::array<btManifoldPoint, 4> fresh;
    std::array<bool, 4> taken{};
    const int n = int(found_.points.size());
    for (int k = 0; k < n; ++k) {
        const ManifoldContact& c = found_.points[size_t(k)];
        // Bullet's convention: the normal on body1 points towards body0; distance < 0 overlaps.
        const Eigen::Vector3d on0 = a_first ? c.on_a : c.on_b, on1 = a_first ? c.on_b : c.on_a;
        const Eigen::Vector3d normal_on_1 = a_first ? Eigen::Vector3d(-c.normal) : c.normal;
        btManifoldPoint p(t0.invXform(to_bt(on0)), t1.invXform(to_bt(on1)), to_bt(normal_on_1), 0);
        write_point(p, on0, on1, normal_on_1, c.depth, slop, oa, ob, c.normal);
        const int old = manifold_->getCacheEntry(p);
        if (old >= 0 && !taken[size_t(old)]) {
            taken[size_t(old)] = true;
            const btManifoldPoint& q = manifold_->getContactPoint(old);
            p.m_appliedImpulse = q.m_appliedImpulse;
            p.m_appliedImpulseLateral1 = q.m_appliedImpulseLateral1;
            p.m_appliedImpulseLateral2 = q.m_appliedImpulseLateral2;
            p.m_prevRHS = q.m_prevRHS;
            p.m_lifeTime = q.m_lifeTime + 1;
        }
        fresh[size_t(k)] = p;
        normal_in_1_[size_t(k)] = t1.getBasis().transpose() * to_bt(normal_on_1);
    }
    manifold_->clearManifold();
    for (int k = 0; k < n; ++k) manifold_->addManifoldPoint(fresh[size_t(k)]);
}

btCollisionAlgorithm* ManifoldAlgorithmCreator::CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                                         const btCollisionObjectWrapper* body0,
                                                                         const btCollisionObjectWrapper* body1) {
    void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(ManifoldAlgorithm));
    return new (memory) ManifoldAlgorithm(ci, body0->getCollisionObject(), body1->getCollisionObject(), context_);
}

} // namespace spt::detail
