// The reference every tree query is tested against: no hierarchy, every pair.
#include "query_internal.hpp"
#include "spt/sphere_block.hpp"
#include "spt/tri_tri.hpp"
#include <cmath>

namespace spt {

void sphere_radii(const CompactTree& t, std::vector<float>& out) {
    out.assign(t.sphere_count(), 0);
    for (const CompactNode& n : t.nodes())
        for (uint32_t k = n.first; n.is_active() && k < n.first + n.count; ++k) out[k] = n.ss_radius;
}

QueryResult collide_brute_force(const CollisionModel& a, const CollisionModel& b, const Pose& b_in_a,
                                const QueryOptions& options, QueryScratch& scratch) {
    QueryRun run(a, b, b_in_a, options, scratch);
    const auto &an = a.tree().nodes(), &bn = b.tree().nodes();
    const QueryMode mode = options.mode;
    auto done = [&] { return run.res.collide && mode == QueryMode::Any; };
    if (options.level == QueryLevel::Bounds) {
        for (uint32_t i = 0; i < an.size() && !done(); ++i)
            for (uint32_t j = 0; j < bn.size() && an[i].is_active() && !done(); ++j) {
                if (!bn[j].is_active()) continue;
                ++run.res.counters.bound_tests;
                const Eigen::Vector3f ca(an[i].center[0], an[i].center[1], an[i].center[2]);
                const Eigen::Vector3f cb = run.b_node_centre(j);
                const float sum = an[i].bv_radius + bn[j].bv_radius + options.inflate;
                const float d2 = (ca - cb).squaredNorm();
                if (!(d2 < sum * sum)) continue;
                run.res.collide = true;
                run.record(i, j, ca, cb, sum, an[i].bv_radius, d2);
            }
    } else if (options.level == QueryLevel::Spheres) {
        for (uint32_t j = 0; j < bn.size(); ++j)
            if (bn[j].is_active()) run.move_block(j);
        std::vector<float> ra, rb;
        sphere_radii(a.tree(), ra);
        sphere_radii(b.tree(), rb);
        const uint32_t nb = uint32_t(b.tree().sphere_count());
        std::vector<float> row(sphere_block_stride(nb));
        const QueryScratch& s = scratch;
        for (uint32_t i = 0; i < a.tree().sphere_count() && !done(); ++i) {
            const float *x = a.tree().x() + i, *y = a.tree().y() + i, *z = a.tree().z() + i;
            sphere_block_d2(x, y, z, 1, s.bx_.data(), s.by_.data(), s.bz_.data(), nb, row.data());
            run.res.counters.sphere_tests += nb;
            for (uint32_t k = 0; k < nb && !done(); ++k) {
                const float reach = ra[i] + rb[k] + options.inflate;
                if (!(row[k] < reach * reach)) continue;
                run.res.collide = true;
                run.record(i, k, Eigen::Vector3f(*x, *y, *z), Eigen::Vector3f(s.bx_[k], s.by_[k], s.bz_[k]), reach,
                           ra[i], row[k]);
            }
        }
    } else {
        const ExactData &ea = a.exact(), &eb = b.exact();
        for (uint32_t p = 0; p < ea.triangles.size() && !done(); ++p)
            for (uint32_t q = 0; q < eb.triangles.size() && !done(); ++q) {
                const Triangle &x = ea.triangles[p], &y = eb.triangles[q];
                ++run.res.counters.triangle_tests;
                if (!triangles_intersect(ea.positions[x[0]], ea.positions[x[1]], ea.positions[x[2]],
                                         run.b_vertex(y[0]), run.b_vertex(y[1]), run.b_vertex(y[2])))
                    continue;
                run.res.collide = true;
                if (mode == QueryMode::All) scratch.tri_pairs_.push_back({p, q});
            }
    }
    if (!run.have_best) run.res.deepest = Contact{};
    return run.res;
}

} // namespace spt
