// The measured peers: FCL (OBBRSS) and Bullet (GImpact) on the same meshes and poses.
#include "peers.hpp"
#include <btBulletCollisionCommon.h>
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <fcl/fcl.h>

namespace bench {

struct FclPeer::Impl {
    std::unique_ptr<fcl::CollisionObjectd> a, b;
};

namespace {

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> fcl_model(const spt::TriangleMesh& mesh) {
    std::vector<fcl::Vector3d> v(mesh.positions.begin(), mesh.positions.end());
    std::vector<fcl::Triangle> t;
    for (const auto& tri : mesh.triangles) t.emplace_back(tri[0], tri[1], tri[2]);
    auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    model->beginModel();
    model->addSubModel(v, t);
    model->endModel();
    return model;
}

} // namespace

FclPeer::FclPeer(const spt::TriangleMesh& mesh) : impl_(std::make_unique<Impl>()) {
    const auto model = fcl_model(mesh);
    impl_->a = std::make_unique<fcl::CollisionObjectd>(model, fcl::Transform3d::Identity());
    impl_->b = std::make_unique<fcl::CollisionObjectd>(model, fcl::Transform3d::Identity());
}

FclPeer::FclPeer(const spt::TriangleMesh& a, const spt::TriangleMesh& b) : impl_(std::make_unique<Impl>()) {
    impl_->a = std::make_unique<fcl::CollisionObjectd>(fcl_model(a), fcl::Transform3d::Identity());
    impl_->b = std::make_unique<fcl::CollisionObjectd>(fcl_model(b), fcl::Transform3d::Identity());
}

FclPeer::~FclPeer() = default;

bool FclPeer::collide(const spt::Pose& p) const {
    fcl::Transform3d t = fcl::Transform3d::Identity();
    t.linear() = p.rotation.toRotationMatrix();
    t.translation() = p.translation;
    impl_->b->setTransform(t);
    fcl::CollisionRequestd req;
    fcl::CollisionResultd res;
    fcl::collide(impl_->a.get(), impl_->b.get(), req, res);
    return res.isCollision();
}

double FclPeer::distance(const spt::Pose& p, Eigen::Vector3d* on_a, Eigen::Vector3d* on_b) const {
    fcl::Transform3d t = fcl::Transform3d::Identity();
    t.linear() = p.rotation.toRotationMatrix();
    t.translation() = p.translation;
    impl_->b->setTransform(t);
    fcl::DistanceRequestd req(on_a != nullptr || on_b != nullptr);
    fcl::DistanceResultd res;
    fcl::distance(impl_->a.get(), impl_->b.get(), req, res);
    if (on_a) *on_a = res.nearest_points[0];
    if (on_b) *on_b = res.nearest_points[1];
    return res.min_distance;
}

struct BulletPeer::Impl {
    std::vector<int> indices;
    std::vector<btScalar> vertices;
    std::unique_ptr<btTriangleIndexVertexArray> array;
    std::unique_ptr<btGImpactMeshShape> shape;
    btDefaultCollisionConfiguration config;
    std::unique_ptr<btCollisionDispatcher> dispatcher;
    btDbvtBroadphase broadphase;
    std::unique_ptr<btCollisionWorld> world;
    btCollisionObject a, b;
};

BulletPeer::BulletPeer(const spt::TriangleMesh& mesh) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    for (const auto& p : mesh.positions) m.vertices.insert(m.vertices.end(), {btScalar(p.x()), btScalar(p.y()), btScalar(p.z())});
    for (const auto& t : mesh.triangles) m.indices.insert(m.indices.end(), {int(t[0]), int(t[1]), int(t[2])});
    m.array = std::make_unique<btTriangleIndexVertexArray>(int(mesh.triangles.size()), m.indices.data(), 3 * int(sizeof(int)),
                                                           int(mesh.positions.size()), m.vertices.data(),
                                                           3 * int(sizeof(btScalar)));
    m.shape = std::make_unique<btGImpactMeshShape>(m.array.get());
    m.shape->setMargin(0);
    m.shape->updateBound();
    m.dispatcher = std::make_unique<btCollisionDispatcher>(&m.config);
    btGImpactCollisionAlgorithm::registerAlgorithm(m.dispatcher.get());
    // contactPairTest asks for closest-point algorithms, which registerAlgorithm leaves out.
    static btGImpactCollisionAlgorithm::CreateFunc gimpact;
    for (int i = 0; i < MAX_BROADPHASE_COLLISION_TYPES; ++i) {
        m.dispatcher->registerClosestPointsCreateFunc(GIMPACT_SHAPE_PROXYTYPE, i, &gimpact);
        m.dispatcher->registerClosestPointsCreateFunc(i, GIMPACT_SHAPE_PROXYTYPE, &gimpact);
    }
    m.world = std::make_unique<btCollisionWorld>(m.dispatcher.get(), &m.broadphase, &m.config);
    m.a.setCollisionShape(m.shape.get());
    m.b.setCollisionShape(m.shape.get());
    m.world->addCollisionObject(&m.a);
    m.world->addCollisionObject(&m.b);
}

BulletPeer::~BulletPeer() {
    impl_->world->removeCollisionObject(&impl_->b);
    impl_->world->removeCollisionObject(&impl_->a);
}

namespace {
struct AnyContact : btCollisionWorld::ContactResultCallback {
    bool hit = false;
    btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper*, int, int, const btCollisionObjectWrapper*,
                             int, int) override {
        if (cp.getDistance() <= 0) hit = true;
        return 0;
    }
};
} // namespace

bool BulletPeer::collide(const spt::Pose& p) const {
    const Eigen::Quaterniond& q = p.rotation;
    impl_->b.setWorldTransform(btTransform(btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w())),
                                           btVector3(btScalar(p.translation.x()), btScalar(p.translation.y()),
                                                     btScalar(p.translation.z()))));
    AnyContact cb;
    impl_->world->contactPairTest(&impl_->a, &impl_->b, cb);
    return cb.hit;
}

} // namespace bench
