// The benchmark protocol: random and near-contact poses, motions, timing by median.
#include "protocol.hpp"
#include <random>

namespace bench {
namespace {

Eigen::Quaterniond random_rotation(std::mt19937& rng) {
    std::normal_distribution<double> n;
    return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
}
Eigen::Vector3d random_unit(std::mt19937& rng) {
    std::normal_distribution<double> n;
    return Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
}

} // namespace

double fcl_backtrack(const FclPeer& fcl, const spt::Pose& pose, const Eigen::Vector3d& back, double diag) {
    auto at = [&](double s) { return spt::Pose::from(pose.translation + s * back, pose.rotation); };
    if (!fcl.collide(at(0))) return 0;
    double lo = 0, hi = 0.01 * diag;
    while (fcl.collide(at(hi))) lo = hi, hi += 0.01 * diag;
    while (hi - lo > 1e-6 * diag) {
        const double mid = 0.5 * (lo + hi);
        (fcl.collide(at(mid)) ? lo : hi) = mid;
    }
    return hi;
}

PoseSets make_pose_sets(const FclPeer& fcl, double diag, int orientations, int directions, unsigned seed) {
    PoseSets s;
    std::mt19937 rng(seed);
    for (int k = 1; k <= 12; ++k)
        for (int i = 0; i < orientations; ++i) {
            const spt::Pose p = spt::Pose::from(0.2 * k * random_unit(rng), random_rotation(rng));
            s.random.push_back(p);
            s.random_truth.push_back(fcl.collide(p));
        }
    // Both copies fit in [-1, 1]^3, so centres 2*sqrt(3) apart cannot touch.
    const double start = 2 * std::sqrt(3.0) + 0.01, step = 0.005 * diag;
    for (int d = 0; d < directions; ++d) {
        const Eigen::Vector3d u = random_unit(rng);
        const Eigen::Quaterniond q = random_rotation(rng);
        auto at = [&](double r) { return spt::Pose::from(r * u, q); };
        double r = start;
        while (r > 0 && !fcl.collide(at(r))) r -= step;
        if (r <= 0) continue; // passes through without touching (possible for a torus)
        double in = r, out = r + step;
        while (out - in > 1e-7 * diag) {
            const double mid = 0.5 * (in + out);
            (fcl.collide(at(mid)) ? in : out) = mid;
        }
        for (int o = 0; o < int(s.offsets.size()); ++o)
            for (bool inside : {true, false}) {
                ContactPose c;
                c.pose = at(out + (inside ? -1 : 1) * s.offsets[size_t(o)] * diag);
                c.motion = -u;
                c.offset = o;
                c.inside = inside;
                c.truth = fcl.collide(c.pose);
                if (c.truth) c.truth_backtrack = fcl_backtrack(fcl, c.pose, u, diag);
                s.near.push_back(c);
            }
    }
    return s;
}

} // namespace bench
