#pragma once
// The poses of the accuracy benchmark and their ground truth (FCL).
#include "peers.hpp"
#include <vector>

namespace bench {

/// A pose near first contact: B moved in (inside) or out by offset * diagonal from it.
struct ContactPose {
    spt::Pose pose;
    Eigen::Vector3d motion; ///< B's approach direction, A's frame (unit)
    int offset = 0;         ///< index into PoseSets::offsets
    bool inside = false;
    bool truth = false;            ///< FCL collide
    double truth_backtrack = 0;    ///< FCL: distance back along -motion to separation (colliding poses)
};

struct PoseSets {
    std::vector<spt::Pose> random;     ///< (a): centre distances 0.2..2.4, random orientations
    std::vector<bool> random_truth;
    std::vector<ContactPose> near;     ///< (b)
    std::vector<double> offsets = {0.003, 0.01, 0.03}; ///< fractions of the diagonal
};

/// Builds both pose sets for two copies of a mesh of diagonal `diag` scaled into [-1, 1]^3.
PoseSets make_pose_sets(const FclPeer& fcl, double diag, int orientations_per_distance, int directions, unsigned seed);

/// FCL backtrack: steps of 1% of the diagonal along `back`, then bisection to 1e-6 of it.
double fcl_backtrack(const FclPeer& fcl, const spt::Pose& pose, const Eigen::Vector3d& back, double diag);

} // namespace bench
