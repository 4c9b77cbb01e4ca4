// The sphere level's last word on a two-sided sample, with the mesh at hand: the sample
// stands for its patch of open surface, which lies on its face (a face sample) or on the
// faces around it (a vertex sample). Its disc spills past the face's edges by up to its
// radius; the faces do not, so a pair whose discs meet only past an edge is let go.
#include "query/query_run.hpp"
#include "query/exact_data.hpp"
#include "geometry/tri_tri.hpp"
#include "geometry/triangle_bvh.hpp"
#include "spt/samples.hpp"

namespace spt {
namespace {

// More face pairs than this around two vertex samples: keep the pair (a cone's apex).
constexpr uint32_t kMaxFacePairs = 64;

// The faces a two-sided sphere's patch lies on: [first, first + count) of `list`, or `one`.
struct Faces {
    const uint32_t* list;
    uint32_t count;
    uint32_t one;
    uint32_t operator[](uint32_t k) const { return list ? list[k] : one; }
};

Faces faces_of(const ExactData& e, uint32_t sphere) {
    const uint32_t src = e.sphere_source[sphere];
    const uint32_t index = src & kMaxSourceIndex;
    if (src & kFaceSampleBit) return {nullptr, 1, index};
    if (index + 1 >= e.vertex_face_start.size()) return {nullptr, 0, 0};
    const uint32_t first = e.vertex_face_start[index];
    return {e.vertex_faces.data() + first, e.vertex_face_start[index + 1] - first, 0};
}

} // namespace

bool QueryRun::pieces_touch(uint32_t sa, uint32_t sb, bool disc_a, bool disc_b, const Eigen::Vector3f& ca,
                            const Eigen::Vector3f& cb, float ra, float rb) {
    const bool face_a = disc_a && !EA.sphere_source.empty(), face_b = disc_b && !EB.sphere_source.empty();
    if (!face_a && !face_b) return true;
    const Faces fa = face_a ? faces_of(EA, sa) : Faces{nullptr, 0, 0};
    const Faces fb = face_b ? faces_of(EB, sb) : Faces{nullptr, 0, 0};
    auto a_corner = [&](uint32_t t, int k) { return EA.positions[EA.triangles[t][k]]; };
    auto b_corner = [&](uint32_t t, int k) { return b_vertex(EB.triangles[t][k]); };
    if (face_a && face_b) {
        if (uint64_t(fa.count) * fb.count > kMaxFacePairs) return true;
        for (uint32_t p = 0; p < fa.count; ++p)
            for (uint32_t q = 0; q < fb.count; ++q) {
                const uint32_t ta = fa[p], tb = fb[q];
                if (piece_memo.valid && piece_memo.a == ta && piece_memo.b == tb) {
                    if (piece_memo.meet) return true;
                    continue;
                }
                ++res.counters.triangle_tests;
                const bool meet = triangles_intersect(a_corner(ta, 0), a_corner(ta, 1), a_corner(ta, 2), b_corner(tb, 0),
                                                      b_corner(tb, 1), b_corner(tb, 2));
                piece_memo = {ta, tb, meet, true};
                if (meet) return true;
            }
        return false;
    }
    // One patch against a ball: some face of the patch within the ball's radius of its centre
    // (with the frame's rounding margin, as the walk prunes).
    const Faces& faces = face_a ? fa : fb;
    const Eigen::Vector3d centre = (face_a ? cb : ca).cast<double>();
    const double reach = double(face_a ? rb : ra) + double(f.margin);
    for (uint32_t k = 0; k < faces.count; ++k) {
        const uint32_t t = faces[k];
        const Eigen::Vector3d x = face_a ? a_corner(t, 0) : b_corner(t, 0), y = face_a ? a_corner(t, 1) : b_corner(t, 1),
                              z = face_a ? a_corner(t, 2) : b_corner(t, 2);
        if ((detail::closest_on_triangle(centre, x, y, z) - centre).squaredNorm() <= reach * reach) return true;
    }
    return faces.count == 0; // no faces known: the disc's answer stands
}

} // namespace spt
