// Level `exact`: the two triangle trees walked against each other, pruned by bounding
// spheres, then slabs or oriented boxes; leaves decided by exact triangle-triangle tests.
#include "query/query_run.hpp"
#include "query/exact_data.hpp"
#include "geometry/obb.hpp"
#include "geometry/tri_tri.hpp"
#include <tuple>

namespace spt {
namespace {

// True if the sphere (centre c, radius r; n's frame) misses node n's box.
bool sphere_misses_box(const TriangleNode& n, const Eigen::Vector3f& c, float r) {
    const Eigen::Vector3f d = c - Eigen::Vector3f(n.center[0], n.center[1], n.center[2]);
    const Eigen::Vector3f w = third_axis(n.axis[0], n.axis[1]);
    const float along[3] = {Eigen::Vector3f(n.axis[0][0], n.axis[0][1], n.axis[0][2]).dot(d),
                            Eigen::Vector3f(n.axis[1][0], n.axis[1][1], n.axis[1][2]).dot(d), w.dot(d)};
    float out2 = 0;
    for (int k = 0; k < 3; ++k) {
        const float o = std::max(std::abs(along[k]) - n.half[k], 0.0f);
        out2 += o * o;
    }
    return out2 > r * r;
}

// The same against a box in the sphere's frame (B's boxes once moved into A's). Not the node's
// version through TriangleNode::box(): building that box cost the walk 4% (env/rob).
bool sphere_misses_box(const Obb& b, const Eigen::Vector3f& c, float r) {
    const Eigen::Vector3f d = c - Eigen::Vector3f(b.center[0], b.center[1], b.center[2]);
    float out2 = 0;
    for (int k = 0; k < 3; ++k) {
        const float o = std::max(std::abs(b.axis[k][0] * d.x() + b.axis[k][1] * d.y() + b.axis[k][2] * d.z()) - b.half[k], 0.0f);
        out2 += o * o;
    }
    return out2 > r * r;
}

} // namespace

const Eigen::Vector3d& QueryRun::b_vertex(uint32_t v) { return detail::MovedB{s, EB, f}.vertex(v); }

const float* QueryRun::b_tri_sphere(uint32_t tri) { return detail::MovedB{s, EB, f}.tri_sphere(tri); }

const Obb& QueryRun::b_tri_box(uint32_t j) { return detail::MovedB{s, EB, f}.tri_box(j); }

bool QueryRun::triangle_pair(uint32_t ta, uint32_t tb) {
    const float* sa = &EA.tri_sphere[4 * size_t(ta)];
    const float* sb = b_tri_sphere(tb);
    const float dx = sa[0] - sb[0], dy = sa[1] - sb[1], dz = sa[2] - sb[2];
    const float reach = sa[3] + sb[3] + f.margin;
    if (dx * dx + dy * dy + dz * dz > reach * reach) return false;
    ++res.counters.triangle_tests;
    const auto& pa = EA.positions;
    const Triangle& x = EA.triangles[ta];
    const Triangle& y = EB.triangles[tb];
    return triangles_intersect(pa[x[0]], pa[x[1]], pa[x[2]], b_vertex(y[0]), b_vertex(y[1]), b_vertex(y[2]));
}

void QueryRun::run_triangles() {
    const ExactData &ea = EA, &eb = EB;
    const auto &an = ea.tri_nodes, &bn = eb.tri_nodes;
    if (an.empty() || bn.empty()) return;
    const bool any = o.mode != QueryMode::All; // deepest asks the triangles only whether they meet
    auto centre_a = [&](uint32_t i) { return Eigen::Vector3f(an[i].center[0], an[i].center[1], an[i].center[2]); };
    // B's node centres and boxes are moved into A's frame when the walk first needs them, once a query.
    detail::MovedB moved{s, eb, f};
    auto centre_b = [&](uint32_t j) { return moved.tri_node(j).centre; };
    auto& stack = s.stack;
    stack.clear();
    // Field by field: a pair built whole and copied with one wide move waits on its two narrow
    // stores (store forwarding fails; 11% of the walk's time on env/rob).
    auto push = [&stack](uint32_t a, uint32_t b) {
        stack.emplace_back();
        stack.back().first = a, stack.back().second = b;
    };
    // The nearer child pair is taken next without a trip through the stack.
    uint32_t i = 0, j = 0;
    bool carried = true;
    for (;;) {
        if (!carried) {
            if (stack.empty()) break;
            std::tie(i, j) = stack.back();
            stack.pop_back();
        }
        carried = false;
        ++res.counters.node_pairs;
        const TriangleNode &na = an[i], &nb = bn[j];
        const Eigen::Vector3f ca = centre_a(i), cb = centre_b(j);
        const float prune = na.radius + nb.radius + f.margin;
        ++res.counters.bound_tests;
        if ((ca - cb).squaredNorm() > prune * prune) continue;
        ++res.counters.bound_tests;
        if (na.boxed | nb.boxed) { // a rod or a sliver: only a box tells it from a ball
            // Against a compact node, first its ball against the elongated one's box (three
            // projections, in that box's own frame).
            if (!nb.boxed && sphere_misses_box(na, cb, nb.radius + f.margin)) continue;
            const Obb& box_b = b_tri_box(j);
            if (!na.boxed && sphere_misses_box(box_b, ca, na.radius + f.margin)) continue;
            if (obbs_disjoint(na.box(), box_b, f.margin)) continue;
        } else { // each node's slab (box axis 0) against the other's sphere, in A's frame
            const Eigen::Vector3f d = cb - ca;
            if (std::abs(na.axis[0][0] * d.x() + na.axis[0][1] * d.y() + na.axis[0][2] * d.z()) >
                na.half[0] + nb.radius + f.margin)
                continue;
            if (std::abs(moved.tri_node(j).axis0.dot(d)) > nb.half[0] + na.radius + f.margin) continue;
        }
        roots_overlap = true; // the first pair to pass is the roots
        if (na.is_leaf() && nb.is_leaf()) {
            // Against a needle (an elongated leaf, one triangle) each compact triangle of the
            // other leaf is tried by its own sphere against the needle's box first: the
            // needle's sphere is far larger than the needle.
            const bool a_vs_box = nb.boxed && na.count > 1, b_vs_box = na.boxed && nb.count > 1;
            for (uint32_t p = na.first; p < na.first + na.count; ++p) {
                if (a_vs_box) {
                    const float* sa = &ea.tri_sphere[4 * size_t(ea.tri_order[p])];
                    const Eigen::Vector3f c = f.R.transpose() * (Eigen::Vector3f(sa[0], sa[1], sa[2]) - f.t);
                    if (sphere_misses_box(nb, c, sa[3] + f.margin)) continue;
                }
                for (uint32_t q = nb.first; q < nb.first + nb.count; ++q) {
                    if (b_vs_box) {
                        const float* sb = b_tri_sphere(eb.tri_order[q]);
                        if (sphere_misses_box(na, Eigen::Vector3f(sb[0], sb[1], sb[2]), sb[3] + f.margin)) continue;
                    }
                    if (!triangle_pair(ea.tri_order[p], eb.tri_order[q])) continue;
                    res.collide = true;
                    if (any) return;
                    s.tri_pairs.push_back({ea.tri_order[p], eb.tri_order[q]});
                }
            }
            continue;
        }
        // Descend the larger sphere; any takes the nearer child first.
        if (nb.is_leaf() || (!na.is_leaf() && na.radius >= nb.radius)) {
            uint32_t near = i + 1, far = na.first;
            // Nearer child by power |c - p|^2 - r^2: no square roots on the way down.
            if (any && (centre_a(far) - cb).squaredNorm() - an[far].radius * an[far].radius <
                           (centre_a(near) - cb).squaredNorm() - an[near].radius * an[near].radius)
                std::swap(near, far);
            push(far, j);
            i = near, carried = true;
        } else {
            uint32_t near = j + 1, far = nb.first;
            if (any && (centre_b(far) - ca).squaredNorm() - bn[far].radius * bn[far].radius <
                           (centre_b(near) - ca).squaredNorm() - bn[near].radius * bn[near].radius)
                std::swap(near, far);
            push(i, far);
            j = near, carried = true;
        }
    }
}

} // namespace spt
