#pragma once
// The measured peers, behind one small interface: FCL (OBBRSS, boolean and distance) and
// Bullet (btGImpactMeshShape). B's pose is given in A's frame; A at the identity.
#include "spt/mesh.hpp"
#include "spt/pose.hpp"
#include <memory>

namespace bench {

/// FCL 0.7 mesh-mesh boolean query on OBBRSS trees of A's and B's meshes.
class FclPeer {
public:
    /// The same mesh for A and B.
    explicit FclPeer(const spt::TriangleMesh& mesh);
    /// Mesh `a` for A (at the identity) and `b` for B.
    FclPeer(const spt::TriangleMesh& a, const spt::TriangleMesh& b);
    ~FclPeer();
    /// True if the triangle surfaces intersect.
    bool collide(const spt::Pose& b_in_a) const;
    /// fcl::distance of the triangle surfaces (0 when they meet), model units; with the nearest
    /// points when asked (A's frame).
    double distance(const spt::Pose& b_in_a, Eigen::Vector3d* on_a = nullptr, Eigen::Vector3d* on_b = nullptr) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Bullet GImpact mesh-mesh contact test (margin 0): collide if any contact has distance <= 0.
class BulletPeer {
public:
    explicit BulletPeer(const spt::TriangleMesh& mesh);
    ~BulletPeer();
    bool collide(const spt::Pose& b_in_a) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace bench
