#pragma once
// Bullet's collision algorithm for two sampled shapes: spt's contact manifold (contact_manifold.hpp)
// written into the pair's btPersistentManifold, each point matched to last step's so the solver
// warm-starts it.
#include "dynamics/contact_manifold.hpp"
#include "dynamics/sampled_shape.hpp"
#include "spt/scene.hpp"
#include <BulletCollision/BroadphaseCollision/btCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionCreateFunc.h>
#include <BulletCollision/NarrowPhaseCollision/btManifoldPoint.h>
#include <array>
#include <memory>

class btPersistentManifold;

namespace spt::detail {

/// What every pair's narrow phase of a step shares.
struct NarrowContext {
    double dt = 0.01;           ///< seconds a step
    double gravity = 0;         ///< |g| when gravity acts, model units / s^2
    DynamicsSettings settings;  ///< the scene's friction, restitution
    bool keep_pairs = false;    ///< keep the sphere pairs (effect pairs)
};

/// One body pair's narrow phase and its manifold.
class ManifoldAlgorithm : public btCollisionAlgorithm {
public:
    ManifoldAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObject* body0,
                      const btCollisionObject* body1, const NarrowContext* context);
    ~ManifoldAlgorithm() override;
    /// Bullet's entry; spt's dispatcher calls collide() instead, on its own threads.
    void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                          const btDispatcherInfo& info, btManifoldResult* result) override;
    /// No time of impact: contacts are found ahead of the motion (speculative margin) instead.
    btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&, btManifoldResult*) override {
        return 1;
    }
    void getAllContactManifolds(btManifoldArray& manifolds) override;
    /// Finds the contact of the two bodies at their current transforms and replaces the manifold's
    /// points with it, keeping the impulses of the points it matches; or, while the pair has moved
    /// less than a quarter of the slop relative to each other since it last looked, moves last
    /// step's points with the bodies and measures their depths again. Touches this pair's data only.
    void collide(QueryScratch& scratch, ManifoldWork& work);
    /// The scene's object indices of the pair, lower first.
    uint32_t a() const { return a_; }
    uint32_t b() const { return b_; }
    /// The manifold (Bullet's body0 and body1 order).
    const btPersistentManifold* manifold() const { return manifold_; }
    /// The last collide(): its query counters and, with keep_pairs, its sphere pairs (a's and b's trees).
    const Manifold& found() const { return found_; }

private:
    const btCollisionObject *body0_, *body1_;
    const NarrowContext* context_;
    btPersistentManifold* manifold_ = nullptr;
    uint32_t a_ = 0, b_ = 0;
    double friction_ = 0, restitution_ = 0, rolling_ = 0;
    Manifold found_;
    std::unique_ptr<QueryScratch> own_scratch_; // processCollision's, made at its first call
    std::unique_ptr<ManifoldWork> own_work_;
    // The relative pose (b in a's frame) at the last query, and each point's normal in body1's
    // frame then: while the pair stays within a sliver of that pose, its points are carried along
    // instead of found again (as Bullet's own manifolds do).
    bool queried_ = false;
    Pose queried_at_;
    std::array<btVector3, 4> normal_in_1_;
    void write_point(btManifoldPoint& p, const Eigen::Vector3d& on0, const Eigen::Vector3d& on1,
                     const Eigen::Vector3d& normal_on_1, double depth, double slop, const btCollisionObject* oa,
                     const btCollisionObject* ob, const Eigen::Vector3d& normal_ab) const;
};

/// Makes ManifoldAlgorithm for two sampled shapes (registered for CUSTOM_CONCAVE_SHAPE_TYPE twice).
class ManifoldAlgorithmCreator : public btCollisionAlgorithmCreateFunc {
public:
    explicit ManifoldAlgorithmCreator(const NarrowContext* context) : context_(context) {}
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;

private:
    const NarrowContext* context_;
};

/// A per-object setting as a pair uses it: the scene's when neither object sets one, the one
/// object's that does, else both combined as Bullet does (the product; friction at most 10).
double combined_setting(double a, double b, double scene, bool friction);

} // namespace spt::detail
