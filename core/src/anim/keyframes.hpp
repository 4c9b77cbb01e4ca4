#pragma once
// A track's value at a time: the key interval found by binary search, then the file's
// interpolation (glTF 2.0 appendix C for the cubic spline).
#include "spt/animation.hpp"
#include <algorithm>
#include <cmath>

namespace spt::detail {

// Where `t` falls among ascending `times` (at least one): the interval [k, k + 1] and how far
// along it (0..1); before the first key or after the last, that key and 0.
struct KeySpan {
    size_t k = 0;
    double s = 0;
    double span = 0; // seconds from key k to key k + 1 (0 at the ends)
};

inline KeySpan find_span(const std::vector<double>& times, double t) {
    if (!(t > times.front())) return {0, 0, 0}; // also a NaN time: the first key
    if (t >= times.back()) return {times.size() - 1, 0, 0};
    const size_t k = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    const double span = times[k + 1] - times[k];
    return {k, span > 0 ? (t - times[k]) / span : 0, span};
}

// Cubic Hermite of glTF's CUBICSPLINE: values v0, v1, out-tangent b0 of key k, in-tangent a1 of k + 1.
template <class V>
V hermite(const V& v0, const V& b0, const V& v1, const V& a1, double s, double span) {
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * v0 + (span * (s3 - 2 * s2 + s)) * b0 + (-2 * s3 + 3 * s2) * v1 + (span * (s3 - s2)) * a1;
}

// Poses taken across a clip, every 1/frames_per_second seconds with both ends: pose k of
// count + 1 is at time(k). At most 10,000 intervals, so a clip of hours is measured more coarsely,
// not forever; a rate that is not a positive number is `fallback`.
struct ClipPoses {
    ClipPoses(const Clip& clip, double frames_per_second, double fallback)
        : duration(clip.duration),
          count(int(std::clamp(std::ceil(clip.duration * (frames_per_second > 0 && std::isfinite(frames_per_second)
                                                             ? frames_per_second
                                                             : fallback)),
                               1.0, 10000.0))) {}
    double time(int k) const { return duration * double(k) / double(count); }
    double duration;
    int count; // intervals: count + 1 poses
};

// Translation or scale at t (the track is not empty).
Eigen::Vector3d sample_vector(const Track<Eigen::Vector3d>& track, double t);
// Rotation at t as a unit quaternion (slerp along the shorter arc; a cubic spline renormalised).
Eigen::Quaterniond sample_rotation(const Track<Eigen::Vector4d>& track, double t);
// Morph weights at t, `count` of them.
void sample_weights(const Track<std::vector<double>>& track, double t, size_t count, std::vector<double>& out);

} // namespace spt::detail
