// Fuzz target: the .spt loader (decode_spt) on any bytes, as they come and with the length
// and checksums resealed so mutations reach the structural checks. A document that loads
// must build a collision model, answer a query and survive an encode/decode round trip.
#include "fuzz_support.hpp"
#include "spt/collision_model.hpp"
#include "spt/query.hpp"
#include "spt/spt_file.hpp"
#include "spt_reseal.hpp"
#include <cmath>
#include <vector>

namespace {

using spt::test::reseal;

void use(const spt::SptDocument& doc) {
    using namespace spt;
    const std::vector<uint8_t> again = encode_spt(doc);
    if (encode_spt(decode_spt(again, "round-trip")) != again) fuzz::fail("encode/decode round trip changed bytes");
    QueryScratch scratch;
    for (const SamplingTree& tree : doc.trees) {
        const CollisionModel m(doc, tree.name());
        for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres})
            for (QueryMode mode : {QueryMode::Any, QueryMode::All, QueryMode::Deepest}) {
                QueryOptions o;
                o.level = level, o.mode = mode;
                const Pose near{Eigen::Quaterniond(0.9, 0.1, 0.3, 0.2).normalized(), Eigen::Vector3d(0.01, 0, 0)};
                const QueryResult r = collide_relative(m, m, near, o, scratch);
                if (!std::isfinite(r.deepest.depth) || !r.deepest.point.allFinite() || !r.deepest.normal.allFinite())
                    fuzz::fail("query on a loaded document gave a non-finite contact");
            }
    }
}

void load(const std::vector<uint8_t>& bytes) {
    spt::fuzz::expect_bad_input_only([&] { use(spt::decode_spt(bytes, "fuzz.spt")); });
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<uint8_t> bytes(data, data + size);
    load(bytes);
    if (bytes.size() >= 32) {
        reseal(bytes);
        load(bytes);
    }
    return 0;
}
