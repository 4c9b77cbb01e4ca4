// Trees built for a recorded motion: the automatic builder with the motion's split chooser asked
// first at every node, at two weights of the random-pose term, and the automatic build alone; the
// candidate that works least on (a sample of) the recorded steps is kept.
#include "base/parallel.hpp"
#include "motion/motion_split.hpp"
#include "spt/error.hpp"
#include "spt/motion_tree.hpp"
#include <algorithm>

namespace spt {
namespace {

// Nodes of more samples than this try one weight only.
constexpr size_t kOneWeightSamples = size_t(1) << 18;

// The recording with at most `most` of its steps that meet a partner, evenly spread (0: all).
MotionRecording compared_steps(const MotionRecording& rec, int most) {
    MotionRecording few;
    few.scene_file = rec.scene_file, few.object = rec.object, few.object_index = rec.object_index;
    few.tree = rec.tree, few.clip = rec.clip, few.scene = rec.scene, few.model = rec.model;
    std::vector<size_t> met;
    for (size_t k = 0; k < rec.steps.size(); ++k)
        if (!rec.steps[k].partners.empty()) met.push_back(k);
    const size_t n = most > 0 ? std::min(met.size(), size_t(most)) : met.size();
    for (size_t i = 0; i < n; ++i) few.steps.push_back(rec.steps[met[i * met.size() / n]]);
    return few;
}

double work(const MotionCost& c) { return c.mean_node_pairs + c.mean_sphere_tests / kSphereTestsPerNodePair; }

// Builds `tree` under `node` (the whole tree when node is the root of an unsplit tree) with each
// candidate, and leaves in `tree` the one that works least on the motion.
EditResult build_best(SamplingTree& tree, NodeId node, const SampleSet& samples, const MotionRecording& rec,
                      const MotionBuildOptions& options, MotionBuildReport* report) {
    if (rec.contact_steps.size() != samples.size())
        throw Error(ErrorKind::BadInput, "the motion was recorded on " + std::to_string(rec.contact_steps.size()) +
                                             " samples, the tree is over " + std::to_string(samples.size()));
    // A large node tries one weight: the build's time is the chooser's, and a second weight would
    // add as much again.
    const TreeNode* at = tree.find(node);
    const bool large = at && at->samples.size() > kOneWeightSamples;
    std::vector<double> weights{options.random_weight};
    if (!large) weights.push_back(options.random_weight / 4);
    // The candidates are built side by side, each on one thread: the same trees as one after another.
    std::vector<SamplingTree> candidates(weights.size() + 1, tree);
    std::vector<EditResult> done(candidates.size());
    BuildOptions one = options.build;
    one.threads = 1;
    detail::parallel_for(candidates.size(), std::max(1, options.build.threads), [&](size_t k, int) {
        if (k < weights.size()) {
            const detail::MotionSplit chooser(samples, rec, weights[k], options.build.leaf_size);
            done[k] = detail::TreeGraft::build_subtree(candidates[k], node, samples, one, &chooser);
        } else {
            done[k] = candidates[k].build_subtree(node, samples, one);
        }
    }, options.build.tasks);
    for (const EditResult& d : done)
        if (!d) return d;
    const MotionRecording few = compared_steps(rec, options.compare_steps);
    std::vector<const SamplingTree*> compared;
    for (const SamplingTree& t : candidates) compared.push_back(&t);
    std::vector<double> cost(candidates.size(), 0);
    if (!few.steps.empty()) {
        const std::vector<MotionCost> measured = measure_motion_cost(few, compared, QueryOptions{}, 1);
        for (size_t k = 0; k < candidates.size(); ++k) cost[k] = work(measured[k]);
    }
    // Ties go to the earlier candidate: the motion's own weight first, the automatic build last.
    size_t best = 0;
    for (size_t k = 1; k < candidates.size(); ++k)
        if (cost[k] < cost[best]) best = k;
    if (report) {
        const size_t motion = weights.size() > 1 && cost[1] < cost[0] ? 1 : 0;
        *report = {cost[motion], weights[motion], cost.back(), best + 1 == candidates.size()};
    }
    tree = std::move(candidates[best]);
    return {};
}

} // namespace

SamplingTree build_motion_tree(std::string name, const SampleSet& samples, const MotionRecording& recording,
                               const MotionBuildOptions& options, MotionBuildReport* report) {
    SamplingTree tree(std::move(name), uint32_t(samples.size()));
    if (samples.size() <= std::max<uint32_t>(1, options.build.leaf_size)) return build_tree(tree.name(), samples, options.build);
    const EditResult done = build_best(tree, root_id(), samples, recording, options, report);
    if (!done) throw Error(ErrorKind::BadInput, done.reason);
    return tree;
}

EditResult build_motion_subtree(SamplingTree& tree, NodeId node, const SampleSet& samples,
                                const MotionRecording& recording, const MotionBuildOptions& options,
                                MotionBuildReport* report) {
    return build_best(tree, node, samples, recording, options, report);
}

} // namespace spt
