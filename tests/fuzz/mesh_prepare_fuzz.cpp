// Fuzz target: mesh preparation from raw arrays (prepare_mesh: weld, topology, orientation,
// normals), then conversion, the collision model and a query at every level. Coordinates
// are small integers times a power of two from 2^-1100 to 2^1100 (subnormal to overflow),
// or raw doubles; indices may be out of range.
#include "fuzz_support.hpp"
#include "spt/collision_model.hpp"
#include "spt/convert.hpp"
#include "spt/query.hpp"
#include "spt/spt_file.hpp"
#include <cmath>
#include <vector>

namespace {

double coordinate(spt::fuzz::Bytes& in, int exponent) {
    const uint8_t kind = in.take<uint8_t>();
    if (kind == 0xFF) return in.take<double>(); // any bit pattern: NaN, infinity, subnormal
    return std::ldexp(double(int8_t(in.take<uint8_t>())), exponent + (kind & 7) - 4);
}

void check_mesh(const spt::TriangleMesh& m) {
    for (const auto& p : m.positions)
        if (!p.allFinite()) spt::fuzz::fail("prepared mesh has a non-finite position");
    for (size_t i = 0; i < m.normals.size(); ++i)
        if (!m.normals[i].allFinite() || (m.normal_valid[i] && std::abs(m.normals[i].norm() - 1) > 1e-6))
            spt::fuzz::fail("prepared mesh has a bad normal");
    for (const auto& t : m.triangles)
        for (uint32_t v : t)
            if (v >= m.positions.size()) spt::fuzz::fail("prepared mesh has an index out of range");
}

void convert_and_query(const spt::TriangleMesh& mesh) {
    using namespace spt;
    ConvertOptions options; // coarse: at most a few hundred face samples a face, so an input stays fast
    options.tolerance = 0.05 * mesh.diagonal();
    const SptDocument doc = make_document(mesh, options);
    decode_spt(encode_spt(doc), "round-trip"); // what convert writes, the loader reads
    const CollisionModel m(doc, mesh);
    QueryScratch scratch;
    const Pose near{Eigen::Quaterniond(0.9, 0.1, 0.3, 0.2).normalized(), 0.1 * mesh.diagonal() * Eigen::Vector3d::Ones()};
    for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact}) {
        QueryOptions o;
        o.level = level, o.mode = QueryMode::Deepest;
        const QueryResult r = collide_relative(m, m, near, o, scratch);
        if (!std::isfinite(r.deepest.depth) || !r.deepest.point.allFinite()) fuzz::fail("non-finite contact");
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace spt;
    fuzz::Bytes in{data, size};
    const size_t nv = 1 + in.take<uint8_t>() % 48, nt = 1 + in.take<uint8_t>() % 64;
    const int exponent = int(in.take<int16_t>() % 1100);
    std::vector<Eigen::Vector3d> positions(nv);
    for (auto& p : positions) p = {coordinate(in, exponent), coordinate(in, exponent), coordinate(in, exponent)};
    std::vector<Triangle> triangles(nt);
    for (auto& t : triangles)
        for (auto& v : t) v = in.take<uint8_t>() % (nv + 2); // a few past the end
    const bool convert = in.take<uint8_t>() & 1;
    fuzz::expect_bad_input_only([&] {
        const ImportedMesh m = prepare_mesh("fuzz.obj", positions, triangles);
        check_mesh(m.mesh);
        if (convert) convert_and_query(m.mesh);
    });
    return 0;
}
