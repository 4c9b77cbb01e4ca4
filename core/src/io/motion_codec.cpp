// Writing and checked reading of the builds from motion a tree records.
#include "io/motion_codec.hpp"
#include "io/tree_refs.hpp"

namespace spt::detail {
namespace {

constexpr uint32_t kMaxMotionText = 4096; // bytes of a scene path or an object name
constexpr int kMaxMotionSteps = 100000000;

} // namespace

void put_motion_builds(Writer& w, const std::vector<MotionBuildStep>& builds) {
    w.put(uint32_t(builds.size()));
    for (const MotionBuildStep& b : builds) {
        w.put(b.node);
        w.put_string(b.scene);
        w.put_string(b.object);
        w.put(int32_t(b.steps));
        w.put(b.leaf_size);
        w.put(b.after_steps);
    }
}

std::vector<MotionBuildStep> get_motion_builds(Reader& r, const SamplingTree& tree) {
    const auto count = r.get<uint32_t>("motion build count");
    // A build takes at least 28 bytes: a bound before any allocation.
    r.need(uint64_t(count) * 28, std::to_string(count) + " motion builds");
    std::vector<MotionBuildStep> builds(count);
    uint32_t last_after = 0;
    for (MotionBuildStep& b : builds) {
        b.node = get_inner_node_id(r, tree, "motion build node", "motion build under node");
        size_t at = r.offset();
        b.scene = r.get_string("motion build scene", kMaxMotionText);
        if (b.scene.empty()) r.fail(at, "motion build with an empty scene path");
        at = r.offset();
        b.object = r.get_string("motion build object", kMaxMotionText);
        if (b.object.empty()) r.fail(at, "motion build with an empty object name");
        at = r.offset();
        b.steps = r.get<int32_t>("motion build steps");
        if (b.steps < 0 || b.steps > kMaxMotionSteps)
            r.fail(at, "motion build steps " + std::to_string(b.steps) + " outside 0 to " + std::to_string(kMaxMotionSteps));
        at = r.offset();
        b.leaf_size = r.get<uint32_t>("motion build leaf size");
        if (b.leaf_size < 1 || b.leaf_size > (1u << 20))
            r.fail(at, "motion build leaf size " + std::to_string(b.leaf_size) + " outside 1 to 1048576");
        at = r.offset();
        b.after_steps = r.get<uint32_t>("motion build place");
        if (b.after_steps > tree.recipe().size() || b.after_steps < last_after)
            r.fail(at, "motion build place " + std::to_string(b.after_steps) + " is not within the tree's " +
                           std::to_string(tree.recipe().size()) + " recipe steps in order");
        last_after = b.after_steps;
    }
    return builds;
}

} // namespace spt::detail
