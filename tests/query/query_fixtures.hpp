#pragma once
// Small models and poses shared by the query tests.
#include "spt/collision_model.hpp"
#include "spt/convert.hpp"
#include "spt/pose.hpp"
#include "mesh/shapes.hpp"
#include <memory>
#include <random>

namespace spt::test {

// A mesh, its document and a model with the exact level.
struct Object {
    TriangleMesh mesh;
    SptDocument doc;
    CollisionModel model;
};

// Vertex samples only: the fixtures are small on purpose (brute force is quadratic).
inline ConvertOptions coarse() {
    ConvertOptions o;
    o.auto_tolerance = false;
    return o;
}

inline std::unique_ptr<Object> make_object(TriangleMesh mesh, const ConvertOptions& opt = coarse()) {
    auto o = std::make_unique<Object>();
    o->mesh = std::move(mesh);
    o->doc = make_document(o->mesh, opt);
    o->model = CollisionModel(o->doc, o->mesh);
    return o;
}

/// The torus most query tests pose against itself (ring 1, tube 0.35, 20 x 10), made once.
inline const Object& torus() {
    static const auto o = make_object(make_torus(1.0, 0.35, 20, 10));
    return *o;
}

inline Eigen::Quaterniond random_rotation(std::mt19937& rng) {
    std::normal_distribution<double> n;
    Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
    return q.normalized();
}

inline Eigen::Vector3d random_unit(std::mt19937& rng) {
    std::normal_distribution<double> n;
    Eigen::Vector3d v(n(rng), n(rng), n(rng));
    return v.normalized();
}

// B's pose in A's frame: centre at `distance` in a random direction, random orientation.
inline Pose random_pose(std::mt19937& rng, double distance) {
    return Pose::from(distance * random_unit(rng), random_rotation(rng));
}

} // namespace spt::test
