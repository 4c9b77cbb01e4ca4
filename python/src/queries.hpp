#pragma once
// spt.collide, spt.distance and spt.backtrack: keyword arguments to core's options, one batch of
// core's (the GIL released while it runs), and the answers as NumPy arrays.
#include "model.hpp"
#include <pybind11/numpy.h>
#include <string>

namespace spt::python {

/// What `spt query`'s options say of a collision query (--level, --surfaces, --culling, --cull-angle).
struct CollideArgs {
    std::string level = "spheres";
    bool surfaces = false;
    bool culling = false;
    double cull_angle = 60;
    int threads = 0;
};

/// spt.collide: query_batch in mode `any`, a bool a pose.
pybind11::array_t<bool> collide(const Model& a, const Model& b, const pybind11::handle& poses, const CollideArgs& args);

/// spt.distance: distance_batch, a float64 a pose (+inf beyond max_distance), with the points when
/// asked: a tuple (distance, points_a, points_b), N x 3 in A's frame, NaN where beyond.
pybind11::object distance(const Model& a, const Model& b, const pybind11::handle& poses, const std::string& level,
                          double max_distance, double relative_error, double absolute_error, bool depth,
                          int threads, bool return_points);

/// spt.backtrack: backtrack_relative at every pose along its direction (`spt query`'s backtrack
/// column), +inf where the search passed max_distance; the poses shared out over `threads` jobs.
pybind11::array_t<double> backtrack(const Model& a, const Model& b, const pybind11::handle& poses,
                                    const pybind11::handle& directions, const CollideArgs& args,
                                    const std::string& rule, double max_distance);

/// Seconds one query_batch of spt.collide's takes inside C++, the poses converted before the clock
/// starts: the benchmark's reference for the binding's own cost (python/bench_collide.py).
double time_collide_batch(const Model& a, const Model& b, const pybind11::handle& poses, const CollideArgs& args);

} // namespace spt::python
