// Fuzz target: queries, backtrack and continuous detection at hostile poses (huge, tiny,
// subnormal, non-finite translations; unnormalised, tiny, zero quaternions; any motion).
// A finite pose with a non-zero quaternion must be answered with finite output; any other
// pose must be refused with Error(BadInput). Hangs show as libFuzzer timeouts.
#include "fuzz_support.hpp"
#include "spt/ccd.hpp"
#include "spt/collision_model.hpp"
#include "spt/convert.hpp"
#include "spt/query.hpp"
#include "spt/response.hpp"
#include "mesh/shapes.hpp"
#include <cmath>
#include <limits>
#include <memory>

namespace {

using namespace spt;

struct Model {
    TriangleMesh mesh;
    SptDocument doc;
    CollisionModel model;
    // A coarse tolerance: few face samples, so building the models stays cheap under ASan.
    explicit Model(TriangleMesh m) : mesh(std::move(m)), doc(make_document(mesh, coarse(mesh))), model(doc, mesh) {}
    static ConvertOptions coarse(const TriangleMesh& m) {
        ConvertOptions o;
        o.tolerance = 0.05 * m.diagonal();
        return o;
    }
};

const Model& model(int k) {
    static const Model torus(make_torus(1.0, 0.35, 12, 6));
    static const Model sheet(make_sheet(2.0, 3)); // open: surfaces only
    return k ? sheet : torus;
}

// Mostly values near contact (small integers / 8), sometimes extremes and raw bit patterns.
double value(fuzz::Bytes& in) {
    const uint8_t kind = in.take<uint8_t>();
    switch (kind % 8) {
    case 0: return in.take<double>();
    case 1: return std::ldexp(double(int8_t(in.take<uint8_t>())), int(in.take<int16_t>() % 1100));
    case 2: return (kind & 8 ? -1 : 1) * std::numeric_limits<double>::max();
    case 3: return (kind & 8 ? -1 : 1) * std::numeric_limits<double>::denorm_min();
    default: return double(int8_t(in.take<uint8_t>())) / 8;
    }
}

Pose pose(fuzz::Bytes& in) {
    Pose p;
    p.translation = {value(in), value(in), value(in)};
    const double w = value(in), x = value(in), y = value(in), z = value(in);
    p.rotation = Eigen::Quaterniond(w, x, y, z); // as given: not normalised
    return p;
}

bool acceptable(const Pose& p) {
    return p.translation.allFinite() && p.rotation.coeffs().allFinite() && p.rotation.coeffs().cwiseAbs().maxCoeff() > 0;
}

// Runs f, which must not throw when `valid`, and may only throw Error(BadInput) otherwise.
template <class F> void run(bool valid, F&& f) {
    try {
        f();
    } catch (const Error& e) {
        if (valid || e.kind() != ErrorKind::BadInput) fuzz::fail(e.what());
    }
}

void check(const QueryResult& r) {
    if (!std::isfinite(r.deepest.depth) || !r.deepest.point.allFinite() || !r.deepest.normal.allFinite())
        fuzz::fail("query gave a non-finite contact");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    fuzz::Bytes in{data, size};
    const uint8_t pick = in.take<uint8_t>();
    const CollisionModel& a = model(pick & 1).model;
    const CollisionModel& b = model((pick >> 1) & 1).model;
    QueryOptions o;
    o.level = QueryLevel((pick >> 2) % 3);
    o.mode = QueryMode((pick >> 4) % 3);
    o.solids = !(pick & 0x40);
    const Pose pa = pose(in), pb = pose(in);
    const Eigen::Vector3d motion(value(in), value(in), value(in));
    const bool valid = acceptable(pa) && acceptable(pb);
    QueryScratch scratch;
    run(valid, [&] { check(collide(a, pa, b, pb, o, scratch)); });
    run(acceptable(pb), [&] { check(collide_relative(a, b, pb, o, scratch)); });
    const bool finite_motion = motion.allFinite();
    if (finite_motion)
        for (BacktrackRule rule : {BacktrackRule::Exact, BacktrackRule::Paper})
            run(valid, [&] {
                const BacktrackResult r = backtrack(a, pa, b, pb, motion, o, rule, scratch);
                if (!std::isfinite(r.distance) || r.distance < 0) fuzz::fail("backtrack gave a bad distance");
            });
    CcdOptions c;
    c.level = o.level == QueryLevel::Bounds ? QueryLevel::Bounds : QueryLevel::Spheres;
    run(acceptable(pa) && acceptable(pb), [&] {
        const CcdResult r = first_contact(a, b, pa, pb, c, scratch);
        if (!(r.toi >= 0 && r.toi <= 1)) fuzz::fail("time of impact outside [0, 1]");
    });
    return 0;
}
