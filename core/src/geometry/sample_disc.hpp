#pragma once
// The sphere level's shape of a two-sided sample: the disc of its face, not its ball.
// A two-sided sphere is centred on an open surface, so two sheets passing within the sum of
// their radii would collide as balls though they never meet; as discs they collide only where
// the faces' planes come within the discs' small thickness. A face's discs still hold every
// point of the face (docs/sampling.md, "Open parts"), so crossing surfaces always collide.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace spt::detail {

// Half-thickness of a sample disc as a fraction of its radius. The disc's normal is the face
// normal stored as snorm8 (tilted by up to 0.007 rad), and the disc must still hold the points
// of its face within 0.9 of its radius from the centre: 0.9 x 0.007 = 1/160, kept with room.
constexpr float kDiscHalfThickness = 1.0f / 64;

// A sampling sphere at a leaf hit, or all of a node's, in one frame: centre, unit normal (an
// axis for a disc), radius, half-thickness, and whether it is a disc (two-sided spheres) or a
// ball. A sample's disc is kDiscHalfThickness*r thick; a node's holds its samples' discs.
struct LeafShape {
    Eigen::Vector3f c, n;
    float r;
    float t;
    bool disc;
};

// False only when shapes a and b, each grown by pad/2, cannot share a point: a ball is the
// sphere, a disc is the set within r of its centre and within t of its plane.
// Conservative: every test below separates only what is surely apart, so it may keep a pair
// that is in fact apart but never drops one that touches.
inline bool leaf_shapes_may_touch(const LeafShape& a, const LeafShape& b, float pad) {
    if (!a.disc && !b.disc) return true; // the caller's sphere test decided
    const Eigen::Vector3f d = b.c - a.c;
    const float half = 0.5f * pad;
    const float ta = a.disc ? a.t + half : 0, tb = b.disc ? b.t + half : 0;
    if (!b.disc || !a.disc) {
        // Disc against ball: the ball's centre within its radius (plus the disc's thickness) of the thin disc.
        const LeafShape& disc = a.disc ? a : b;
        const float reach = (a.disc ? b.r : a.r) + pad + (a.disc ? ta : tb) - half;
        const float h = disc.n.dot(d);
        const float q = std::sqrt(std::max(0.0f, d.squaredNorm() - h * h));
        const float e = std::max(0.0f, q - disc.r);
        return h * h + e * e <= reach * reach;
    }
    // Two discs. Each lies within its thickness of its plane; along the other's normal it
    // reaches r*sin(angle) + thickness, and never more than its radius.
    const Eigen::Vector3f x = a.n.cross(b.n);
    const float s = std::min(1.0f, x.norm());
    const float ha = a.n.dot(d), hb = b.n.dot(d);
    if (std::abs(ha) > ta + std::min(b.r + half, b.r * s + tb)) return false;
    if (std::abs(hb) > tb + std::min(a.r + half, a.r * s + ta)) return false;
    if (!(s > 1e-3f)) return true; // nearly parallel: the slabs above decided
    // Crossing planes: a common point lies within rho of the planes' line L and within each
    // disc's radius, so along L it lies on both discs' chords, widened by rho.
    const Eigen::Vector3f u = x / s;
    const float rho = (ta + tb) / s;
    const float ra = a.r + half, rb = b.r + half;
    const float off_a = std::max(0.0f, std::abs(hb) / s - rho), off_b = std::max(0.0f, std::abs(ha) / s - rho);
    if (off_a > ra || off_b > rb) return false;
    const float chord_a = std::sqrt(ra * ra - off_a * off_a), chord_b = std::sqrt(rb * rb - off_b * off_b);
    return std::abs(u.dot(d)) <= chord_a + chord_b;
}

} // namespace spt::detail
