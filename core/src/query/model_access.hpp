#pragma once
// The library's own view of a CollisionModel's private parts: the exact level's triangles and
// where the model is solid. Callers outside core never see these layouts.
#include "query/exact_data.hpp"
#include "query/solid.hpp"
#include "spt/collision_model.hpp"

namespace spt::detail {

struct ModelAccess {
    static const ExactData& exact(const CollisionModel& m) {
        static const ExactData kNone;
        return m.exact_ ? *m.exact_ : kNone;
    }
    static const SolidData& solid(const CollisionModel& m) {
        static const SolidData kNone;
        return m.solid_ ? *m.solid_ : kNone;
    }
    static PendingPose* pending(const CollisionModel& m) { return m.pending_.pose; }
    static const float* node_slab(const CollisionModel& m) { return m.node_slab_.empty() ? nullptr : m.node_slab_.data(); }
    static const float* node_max_radius(const CollisionModel& m) {
        return m.node_max_radius_.empty() ? nullptr : m.node_max_radius_.data();
    }
};

/// Triangle data for the `exact` level, empty without a mesh.
inline const ExactData& exact_of(const CollisionModel& m) { return ModelAccess::exact(m); }
/// Per node, a unit normal and half-thickness holding its spheres (query/node_slab.hpp); null when
/// the spheres have moved since they were fitted.
inline const float* node_slab_of(const CollisionModel& m) { return ModelAccess::node_slab(m); }
/// Per node, the largest sampling-sphere radius below it (query/node_slab.hpp); null for an empty model.
inline const float* node_max_radius_of(const CollisionModel& m) { return ModelAccess::node_max_radius(m); }
/// Where the model is solid, and its anchor points.
inline const SolidData& solid_of(const CollisionModel& m) { return ModelAccess::solid(m); }

} // namespace spt::detail
