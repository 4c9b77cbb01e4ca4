// The reference every tree query is tested against: no hierarchy, every pair.
#include "query/model_access.hpp"
#include "query/pending_pose.hpp"
#include "query/brute_force.hpp"
#include "query/query_run.hpp"
#include "query/exact_data.hpp"
#include "geometry/sphere_block.hpp"
#include "geometry/tri_tri.hpp"
#include <algorithm>
#include <cmath>
#include <vector>

namespace spt {

QueryResult collide_brute_force(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                                const QueryOptions& options, QueryScratch& scratch) {
    detail::settle(a), detail::settle(b); // a lazy pose is posed in full first
    QueryRun run(a, b, b_in_a, options, scratch);
    const auto &an = a.tree().nodes(), &bn = b.tree().nodes();
    const QueryMode mode = options.mode;
    auto done = [&] { return run.res.collide && mode == QueryMode::Any; };
    if (options.level == QueryLevel::Bounds) {
        // B's node centres moved once, not once a pair: the same floats, an n + m cost.
        std::vector<Eigen::Vector3f> b_centre(bn.size());
        for (uint32_t j = 0; j < bn.size(); ++j) b_centre[j] = run.b_node_centre(j);
        for (uint32_t i = 0; i < an.size() && !done(); ++i)
            for (uint32_t j = 0; j < bn.size() && an[i].is_active() && !done(); ++j) {
                if (!bn[j].is_active()) continue;
                ++run.res.counters.bound_tests;
                const Eigen::Vector3f ca(an[i].center[0], an[i].center[1], an[i].center[2]);
                const Eigen::Vector3f& cb = b_centre[j];
                const float sum = an[i].bv_radius + bn[j].bv_radius + options.inflate;
                const float d2 = (ca - cb).squaredNorm();
                if (!(d2 < sum * sum)) continue;
                run.res.collide = true;
                run.record(i, j, i, j, ca, cb, sum, an[i].bv_radius, d2);
            }
    } else if (options.level == QueryLevel::Spheres) {
        // Every sphere as one column per coordinate, B's moved as the tree query moves them.
        const size_t na = a.tree().sphere_count(), nb = b.tree().sphere_count();
        std::vector<float> ax(na), ay(na), az(na), bx(nb + 8), by(nb + 8), bz(nb + 8), ra(na), rb(nb);
        std::vector<uint32_t> node_a(na), node_b(nb);
        for (uint32_t i = 0; i < an.size(); ++i)
            for (uint32_t k = an[i].first; an[i].is_active() && k < an[i].first + an[i].count; ++k) {
                const Eigen::Vector3f c = a.tree().sphere_center(an[i], k);
                ax[k] = c.x(), ay[k] = c.y(), az[k] = c.z(), ra[k] = an[i].ss_radius, node_a[k] = i;
            }
        // In sphere order: what a leaf's move spills past its count, the next leaf overwrites.
        for (uint32_t j = 0; j < bn.size(); ++j) {
            if (!bn[j].is_active()) continue;
            const uint32_t k = bn[j].first;
            run.move_leaf(j, &bx[k], &by[k], &bz[k]);
            std::fill(rb.begin() + k, rb.begin() + k + bn[j].count, bn[j].ss_radius);
            std::fill(node_b.begin() + k, node_b.begin() + k + bn[j].count, j);
        }
        std::vector<float> row(sphere_block_stride(uint32_t(nb)));
        for (uint32_t i = 0; i < na && !done(); ++i) {
            sphere_block_d2(&ax[i], &ay[i], &az[i], 1, bx.data(), by.data(), bz.data(), uint32_t(nb), row.data());
            run.res.counters.sphere_tests += nb;
            // Most rows meet nothing: a pass with no early exit (which the compiler vectorises)
            // says so before the per-pair loop, with the same comparison.
            const float ra_i = ra[i], inflate = options.inflate;
            const float *rb_k = rb.data(), *d2_k = row.data();
            int near = 0;
            for (size_t k = 0; k < nb; ++k) {
                const float reach = ra_i + rb_k[k] + inflate;
                near |= d2_k[k] < reach * reach;
            }
            if (!near) continue;
            for (uint32_t k = 0; k < nb && !done(); ++k) {
                const float reach = ra[i] + rb[k] + options.inflate;
                if (!(row[k] < reach * reach)) continue;
                if (!run.shapes_touch(i, k, Eigen::Vector3f(ax[i], ay[i], az[i]), Eigen::Vector3f(bx[k], by[k], bz[k]),
                                      ra[i], rb[k]))
                    continue;
                run.res.collide = true;
                run.record(node_a[i], node_b[k], i, k, Eigen::Vector3f(ax[i], ay[i], az[i]),
                           Eigen::Vector3f(bx[k], by[k], bz[k]), reach, ra[i], row[k]);
            }
        }
    } else {
        const ExactData &ea = detail::exact_of(a), &eb = detail::exact_of(b);
        for (uint32_t p = 0; p < ea.triangles.size() && !done(); ++p)
            for (uint32_t q = 0; q < eb.triangles.size() && !done(); ++q) {
                const Triangle &x = ea.triangles[p], &y = eb.triangles[q];
                ++run.res.counters.triangle_tests;
                if (!triangles_intersect(ea.positions[x[0]], ea.positions[x[1]], ea.positions[x[2]],
                                         run.b_vertex(y[0]), run.b_vertex(y[1]), run.b_vertex(y[2])))
                    continue;
                run.res.collide = true;
                if (mode == QueryMode::All) detail::buffers_of(scratch).tri_pairs.push_back({p, q});
            }
    }
    run.roots_overlap = true; // no tree: containment is asked whenever nothing else met
    run.check_containment();
    return run.res;
}

} // namespace spt
