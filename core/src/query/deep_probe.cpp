// A deep overlap found in a few dozen node pairs. The `all` walk that stops at its first deep pair
// goes in the tree's order and lists the shallow pairs it meets first: thousands of node pairs
// before it reaches the middle of two shells crossed by half a radius. Where the balls overlap
// most is where such pairs lie, so one greedy descent there finds one; if it does not, the walk
// decides as before, and `deep` is the same either way (whether any leaf pair holds a deep pair).
#include "query/model_access.hpp"
#include "query/pending_pose.hpp"
#include "query/query_run.hpp"
#include <cmath>
#include <limits>

namespace spt {

bool QueryRun::probe_deep() {
    if (o.level != QueryLevel::Spheres || detail::pending_of(A) || detail::pending_of(B)) return false;
    const auto &an = A.tree().nodes(), &bn = B.tree().nodes();
    if (an.empty() || bn.empty()) return false;
    auto centre_a = [&](uint32_t i) { return Eigen::Vector3f(an[i].center[0], an[i].center[1], an[i].center[2]); };
    const float pad = o.inflate + f.margin;
    uint32_t i = 0, j = 0;
    Eigen::Vector3f ca = centre_a(0), cb = b_node_centre(0);
    // Worth a descent only where the roots' balls overlap by more than half the largest reach a
    // pair can have (shallow presses, most contacts of a pile, cost the walk they cost before).
    const float* max_r_a = detail::node_max_radius_of(A);
    const float* max_r_b = detail::node_max_radius_of(B);
    if (!max_r_a || !max_r_b ||
        !(an[0].bv_radius + bn[0].bv_radius + pad - (ca - cb).norm() > 0.5f * (max_r_a[0] + max_r_b[0])))
        return false;
    for (;;) {
        ++res.counters.node_pairs;
        const bool leaf_a = an[i].is_active(), leaf_b = bn[j].is_active();
        if (leaf_a && leaf_b) {
            // The leaf test of the walk, its pairs taken back off the list.
            const size_t listed = s.pairs.size();
            sphere_leaf_pair(i, j, ca);
            const bool deep = leaf_deep;
            s.pairs.resize(listed);
            leaf_deep = false;
            return deep;
        }
        // The larger ball is split, as the walk splits it; the child whose ball overlaps the other most.
        const bool side_a = leaf_b || (!leaf_a && an[i].bv_radius >= bn[j].bv_radius);
        const uint32_t at = side_a ? i : j;
        const auto& nodes = side_a ? an : bn;
        float most = -std::numeric_limits<float>::infinity();
        uint32_t pick = nodes[at].first;
        Eigen::Vector3f picked = Eigen::Vector3f::Zero();
        for (const uint32_t child : {at + 1, nodes[at].first}) {
            const Eigen::Vector3f c = side_a ? centre_a(child) : b_node_centre(child);
            const float overlap = nodes[child].bv_radius + (side_a ? bn[j].bv_radius : an[i].bv_radius) + pad -
                                  (c - (side_a ? cb : ca)).norm();
            ++res.counters.bound_tests;
            if (overlap > most) most = overlap, pick = child, picked = c;
        }
        (side_a ? i : j) = pick;
        (side_a ? ca : cb) = picked;
        // The same bar all the way down: where the balls overlap by less than half the largest reach
        // below them, a deep pair is unlikely, and the walk decides (a shallow press ends here in
        // a step or two).
        if (!(most > 0.5f * (max_r_a[i] + max_r_b[j]))) return false;
    }
}

} // namespace spt
