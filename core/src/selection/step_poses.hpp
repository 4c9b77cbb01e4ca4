#pragma once
// Where a recipe step's strokes find the samples: at the bind pose the samples' own points and
// the mesh; at a clip's pose, the points and the mesh a DeformingModel gives there, posed once
// for a run of steps at the same pose.
#include "spt/deforming_model.hpp"
#include "spt/selection.hpp"
#include "spt/spt_file.hpp"
#include <memory>
#include <optional>
#include <string>

namespace spt::detail {

/// The samples' surface points and the mesh at one pose.
struct PosedSamples {
    SamplePoints points;      ///< per sample, local frame
    const TriangleMesh* mesh; ///< for visible-only strokes
};

/// The samples of one document at the poses a recipe's steps record.
class StepPoses {
public:
    /// Bind pose only: a step made at a clip's pose is Error(BadInput) (no animation is known).
    StepPoses(const SampleSet& samples, const TriangleMesh& mesh);
    /// `doc`'s samples on `animated`, the mesh `doc` was made from.
    StepPoses(const SptDocument& doc, std::shared_ptr<const AnimatedMesh> animated);
    ~StepPoses();

    /// The samples and the mesh at `pose`, valid until the next call; `which` names the step in
    /// the Error(BadInput) for a clip the mesh lacks.
    PosedSamples at(const RecipePose& pose, const std::string& which);
    /// The mesh at the bind pose (its topology is every pose's).
    const TriangleMesh& bind_mesh() const { return mesh_; }

private:
    const SampleSet& samples_;
    const TriangleMesh& mesh_;
    std::shared_ptr<const AnimatedMesh> animated_;
    const SptDocument* doc_ = nullptr;
    std::unique_ptr<DeformingModel> model_; // made at the first step with a clip
    std::optional<RecipePose> posed_;       // the pose model_ and posed_mesh_ hold
    TriangleMesh posed_mesh_;
};

} // namespace spt::detail
