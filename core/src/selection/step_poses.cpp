// StepPoses: a recipe step's samples at the pose it was made at.
#include "selection/step_poses.hpp"
#include "spt/error.hpp"
#include "spt/recipe.hpp"

namespace spt::detail {
namespace {

// The clip named exactly `name` (a recorded name, never an index), or Error(BadInput) naming the
// clips the mesh has.
const Clip& clip_named(const AnimatedMesh* mesh, const std::string& mesh_name, const RecipePose& pose,
                       const std::string& which) {
    if (mesh)
        for (const Clip& c : mesh->clips)
            if (c.name == pose.clip) return c;
    std::string have;
    if (mesh)
        for (const Clip& c : mesh->clips) have += (have.empty() ? "'" : ", '") + c.name + "'";
    throw_bad_input(mesh_name, which + " was made at clip '" + pose.clip + "' (" + std::to_string(pose.time) +
                                   " s), which the mesh lacks; " +
                                   (have.empty() ? std::string("it has no clips") : "its clips: " + have));
}

} // namespace

StepPoses::StepPoses(const SampleSet& samples, const TriangleMesh& mesh) : samples_(samples), mesh_(mesh) {}

StepPoses::StepPoses(const SptDocument& doc, std::shared_ptr<const AnimatedMesh> animated)
    : samples_(doc.samples), mesh_(animated->imported.mesh), animated_(std::move(animated)), doc_(&doc) {}

StepPoses::~StepPoses() = default;

PosedSamples StepPoses::at(const RecipePose& pose, const std::string& which) {
    if (pose.bind()) return {samples_, &mesh_};
    const Clip& clip = clip_named(animated_.get(), mesh_.name, pose, which);
    if (!model_) {
        // The samples' points at a pose do not depend on the tree: any tree over them binds.
        SptDocument bound{doc_->mesh, doc_->samples, {unsplit_tree("pose", doc_->samples)}};
        model_ = std::make_unique<DeformingModel>(bound, animated_, "", false);
        posed_mesh_ = mesh_;
    }
    if (posed_ != pose) {
        model_->pose(&clip, pose.time);
        posed_mesh_.positions = model_->vertices();
        posed_mesh_.normals = model_->vertex_normals();
        posed_ = pose;
    }
    return {SamplePoints(model_->sample_points(), samples_.origin), &posed_mesh_};
}

} // namespace spt::detail
