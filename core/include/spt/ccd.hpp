#pragma once
/// Continuous collision detection of the sphere model (beyond the paper): the
/// first time of impact of B moving from one pose to another relative to A, so a
/// fast thin object cannot pass through a wall between two steps.
#include "spt/query.hpp"

namespace spt {

/// Options of a continuous query.
struct CcdOptions {
    QueryLevel level = QueryLevel::Spheres; ///< Bounds or Spheres
    bool normal_culling = false;           ///< skip spheres facing away (QueryOptions::normal_culling)
    float cull_cos = 0.5f;                 ///< culling threshold (QueryOptions::cull_cos)
    double tolerance = 0; ///< model units; 0: 1e-4 of B's diagonal
};

/// Result of a continuous query.
struct CcdResult {
    bool hit = false;  ///< the model may touch during the motion
    double toi = 1;    ///< time of impact in [0, 1]; never later than the true first contact
    int queries = 0;   ///< static queries run
    QueryCounters counters; ///< work of every static query together
};

/// B moves from b0 to b1 (poses in A's frame; translation linear, rotation slerp).
/// Intervals of time are ruled out by a static query at their middle with every
/// sphere grown by the farthest any point of B can move in half the interval,
/// |dt|/2 * (|t1 - t0| + angle * B.reach()); so no contact is skipped. An interval
/// that cannot be ruled out once that growth is below the tolerance gives the time
/// of impact: the model comes within 2 * tolerance of contact there, and nothing
/// touches earlier.
CcdResult first_contact(const CollisionModel& a, const CollisionModel& b, const Pose& b0_in_a, const Pose& b1_in_a,
                        const CcdOptions& options, QueryScratch& scratch);

} // namespace spt
