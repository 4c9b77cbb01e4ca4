#pragma once
// A model posed lazily (DeformingModel::pose_lazily): its layout holds the pose near the root
// only, and each part below is posed when a query first reads it (docs/deforming.md, "Lazy refit").
#include "query/model_access.hpp"
#include <atomic>
#include <cstdint>

namespace spt::detail {

constexpr uint32_t kNoRegion = 0xffffffffu;

class PendingPose {
public:
    virtual ~PendingPose() = default;
    /// Poses the part of the layout that a walk reads at compact node `node` (its children and
    /// grandchildren's balls, or its spheres) if that is not done yet.
    /// Several walks may ensure at once: a region is posed once, under the pose's lock, and a
    /// walk reads it only after it sees the region's flag set.
    void ensure(uint32_t node) {
        const uint32_t r = need_[node];
        if (r != kNoRegion && !posed_[r].load(std::memory_order_acquire)) pose_region(r);
    }
    /// Whether compact node `node`'s ball is fitted from the posed vertices rather than the spheres
    /// below (a cover or a node above the covers): looser than its children's, so a walk counts
    /// it as larger when it chooses which ball of a pair to split.
    bool loose(uint32_t node) const { return loose_[node] != 0; }
    /// Poses the rest: the model becomes what a full pose makes, and is no longer pending.
    virtual void settle() = 0;
    /// Readies the exact level: the triangles' balls and tree refit around the posed corners (at
    /// most once a pose, under the pose's lock), the sampling spheres left as they are.
    void ensure_triangles() {
        if (!triangles_posed_.load(std::memory_order_acquire)) pose_triangles();
    }

protected:
    const uint32_t* need_ = nullptr; // per compact node: the region to pose before reading below it
    std::atomic<uint8_t>* posed_ = nullptr; // per region: posed at the current pose
    const uint8_t* loose_ = nullptr;        // per compact node: 1 for a cover or a node above them
    virtual void pose_region(uint32_t r) = 0;
    virtual void pose_triangles() = 0;
    std::atomic<uint8_t> triangles_posed_{0}; // the triangle tree refit at the current pose
};

/// The model's pending pose, or null when the model is posed throughout.
inline PendingPose* pending_of(const CollisionModel& m) { return ModelAccess::pending(m); }
/// Poses what a lazy pose of `m` left; a no-op for a model posed throughout.
inline void settle(const CollisionModel& m) {
    if (PendingPose* p = pending_of(m)) p->settle();
}
/// Readies the triangles of a lazily posed `m` (PendingPose::ensure_triangles); a no-op for a
/// model posed throughout or without triangles.
inline void ensure_triangles(const CollisionModel& m) {
    if (PendingPose* p = pending_of(m); p && m.has_mesh()) p->ensure_triangles();
}

} // namespace spt::detail
