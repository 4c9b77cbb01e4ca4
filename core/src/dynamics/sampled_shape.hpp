#pragma once
// A scene object as a Bullet collision shape: a sampling-tree model that only spt's own collision
// algorithm (manifold_algorithm.hpp) reads. No Bullet algorithm is registered for the shape type,
// and no triangles are offered, so Bullet never tests it itself.
#include "spt/pose.hpp"
#include "spt/scene.hpp"
#include <BulletCollision/CollisionShapes/btCollisionShape.h>

namespace spt::detail {

/// Bullet's float vector and transform from spt's doubles, and back.
inline btVector3 to_bt(const Eigen::Vector3d& v) { return {btScalar(v.x()), btScalar(v.y()), btScalar(v.z())}; }
inline Eigen::Vector3d from_bt(const btVector3& v) { return {double(v.x()), double(v.y()), double(v.z())}; }
btTransform to_bt(const Pose& p);
Pose from_bt(const btTransform& t);

/// What spt knows of one body (btCollisionObject user pointer).
struct BodyInfo {
    uint32_t index = 0;                 ///< object index in the scene
    const SceneObject* object = nullptr; ///< its model, bounding sphere and settings
    Pose body_from_object;  ///< object frame to the body frame (centre of mass, principal axes); identity unless it moves
    bool moves = false;     ///< dynamic (moved by the solver)
    double mass = 0;        ///< 0 for static and path objects
    Eigen::Vector3d inertia = Eigen::Vector3d::Zero(); ///< principal moments, body axes
    double reach = 0;       ///< farthest model point from the body origin, model units (bounds rotation)
    double size = 0;        ///< the model's diagonal, model units
};

/// The shape of a body: its AABB is the object's broad-phase sphere, grown by `margin`.
class SampledShape : public btCollisionShape {
public:
    /// `info` must outlive the shape; `margin`: the shape's contact margin (model units).
    SampledShape(const BodyInfo* info, double margin);
    /// The AABB of the broad-phase sphere plus the margin in the world (t: body to world).
    void getAabb(const btTransform& t, btVector3& aabbMin, btVector3& aabbMax) const override;
    /// Scale is applied before conversion; Bullet's scaling is ignored.
    void setLocalScaling(const btVector3&) override {}
    const btVector3& getLocalScaling() const override { return scaling_; }
    /// The principal moments scaled to `mass` (Bullet calls it for a body made without them).
    void calculateLocalInertia(btScalar mass, btVector3& inertia) const override;
    const char* getName() const override { return "SptSampledShape"; }
    void setMargin(btScalar m) override { margin_ = m; }
    btScalar getMargin() const override { return margin_; }
    /// The body this shape stands for.
    const BodyInfo& info() const { return *info_; }

private:
    const BodyInfo* info_;
    btScalar margin_;
    btVector3 scaling_{1, 1, 1};
};

} // namespace spt::detail
