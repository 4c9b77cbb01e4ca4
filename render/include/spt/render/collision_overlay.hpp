#pragma once
/// Filling a CollisionOverlay. A query at level Spheres in mode All leaves its
/// colliding pairs in spt::QueryScratch::pairs() as sphere indices in CompactTree
/// order; world_spheres gives each tree's spheres in that order, and
/// make_sphere_pair turns one pair of them into what the overlay draws.
/// overlapping_pairs finds every pair without a tree or the query: a reference
/// for tests and small scenes.
#include "spt/compact_tree.hpp"
#include "spt/render/frame.hpp"
#include <vector>

namespace spt::render {

/// The sampling spheres of `compact`, moved into the object frame by its local origin, then
/// into the world by `pose` (rigid, object to world), in CompactTree order: index k is
/// sphere k. Model units.
std::vector<Sphere> world_spheres(const CompactTree& compact, const Eigen::Affine3f& pose);

/// The pair record of spheres a and b (same frame, usually the world): depth =
/// ra + rb - |cb - ca| (model units), normal from a towards b (+Y if the centres
/// coincide), contact midway through the overlap on the line of centres.
SpherePair make_sphere_pair(const Sphere& a, const Sphere& b);

/// Every (i, j) with a[i] and b[j] overlapping (depth > 0), ordered by i then j, in
/// the frame of a and b: the pairs of testing every sphere of a against every sphere of
/// b, found by a sweep along x (O((|a| + |b|) log |b|) plus the spheres each one's x
/// window holds).
std::vector<SpherePair> overlapping_pairs(const std::vector<Sphere>& a, const std::vector<Sphere>& b);

} // namespace spt::render
