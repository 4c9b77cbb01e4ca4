// Collision-overlay pairs: world sampling spheres, the pair record of two spheres, every overlapping pair.
#include "spt/render/collision_overlay.hpp"
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace spt::render {

std::vector<Sphere> world_spheres(const CompactTree& compact, const Eigen::Affine3f& pose) {
    std::vector<Sphere> out(compact.sphere_count());
    const Eigen::Vector3d origin = compact.origin();
    for (const CompactNode& n : compact.nodes()) {
        if (!n.is_active()) continue;
        for (uint32_t k = n.first; k < n.first + n.count; ++k)
            out[k] = {pose * Eigen::Vector3f((origin + compact.sphere_center(n, k).cast<double>()).cast<float>()),
                      n.ss_radius};
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
    // b sorted by x: each sphere of a meets only those within its radius plus b's largest in
    // x. The window is widened by a thousandth so that rounding in the subtraction never drops
    // a pair the test below keeps; every pair in it is tested as before, so the pairs are the
    // same as pairing off all of a with all of b. A sphere of b whose x is NaN fails that test
    // with any other, and is left out of the sort (a NaN has no order).
    std::vector<uint32_t> order;
    order.reserve(b.size());
    float widest = 0;
    for (uint32_t j = 0; j < b.size(); ++j)
        if (!std::isnan(b[j].center.x())) order.push_back(j), widest = std::max(widest, std::abs(b[j].radius));
    std::sort(order.begin(), order.end(), [&](uint32_t i, uint32_t j) { return b[i].center.x() < b[j].center.x(); });
    std::vector<SpherePair> out;
    std::vector<uint32_t> hits;
    for (const Sphere& x : a) {
        const float window = 1.001f * (std::abs(x.radius) + widest); // |ra + rb| <= |ra| + |rb|
        auto first = std::lower_bound(order.begin(), order.end(), x.center.x() - window,
                                      [&](uint32_t j, float v) { return b[j].center.x() < v; });
        hits.clear();
        for (auto it = first; it != order.end() && b[*it].center.x() <= x.center.x() + window; ++it) {
            const Sphere& y = b[*it];
            const float r = x.radius + y.radius;
            if ((y.center - x.center).squaredNorm() < r * r) hits.push_back(*it);
        }
        std::sort(hits.begin(), hits.end());
        for (uint32_t j : hits) out.push_back(make_sphere_pair(x, b[j]));
    }
    return out;
}

} // namespace spt::render
