// Volume, centre of mass and inertia tensor of the solid a closed mesh bounds: each triangle with
// the origin spans a signed tetrahedron, and the solid's integrals are the sums of theirs.
#include "spt/error.hpp"
#include "spt/mesh.hpp"
#include <cmath>

namespace spt {

SolidMass mass_properties(const TriangleMesh& mesh) {
    // About a point inside the bounds, not the origin: a mesh far from the origin keeps its digits.
    const auto [lo, hi] = mesh.bounds();
    const Eigen::Vector3d ref = 0.5 * (lo + hi);
    double volume = 0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero(); // integral of x over the solid
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero(); // integral of x x^T
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (mesh.copies_earlier_face(f)) continue;
        const Triangle& t = mesh.triangles[f];
        const Eigen::Vector3d a = mesh.positions[t[0]] - ref, b = mesh.positions[t[1]] - ref,
                              c = mesh.positions[t[2]] - ref;
        const double v6 = a.dot(b.cross(c)); // six times the tetrahedron (0, a, b, c)'s signed volume
        volume += v6 / 6;
        first += v6 / 24 * (a + b + c);
        // Over a tetrahedron with a vertex at 0: integral of x x^T = det/120 (sum of v v^T + (sum v)(sum v)^T).
        const Eigen::Vector3d s = a + b + c;
        second += v6 / 120 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
    if (!(volume > 1e-12 * std::pow(mesh.diagonal(), 3)))
        throw Error(ErrorKind::BadInput, mesh.name + ": the mesh encloses no volume, so it has no mass of its own");
    SolidMass m;
    m.volume = volume;
    const Eigen::Vector3d centre = first / volume;
    m.centre = ref + centre;
    const Eigen::Matrix3d about_centre = second - volume * centre * centre.transpose(); // parallel axis
    m.inertia = Eigen::Matrix3d::Identity() * about_centre.trace() - about_centre;
    return m;
}

} // namespace spt
