// replay_recipe: the recorded strokes of every manual split select again on new samples, at the
// pose each split was made at.
#include "spt/recipe.hpp"
#include "selection/step_poses.hpp"
#include "spt/selection.hpp"
#include "spt/spt_file.hpp"
#include <optional>

namespace spt {
namespace {

SamplingTree replay(const SamplingTree& authored, const SampleSet& samples, detail::StepPoses& poses,
                    ReplayReport* report) {
    ReplayReport local;
    ReplayReport& out = report ? *report : local;
    SamplingTree tree = unsplit_tree(authored.name(), samples);
    const auto& steps = authored.recipe();
    // Linked, grow and shrink read the mesh's adjacency: made once, only for a recipe that has them.
    std::optional<SampleAdjacency> adjacency;
    for (const RecipeStep& step : steps)
        for (const RecipeStroke& s : step.strokes)
            if (s.needs_adjacency() && !adjacency) adjacency.emplace(poses.bind_mesh(), samples);
    for (size_t k = 0; k < steps.size(); ++k) {
        const RecipeStep& step = steps[k];
        const std::string which = "step " + std::to_string(k + 1) + " (split of node " + std::to_string(step.node) + ")";
        const TreeNode* n = tree.find(step.node);
        if (!n) {
            out.skipped.push_back(which + ": the node does not exist, an earlier step was not replayed");
            continue;
        }
        const detail::PosedSamples at = poses.at(step.pose, "tree '" + authored.name() + "' " + which);
        // The tree's geometry stays the bind pose's: only where the strokes find the samples moves.
        const EditResult r = tree.split(step.node, select_strokes(at.points, tree, step, at.mesh, adjacency ? &*adjacency : nullptr), samples);
        if (!r) {
            out.skipped.push_back(which + ": " + r.reason);
            continue;
        }
        tree.add_recipe_step(step);
        ++out.replayed;
    }
    return tree;
}

} // namespace

SamplingTree unsplit_tree(const std::string& name, const SampleSet& samples) {
    SamplingTree tree(name, uint32_t(samples.size()));
    tree.assign_radii(samples, RadiusRule{});
    tree.compute_bounds(samples, BoundsMethod::Tight);
    return tree;
}

SamplingTree replay_recipe(const SamplingTree& authored, const SampleSet& samples, const TriangleMesh& mesh,
                           ReplayReport* report) {
    detail::StepPoses poses(samples, mesh);
    return replay(authored, samples, poses, report);
}

SamplingTree replay_recipe(const SamplingTree& authored, const SptDocument& doc,
                           std::shared_ptr<const AnimatedMesh> animated, ReplayReport* report) {
    detail::StepPoses poses(doc, std::move(animated));
    return replay(authored, doc.samples, poses, report);
}

bool recipe_has_poses(const SptDocument& doc) {
    for (const SamplingTree& t : doc.trees)
        for (const RecipeStep& step : t.recipe())
            if (!step.pose.bind()) return true;
    return false;
}

} // namespace spt
