// Collision-overlay pairs: world sampling spheres, the pair record of two spheres, brute-force overlaps.
#include "spt/render/collision_overlay.hpp"
#include <cmath>

namespace spt::render {

std::vector<Sphere> world_spheres(const CompactTree& compact, const Eigen::Affine3f& pose) {
    std::vector<Sphere> out(compact.sphere_count());
    const Eigen::Vector3f origin = compact.origin().cast<float>();
    for (const CompactNode& n : compact.nodes()) {
        if (!n.is_active()) continue;
        for (uint32_t k = n.first; k < n.first + n.count; ++k)
            out[k] = {pose * (origin + compact.sphere_centre(n, k)), n.ss_radius};
    }
    return out;
}

SpherePair make_sphere_pair(const Sphere& a, const Sphere& b) {
    SpherePair p;
    p.a = a, p.b = b;
    const Eigen::Vector3f d = b.center - a.center;
    const float dist = d.norm();
    p.normal = dist > 1e-12f ? Eigen::Vector3f(d / dist) : Eigen::Vector3f::UnitY();
    p.depth = a.radius + b.radius - dist;
    p.contact = a.center + p.normal * (a.radius - 0.5f * p.depth);
    return p;
}

std::vector<SpherePair> overlapping_pairs(const std::vector<Sphere>& a, const std::vector<Sphere>& b) {
    std::vector<SpherePair> out;
    for (const Sphere& x : a)
        for (const Sphere& y : b) {
            const float r = x.radius + y.radius;
            if ((y.center - x.center).squaredNorm() < r * r) out.push_back(make_sphere_pair(x, y));
        }
    return out;
}

} // namespace spt::render
