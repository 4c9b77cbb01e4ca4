// Fuzz target: the pose file parser of `spt query` (cli/pose_file.cpp) on any text. Every
// pose it accepts must be finite, within the documented bound, with a unit quaternion.
#include "fuzz_support.hpp"
#include "spt/pose_file.hpp"
#include <cmath>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace spt;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    fuzz::expect_bad_input_only([&] {
        for (const PoseLine& p : parse_poses(in, "fuzz.txt")) {
            if (!p.pose.translation.allFinite() || p.pose.translation.cwiseAbs().maxCoeff() > kMaxCoordinate)
                fuzz::fail("accepted a translation that is not finite or beyond the bound");
            if (!(std::abs(p.pose.rotation.norm() - 1) < 1e-9)) fuzz::fail("accepted pose without a unit quaternion");
            if (p.direction && !p.direction->allFinite()) fuzz::fail("accepted a non-finite direction");
            if (p.line == 0) fuzz::fail("line numbers start at 1");
        }
    });
    return 0;
}
