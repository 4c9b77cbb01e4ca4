#include "spt/convert.hpp"
#include "spt/motion_tree.hpp"
#include "spt/error.hpp"
#include "spt/recipe.hpp"
#include <algorithm>
#include <chrono>

namespace spt {

std::vector<TreeReplay> replay_trees(SptDocument& doc, const TriangleMesh& mesh, const SptDocument& recipes,
                                     const BuildOptions& build, std::shared_ptr<const AnimatedMesh> animated,
                                     const std::string& recipe_folder) {
    std::vector<TreeReplay> done;
    std::vector<SamplingTree> trees;
    for (const SamplingTree& t : recipes.trees) {
        TreeReplay r;
        r.tree = t.name();
        r.steps = t.recipe().size();
        r.motion_builds = t.motion_builds().size();
        r.built_automatically = t.recipe().empty() && t.motion_builds().empty();
        for (const MotionBuildStep& m : t.motion_builds())
            if (m.after_steps != t.recipe().size())
                throw Error(ErrorKind::BadInput, "tree '" + t.name() + "': a split made after its build from motion "
                                                 "under node " + std::to_string(m.node) +
                                                 " cannot be replayed yet (merge the split, or build from motion last)");
        if (r.built_automatically) trees.push_back(build_tree(t.name(), doc.samples, build));
        else if (t.recipe().empty()) trees.push_back(unsplit_tree(t.name(), doc.samples));
        else if (animated) trees.push_back(replay_recipe(t, doc, animated, &r.report));
        else trees.push_back(replay_recipe(t, doc.samples, mesh, &r.report));
        if (!t.motion_builds().empty()) {
            auto with_clips = animated;
            if (!with_clips) {
                auto plain = std::make_shared<AnimatedMesh>();
                plain->imported.mesh = mesh;
                with_clips = std::move(plain);
            }
            replay_motion_builds(trees.back(), t.motion_builds(), doc, with_clips, recipe_folder, build);
        }
        done.push_back(std::move(r));
    }
    doc.trees = std::move(trees); // only once every tree is made: a failure leaves doc as it was
    return done;
}

const SamplingTree& append_tree(SptDocument& doc, const TriangleMesh& mesh, const std::string& name,
                                BuildOptions build, bool replace, const std::string& path, ConvertStats* stats) {
    const std::string mismatch = check_mesh_matches(doc.mesh, mesh);
    if (!mismatch.empty()) throw_bad_input(path, mismatch + " (" + mesh.name + ")");
    auto same = std::find_if(doc.trees.begin(), doc.trees.end(), [&](const SamplingTree& t) { return t.name() == name; });
    if (same != doc.trees.end() && !replace)
        throw Error(ErrorKind::CannotWrite, path + ": already has a tree named '" + name + "'; use --force to replace it");
    ConvertStats local;
    ConvertStats& st = stats ? *stats : local;
    st = ConvertStats{};
    for (size_t i = 0; i < doc.samples.size(); ++i) {
        const bool face = doc.samples.is_face_sample(i);
        ++(face ? st.face_samples : st.vertex_samples);
        // Face samples were placed for a tolerance: the new tree keeps its guarantee.
        build.radius_coherent = build.radius_coherent || face;
    }
    const auto t0 = std::chrono::steady_clock::now();
    SamplingTree tree = build_tree(name, doc.samples, build);
    st.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (same != doc.trees.end()) doc.trees.erase(same);
    doc.trees.push_back(std::move(tree));
    return doc.trees.back();
}

} // namespace spt
