// replay_recipe: the recorded strokes of every manual split select again on new samples.
#include "spt/recipe.hpp"
#include "spt/selection.hpp"

namespace spt {

SamplingTree unsplit_tree(const std::string& name, const SampleSet& samples) {
    SamplingTree tree(name, uint32_t(samples.size()));
    tree.assign_radii(samples, RadiusRule{});
    tree.compute_bounds(samples, BoundsMethod::Tight);
    return tree;
}

SamplingTree replay_recipe(const SamplingTree& authored, const SampleSet& samples, const TriangleMesh& mesh,
                           ReplayReport* report) {
    ReplayReport local;
    ReplayReport& out = report ? *report : local;
    SamplingTree tree = unsplit_tree(authored.name(), samples);
    const auto& steps = authored.recipe();
    for (size_t k = 0; k < steps.size(); ++k) {
        const RecipeStep& step = steps[k];
        const std::string which = "step " + std::to_string(k + 1) + " (split of node " + std::to_string(step.node) + ")";
        const TreeNode* n = tree.find(step.node);
        if (!n) {
            out.skipped.push_back(which + ": the node does not exist, an earlier step was not replayed");
            continue;
        }
        const EditResult r = tree.split(step.node, select_strokes(samples, tree, step, &mesh), samples);
        if (!r) {
            out.skipped.push_back(which + ": " + r.reason);
            continue;
        }
        tree.add_recipe_step(step);
        ++out.replayed;
    }
    return tree;
}

} // namespace spt
