// Compact stored forms of sample data: octahedral normals and bfloat16 lengths.
#include "sampling/encoding.hpp"
#include "base/float_round.hpp"
#include <algorithm>
#include <cmath>
#include <cstring>

namespace spt {
namespace {

// std::round's value, without a library call per coordinate (NaN, from an infinite input
// normal: 0, where rounding it to an integer would be undefined).
int16_t to_snorm16(float v) { return int16_t(detail::round_half_away(std::clamp(v, -1.0f, 1.0f) * 32767.0f)); }

} // namespace

uint32_t encode_normal(const Eigen::Vector3f& n_in) {
    // Octahedral map: project onto |x|+|y|+|z| = 1, fold the lower half over.
    Eigen::Vector3f n = n_in;
    const float l1 = std::abs(n.x()) + std::abs(n.y()) + std::abs(n.z());
    if (!(l1 > 0)) n = Eigen::Vector3f(0, 0, 1);
    else n /= l1;
    float u = n.x(), v = n.y();
    if (n.z() < 0) {
        const float ou = u, ov = v;
        u = (1.0f - std::abs(ov)) * (ou >= 0 ? 1.0f : -1.0f);
        v = (1.0f - std::abs(ou)) * (ov >= 0 ? 1.0f : -1.0f);
    }
    const auto qu = uint16_t(to_snorm16(u));
    const auto qv = uint16_t(to_snorm16(v));
    return uint32_t(qu) | (uint32_t(qv) << 16);
}

Eigen::Vector3f decode_normal(uint32_t code) {
    const float u = std::max(-1.0f, float(int16_t(code & 0xffff)) / 32767.0f);
    const float v = std::max(-1.0f, float(int16_t(code >> 16)) / 32767.0f);
    Eigen::Vector3f n(u, v, 1.0f - std::abs(u) - std::abs(v));
    if (n.z() < 0) {
        const float ou = n.x(), ov = n.y();
        n.x() = (1.0f - std::abs(ov)) * (ou >= 0 ? 1.0f : -1.0f);
        n.y() = (1.0f - std::abs(ou)) * (ov >= 0 ? 1.0f : -1.0f);
    }
    return n.normalized();
}

uint16_t encode_length(float v, bool round_down) {
    if (!(v >= 0)) v = 0;
    if (std::isinf(v)) return 0x7f80;
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    if (!round_down) bits += 0x7fff + ((bits >> 16) & 1); // round half to even
    return uint16_t(std::min<uint32_t>(bits >> 16, 0x7f80));
}

float decode_length(uint16_t code) {
    const uint32_t bits = uint32_t(code) << 16;
    float v;
    std::memcpy(&v, &bits, 4);
    return v;
}

} // namespace spt
