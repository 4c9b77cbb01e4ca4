// A scene object as a Bullet collision shape (sampled_shape.hpp).
#include "dynamics/sampled_shape.hpp"
#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>

namespace spt::detail {

btTransform to_bt(const Pose& p) {
    const Eigen::Quaterniond& q = p.rotation;
    return btTransform(btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w())), to_bt(p.translation));
}

Pose from_bt(const btTransform& t) {
    const btQuaternion q = t.getRotation();
    return Pose::from(from_bt(t.getOrigin()), Eigen::Quaterniond(double(q.w()), double(q.x()), double(q.y()), double(q.z())));
}

SampledShape::SampledShape(const BodyInfo* info, double margin) : info_(info), margin_(btScalar(margin)) {
    m_shapeType = CUSTOM_CONCAVE_SHAPE_TYPE;
}

void SampledShape::getAabb(const btTransform& t, btVector3& aabbMin, btVector3& aabbMax) const {
    // Read at every step: an animated object's sphere follows its clip.
    const SceneObject& o = *info_->object;
    const btVector3 centre = t * to_bt(info_->body_from_object.apply(o.bound_center));
    const btScalar r = btScalar(o.bound_radius) + margin_;
    aabbMin = centre - btVector3(r, r, r);
    aabbMax = centre + btVector3(r, r, r);
}

void SampledShape::calculateLocalInertia(btScalar mass, btVector3& inertia) const {
    const double scale = info_->mass > 0 ? double(mass) / info_->mass : 0;
    inertia = to_bt(info_->inertia * scale);
}

} // namespace spt::detail
