#pragma once
// NumPy arrays of poses and motion directions to core's types, every row checked as `spt query`
// checks a pose file's lines (spt/pose_file.hpp), the argument and row named in the message.
#include "spt/pose.hpp"
#include <pybind11/numpy.h>
#include <vector>

namespace spt::python {

/// B's poses in A's frame from an N x 7 (tx ty tz qw qx qy qz) or N x 4 x 4 (rigid transform)
/// array of numbers; ValueError or TypeError naming `name` and the row for anything else.
std::vector<Pose> poses_from_array(const pybind11::handle& array, const char* name);

/// B's motion directions from an N x 3 array of finite numbers, N = `rows`.
std::vector<Eigen::Vector3d> directions_from_array(const pybind11::handle& array, const char* name, size_t rows);

} // namespace spt::python
