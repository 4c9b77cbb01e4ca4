// Trees built for a scene's motion inside a document: `spt convert --motion` and the replay of
// the builds a recipe records.
#include "spt/error.hpp"
#include "spt/motion_tree.hpp"
#include <algorithm>
#include <filesystem>

namespace spt {
namespace {

// The document with `tree` as its only tree, for a recording that runs with it.
std::shared_ptr<const SptDocument> with_tree(const SptDocument& doc, const SamplingTree& tree) {
    auto one = std::make_shared<SptDocument>();
    one->mesh = doc.mesh;
    one->samples = doc.samples;
    one->trees.push_back(tree);
    return one;
}

MotionRecording record_for(const std::string& scene_path, const std::string& object, const SptDocument& doc,
                           const SamplingTree& tree, std::shared_ptr<const AnimatedMesh> mesh, int steps, int threads) {
    const Scene scene = load_scene(scene_path);
    MotionOptions mo;
    mo.steps = steps;
    mo.threads = std::max(1, threads);
    return record_motion(scene, object, MotionModel{with_tree(doc, tree), tree.name(), std::move(mesh)}, mo);
}

// Face samples were placed for a tolerance: a tree built over them keeps its guarantee (as append_tree).
BuildOptions kept_coherent(BuildOptions build, const SampleSet& samples) {
    for (size_t i = 0; i < samples.size() && !build.radius_coherent; ++i) build.radius_coherent = samples.is_face_sample(i);
    return build;
}

} // namespace

const SamplingTree& add_motion_tree(SptDocument& doc, std::shared_ptr<const AnimatedMesh> mesh,
                                    const std::string& scene_path, const std::string& scene_in_file,
                                    const std::string& object, const std::string& name, MotionBuildOptions options,
                                    int steps, bool replace) {
    auto same = std::find_if(doc.trees.begin(), doc.trees.end(), [&](const SamplingTree& t) { return t.name() == name; });
    if (same != doc.trees.end() && !replace)
        throw Error(ErrorKind::CannotWrite, "the document already has a tree named '" + name + "'; use --force to replace it");
    options.build = kept_coherent(options.build, doc.samples);
    // Recorded with an automatic tree, as a replay records it: the same motion, the same tree.
    const MotionRecording rec = record_for(scene_path, object, doc, build_tree("recording", doc.samples, options.build),
                                           std::move(mesh), steps, options.build.threads);
    SamplingTree tree = build_motion_tree(name, doc.samples, rec, options);
    tree.add_motion_build(MotionBuildStep{root_id(), scene_in_file, object, steps, options.build.leaf_size, 0});
    same = std::find_if(doc.trees.begin(), doc.trees.end(), [&](const SamplingTree& t) { return t.name() == name; });
    if (same != doc.trees.end()) {
        *same = std::move(tree);
        return *same;
    }
    doc.trees.push_back(std::move(tree));
    return doc.trees.back();
}

void replay_motion_builds(SamplingTree& tree, const std::vector<MotionBuildStep>& recorded, const SptDocument& doc,
                          std::shared_ptr<const AnimatedMesh> mesh, const std::string& folder, const BuildOptions& build) {
    namespace fs = std::filesystem;
    for (const MotionBuildStep& m : recorded) {
        const fs::path scene = fs::path(m.scene).is_relative() && !folder.empty() ? fs::path(folder) / m.scene : fs::path(m.scene);
        const TreeNode* n = tree.find(m.node);
        if (!n || !n->active)
            throw Error(ErrorKind::BadInput, "tree '" + tree.name() + "': the build from motion under node " +
                                                 std::to_string(m.node) + " finds no active node there to build under");
        MotionBuildOptions options;
        options.build = kept_coherent(build, doc.samples);
        options.build.leaf_size = m.leaf_size;
        const MotionRecording rec = record_for(scene.string(), m.object, doc,
                                               build_tree("recording", doc.samples, options.build), mesh, m.steps,
                                               build.threads);
        const EditResult done = build_motion_subtree(tree, m.node, doc.samples, rec, options);
        if (!done) throw Error(ErrorKind::BadInput, "tree '" + tree.name() + "': " + done.reason);
        tree.add_motion_build(m);
    }
}

} // namespace spt
