// Stopping the automatic builder from outside (an editor's Cancel build): build_tree and
// build_subtree throw Cancelled and leave the tree they were asked to change as it was.
#include "spt/error.hpp"
#include "spt/recipe.hpp"
#include "spt/spt_file.hpp"
#include "spt/tree_builder.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>
#include <random>

using namespace spt;

namespace {

// `n` samples scattered through a unit cube: the builder reads only points, spacing and radius.
SampleSet scattered(size_t n) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0, 1);
    SampleSet s;
    for (size_t i = 0; i < n; ++i)
        s.add({u(rng), u(rng), u(rng)}, Eigen::Vector3f::UnitZ(), uint32_t(i), 0.01f);
    return s;
}

std::vector<uint8_t> bytes(const SamplingTree& t, const SampleSet& s) {
    SptDocument d;
    d.samples = s;
    d.trees = {t};
    return encode_spt(d);
}

} // namespace

TEST(BuildCancel, AFlagSetBeforeTheCallStopsBuildTreeAndBuildSubtreeLeavesTheTree) {
    const SampleSet s = scattered(5000);
    std::atomic<bool> cancel{true};
    BuildOptions o;
    o.cancel = &cancel;
    EXPECT_THROW(build_tree("t", s, o), Cancelled);
    SamplingTree t = unsplit_tree("t", s);
    const std::vector<uint8_t> before = bytes(t, s);
    EXPECT_THROW(t.build_subtree(root_id(), s, o), Cancelled);
    EXPECT_EQ(bytes(t, s), before);
    // A node too small to look at the flag while it is split still stops before its radii.
    const SampleSet few = scattered(100);
    EXPECT_THROW(build_tree("t", few, o), Cancelled);
}

TEST(BuildCancel, AFlagSetWhileALargeTreeIsBuiltStopsItOnOneThreadOrMore) {
    // 300,000 samples take far longer to build than the other thread needs to set the flag;
    // before the builder looked at it, the build ran to its end.
    const SampleSet s = scattered(300000);
    for (int threads : {1, 2}) {
        std::atomic<bool> cancel{false};
        BuildOptions o;
        o.cancel = &cancel;
        o.threads = threads;
        test::CancelFromAnotherThread canceller(cancel);
        canceller.start();
        EXPECT_THROW(build_tree("t", s, o), Cancelled) << threads << " thread(s)";
    }
}

TEST(BuildCancel, AFlagLeftUnsetBuildsTheSameTree) {
    const SampleSet s = scattered(20000);
    std::atomic<bool> cancel{false};
    BuildOptions o;
    o.threads = 2;
    const SamplingTree plain = build_tree("t", s, o);
    o.cancel = &cancel;
    EXPECT_EQ(bytes(build_tree("t", s, o), s), bytes(plain, s));
}
