// Mass and inertia of a moving object (rigid_mass.hpp).
#include "dynamics/rigid_mass.hpp"
#include "spt/error.hpp"
#include <Eigen/Eigenvalues>
#include <algorithm>

namespace spt::detail {
namespace {

// Centre and inertia (per unit mass) of a uniform box around the model's sampling spheres.
std::pair<Eigen::Vector3d, Eigen::Matrix3d> box_of_spheres(const CollisionModel& m) {
    const CompactTree& t = m.tree();
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
    for (const CompactNode& n : t.nodes())
        for (uint32_t k = n.first; k < n.first + n.count; ++k) {
            const Eigen::Vector3d c = m.origin() + t.sphere_center(n, k).cast<double>();
            const Eigen::Vector3d r = Eigen::Vector3d::Constant(double(n.ss_radius));
            lo = lo.cwiseMin(c - r), hi = hi.cwiseMax(c + r);
        }
    if (!(lo.array() <= hi.array()).all()) lo = hi = m.origin();
    const Eigen::Vector3d e = hi - lo;
    const Eigen::Vector3d s = e.cwiseProduct(e) / 12;
    return {0.5 * (lo + hi), Eigen::Vector3d(s.y() + s.z(), s.x() + s.z(), s.x() + s.y()).asDiagonal()};
}

} // namespace

RigidMass rigid_mass(const SceneObject& o, const std::string& scene_file, size_t index) {
    RigidMass r;
    Eigen::Vector3d centre;
    Eigen::Matrix3d inertia; // about the centre, object axes, of the whole mass
    if (o.solid) {
        r.mass = o.mass > 0 ? o.mass : o.density * o.solid->volume;
        centre = o.solid->centre;
        inertia = o.solid->inertia * (r.mass / o.solid->volume);
    } else if (o.mass > 0) {
        r.mass = o.mass;
        const auto [c, per_mass] = box_of_spheres(*o.model);
        centre = c, inertia = per_mass * r.mass;
    } else {
        throw Error(ErrorKind::BadInput,
                    scene_file + ": at /objects/" + std::to_string(index) + ": object '" + o.name +
                        "' moves under dynamics and has no mass: its model is " +
                        (o.model->has_mesh() ? "an open mesh, which bounds no volume"
                                             : "a .spt file without its closed mesh") +
                        "; give it a 'mass'");
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(0.5 * (inertia + inertia.transpose()));
    Eigen::Matrix3d axes = eigen.eigenvectors();
    if (axes.determinant() < 0) axes.col(2) = -axes.col(2); // a rotation, not a reflection
    // A flat or thin part has a vanishing moment: kept above a sliver of the largest so the solver
    // never divides by zero.
    const double top = eigen.eigenvalues().maxCoeff();
    r.principal_moments = eigen.eigenvalues().cwiseMax(1e-6 * top);
    r.object_from_body = Pose::from(centre, Eigen::Quaterniond(axes));
    return r;
}

} // namespace spt::detail
