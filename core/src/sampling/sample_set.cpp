// SampleSet: samples snapped to the precision the .spt file stores.
#include "spt/samples.hpp"
#include "sampling/encoding.hpp"

namespace spt {

void SampleSet::add(const Eigen::Vector3f& p, const Eigen::Vector3f& n, uint32_t source, float s, float r_max) {
    points.push_back(p);
    normals.push_back(snap_normal(n));
    sources.push_back(source);
    spacing.push_back(snap_length(s, false));
    max_radius.push_back(snap_length(r_max, true));
}

void SampleSet::append(const SampleSet& other) {
    points.insert(points.end(), other.points.begin(), other.points.end());
    normals.insert(normals.end(), other.normals.begin(), other.normals.end());
    sources.insert(sources.end(), other.sources.begin(), other.sources.end());
    spacing.insert(spacing.end(), other.spacing.begin(), other.spacing.end());
    max_radius.insert(max_radius.end(), other.max_radius.begin(), other.max_radius.end());
}

} // namespace spt
