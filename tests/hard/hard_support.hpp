#pragma once
// Shared by the hard-case tests: moved and scaled copies of meshes, and poses at a known
// distance from first contact, found with the exact level (the independent reference).
#include "spt/collision_model.hpp"
#include "spt/convert.hpp"
#include "spt/query.hpp"
#include "mesh/shapes.hpp"
#include <memory>
#include <random>
#include <vector>

namespace spt::hard {

/// Every query level, coarsest first.
inline constexpr QueryLevel kLevels[] = {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact};

/// A mesh, its document (default conversion) and its model with the exact level.
struct Object {
    TriangleMesh mesh;
    SptDocument doc;
    CollisionModel model;
};

inline std::unique_ptr<Object> make_object(TriangleMesh mesh, const ConvertOptions& options = {}) {
    auto o = std::make_unique<Object>();
    o->mesh = std::move(mesh);
    o->doc = make_document(o->mesh, options);
    o->model = CollisionModel(o->doc, o->mesh);
    return o;
}

/// `mesh` with every vertex mapped by x -> scale * x + offset (positions only; prepared again).
inline TriangleMesh transformed(const TriangleMesh& mesh, double scale, const Eigen::Vector3d& offset) {
    std::vector<Eigen::Vector3d> p(mesh.positions.size());
    for (size_t i = 0; i < p.size(); ++i) p[i] = scale * mesh.positions[i] + offset;
    return prepare_mesh(mesh.name, std::move(p), mesh.triangles).mesh;
}

inline Eigen::Quaterniond random_rotation(std::mt19937& rng) {
    std::normal_distribution<double> n;
    // One draw a statement, z first (as GCC ordered them when the tests were written): the
    // order of a call's arguments is the compiler's choice, and a seed must give the same
    // poses from every build.
    const double z = n(rng), y = n(rng), x = n(rng), w = n(rng);
    return Eigen::Quaterniond(w, x, y, z).normalized();
}

inline Eigen::Vector3d random_unit(std::mt19937& rng) {
    std::normal_distribution<double> n;
    const double z = n(rng), y = n(rng), x = n(rng); // as in random_rotation
    return Eigen::Vector3d(x, y, z).normalized();
}

/// A configuration near first contact, in A's object frame: B rotated by `rotation` about
/// `centre` (a point of the object frame, the same for A and B) and moved along `direction`
/// by `distance`, where `contact` is the distance at which the exact level first reports
/// a collision coming in from far away.
struct NearContact {
    Eigen::Quaterniond rotation;
    Eigen::Vector3d direction;
    double contact = 0;
};

/// B's pose in A's frame for a NearContact at `distance` along its direction, rotating about `centre`.
inline Pose pose_at(const NearContact& c, double distance, const Eigen::Vector3d& centre) {
    const Eigen::Vector3d t = centre - c.rotation * centre + distance * c.direction;
    return Pose{c.rotation, t};
}

/// Random near-contact configurations of b against a, both centred on `centre`: marches in
/// from far in steps of 0.5% of the diagonal until the exact level collides, then bisects to
/// 1e-7 of the diagonal.
inline std::vector<NearContact> near_contacts(const CollisionModel& a, const CollisionModel& b, const Eigen::Vector3d& centre,
                                              double diagonal, int count, uint32_t seed) {
    std::mt19937 rng(seed);
    QueryScratch s;
    QueryOptions exact;
    exact.level = QueryLevel::Exact;
    std::vector<NearContact> out;
    while (int(out.size()) < count) {
        NearContact c{random_rotation(rng), random_unit(rng), 0};
        auto hit = [&](double d) { return collide_relative(a, b, pose_at(c, d, centre), exact, s).collide; };
        double far = 2 * diagonal, step = 0.005 * diagonal;
        if (hit(far)) continue;
        double d = far;
        while (d > 0 && !hit(d - step)) d -= step;
        if (d <= step) continue; // passed through the middle without touching: not a contact configuration
        double lo = d - step, hi = d; // lo collides, hi does not
        while (hi - lo > 1e-7 * diagonal) {
            const double mid = 0.5 * (lo + hi);
            (hit(mid) ? lo : hi) = mid;
        }
        c.contact = lo;
        out.push_back(c);
    }
    return out;
}

} // namespace spt::hard
