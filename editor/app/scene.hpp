#pragma once
// What the four views draw, made once from the document for all of them: the mesh, the
// sampling spheres of the edited tree (coloured by level or node), the current node
// highlighted with its bounding sphere, and the selected samples' spheres (marks on the
// sampling spheres, drawn in the selection colour), all at the pose the timeline shows. Each
// part carries a revision so a view re-uploads only what changed.
#include "editor_document.hpp"
#include "spt/render/frame.hpp"
#include "spt/motion.hpp"
#include "spt/render/tree_overlay.hpp"
#include <QObject>
#include <memory>

namespace spt::editor {

/// Colour of selected samples' spheres.
render::Color selection_color();

/// Draw data of the open document; object frame = world frame, model units.
struct SceneData {
    const TriangleMesh* mesh = nullptr;             ///< null when the mesh is unknown
    std::vector<render::SphereInstance> spheres;    ///< every sampling sphere, CompactTree order
    render::SphereRange highlight;                  ///< the current node's spheres
    std::vector<uint32_t> selected;                 ///< indices into `spheres` of the selected samples
    std::vector<render::WireSphere> wires;          ///< bounding sphere of the current node
    /// Coloured by contacts: the heat map's legend (a row for 0 steps first) and scale; empty otherwise.
    std::vector<render::HeatLegendRow> legend;
    render::HeatScale heat;                         ///< the heat map's scale (with `legend`)
    bool hiding = false;                            ///< some node is hidden: only `shown` is drawn
    std::vector<render::SphereRange> shown;         ///< with `hiding`, the ranges of `spheres` drawn
    /// The mesh and `spheres` are relative to it (the document's local origin), drawn with
    /// render::local_frame(origin): far from the origin float keeps their detail only so.
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    /// The mesh's vertices and normals at the pose shown (object frame; Renderer::update_mesh), null
    /// when the mesh has no clips: it stays as uploaded.
    const std::vector<Eigen::Vector3d>* vertices = nullptr;
    const std::vector<Eigen::Vector3d>* normals = nullptr; ///< with `vertices`
    uint64_t mesh_revision = 0;      ///< changes when the mesh changes
    uint64_t pose_revision = 0;      ///< changes when `vertices` move
    uint64_t spheres_revision = 0;   ///< changes when `spheres` changes
    uint64_t selected_revision = 0;  ///< changes when `selected` changes
    uint64_t revision = 0;           ///< changes on any change (views repaint)
};

/// Keeps SceneData in step with an EditorDocument.
class Scene : public QObject {
    Q_OBJECT
public:
    /// Follows `doc`'s signals; `doc` must outlive the scene.
    explicit Scene(EditorDocument& doc, QObject* parent = nullptr);
    /// The current draw data.
    const SceneData& data() const { return data_; }
    /// The frame every view draws (what `spt render --overlay spheres,node,grid,axes --node ID` draws, plus the
    /// selection as marks on `spheres`); handles are the view's own uploads.
    render::Frame frame(render::MeshHandle mesh, render::SphereSetHandle spheres) const;
    /// Colours spheres by node (default: a split's two children in opposite hues) or by level.
    void set_color_by(render::ColorBy by);
    /// How spheres are coloured.
    render::ColorBy color_by() const { return color_by_; }
    /// The motion whose contact counts colour the spheres by contacts (null: none, all grey).
    void set_motion(std::shared_ptr<const MotionRecording> motion);

signals:
    /// Something to draw changed.
    void changed();

private:
    void rebuild_mesh();
    void rebuild_tree();
    void rebuild_spheres();
    void rebuild_legend();
    const std::vector<uint32_t>* contact_counts() const; // the motion's, if it is of this document
    void rebuild_current();
    void rebuild_selection();
    void rebuild_pose();
    void rebuild_shown();
    EditorDocument& doc_;
    SceneData data_;
    render::ColorBy color_by_ = render::ColorBy::Node;
    std::shared_ptr<const MotionRecording> motion_;
    std::vector<uint32_t> sphere_of_sample_; // index into data_.spheres of each sample; UINT32_MAX if none
    std::unique_ptr<CompactTree> compact_;
};

} // namespace spt::editor
