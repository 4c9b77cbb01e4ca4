#pragma once
// What a step finds about one candidate pair, written by one worker, read in pair order.
#include "spt/query.hpp"
#include "spt/query_scratch.hpp"
#include <vector>

namespace spt::detail {

struct PairWork {
    bool ccd_ran = false, ccd_hit = false, collide = false;
    double toi = 1;        // fraction of the step
    double ccd_band = 0;   // distance within which a ccd hit counts as touching, model units
    QueryCounters qc;      // every query of the pair this step
    double depth = 0;
    Eigen::Vector3d point = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitX();
    std::vector<SpherePair> pairs;
    bool deep = false; // depth took the deep-overlap route: `pairs` and the scratch's pairs are not every pair
    SpherePair deepest{}; // a deep overlap's deepest pair (w.deep), where its response starts
    bool all_collide = false;                           // the pairs effect's `all` query: its answer
    Eigen::Vector3d all_point = Eigen::Vector3d::Zero(); // and its contact (a containment's anchor)
};

/// Deepest sphere pair of A and B (world poses) at `level`, spheres grown by `band`; for a deep
/// overlap (w.deep: surfaces crossing) by branch and bound, with the normal of that pair's two
/// active nodes (docs/scenes.md, "Deep overlaps"), else from every overlapping pair; (0 for a
/// colliding pair; a ccd hit that stopped short of contact grows them to find where it touches).
/// Sets w.depth (minus the band, at least 0), w.point and w.normal (contact_normal), adds counters.
/// `*_dynamic`: the object moves by velocities (contact_normal's a_moves, b_moves).
void deepest_contact(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                     QueryLevel level, double band, bool a_dynamic, bool b_dynamic, PairWork& w,
                     QueryScratch& scratch);

/// As deepest_contact, from the sphere pairs of an `all` query already run at `level` with
/// spheres grown by `band` (`collide` and `point`: its answer and contact): the pairs effect's
/// query serves depth too.
void contact_from_pairs(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                        QueryLevel level, double band, bool a_dynamic, bool b_dynamic,
                        const std::vector<SpherePair>& pairs, bool collide, const Eigen::Vector3d& point, PairWork& w,
                        QueryScratch& scratch);

/// Contact normal (world, unit, from A towards B): the depth-weighted sum of the surface normals
/// of the overlapping sphere pairs `pairs`, n_a - n_b, each turned to face the other sphere; so a
/// flat face gives its exact face normal. `a_moves` / `b_moves` false: that object's surface
/// alone gives it (what is struck is fixed). `fallback` when the sum vanishes. `scratch`: working
/// memory only (its pair list is not read, so `pairs` may be it).
Eigen::Vector3d contact_normal(const CollisionModel& a, const Pose& pa, const CollisionModel& b, const Pose& pb,
                               const std::vector<SpherePair>& pairs, const Eigen::Vector3d& fallback, bool a_moves,
                               bool b_moves, QueryScratch& scratch);

} // namespace spt::detail
