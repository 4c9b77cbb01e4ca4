// SampleSet: samples snapped to the precision the .spt file stores.
#include "spt/samples.hpp"
#include "sampling/encoding.hpp"

namespace spt {

void SampleSet::add(const Eigen::Vector3f& p, const Eigen::Vector3f& n, uint32_t source, float s, float r_max) {
    points.push_back(p);
    normals.push_back(decode_normal(encode_normal(n)));
    sources.push_back(source);
    spacing.push_back(decode_length(encode_length(s, false)));
    max_radius.push_back(decode_length(encode_length(r_max, true)));
}

} // namespace spt
