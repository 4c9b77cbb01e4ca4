// Far from the origin: a model whose geometry lies 10^6 from the world origin draws as sharply
// as at the origin. Float world coordinates keep 1/16 of a unit there, which snapped sampling
// spheres and vertices of a part a few units across into visible rows (the editor's views of
// a mesh exported in world units); geometry is now uploaded relative to the model's local
// origin and its pose composed with the view in double.
#include "scenes.hpp"
#include "spt/compact_tree.hpp"
#include "spt/convert.hpp"
#include "spt/render/tree_overlay.hpp"
#include "test_meshes.hpp"
#include <gtest/gtest.h>

using namespace spt::render;
using spt::test::OffscreenRenderer;

namespace {

// Exactly representable in float, as a local origin snapped to its power-of-two grid is.
const Eigen::Vector3d kFar(1048576.0, -2097152.0, 524288.0);

struct Model {
    spt::TriangleMesh mesh;
    spt::SptDocument doc;
};

// The torus's model at the origin, and the same model moved by `offset` (mesh and local origin).
Model torus_model(const Eigen::Vector3d& offset) {
    Model m{spt::test::torus(1.0, 0.35, 48, 24), {}};
    m.doc = spt::make_document(m.mesh);
    for (Eigen::Vector3d& p : m.mesh.positions) p += offset;
    m.doc.samples.origin += offset;
    return m;
}

// Mesh and sampling spheres uploaded relative to the model's local origin and placed by local_frame,
// as the editor and `spt render` draw them; or, with `world_floats`, the spheres' centres
// rounded to float in the world frame, as they were drawn before.
Frame model_frame(Renderer& r, const Model& m, bool world_floats = false) {
    const spt::CompactTree compact(m.doc.trees.front(), m.doc.samples);
    const Eigen::Vector3d origin = m.doc.samples.origin;
    Frame f;
    // Without the grid: its extent and height follow the frame's bounds, which are float, so
    // far out they can pick the next line or a ground a float spacing lower.
    f.grid = false;
    MeshItem mesh;
    mesh.mesh = r.add_mesh(m.mesh, origin);
    mesh.pose = local_frame(origin);
    mesh.style.opacity = 0.3f;
    f.meshes.push_back(mesh);
    SphereItem spheres;
    if (world_floats) {
        spheres.spheres = r.add_spheres(sampling_spheres(compact, m.doc.trees.front(), ColorBy::Level));
    } else {
        spheres.spheres = r.add_spheres(sampling_spheres(compact, m.doc.trees.front(), ColorBy::Level, origin));
        spheres.pose = local_frame(origin);
    }
    f.spheres.push_back(spheres);
    return f;
}

} // namespace

TEST(FarRender, AModelAMillionUnitsOutDrawsAsAtTheOriginInTheOrthographicViews) {
    OffscreenRenderer r("osmesa", 320, 240);
    const Model near = torus_model(Eigen::Vector3d::Zero()), far = torus_model(kFar);
    const Frame near_frame = model_frame(*r.renderer, near), far_frame = model_frame(*r.renderer, far);
    const Frame old_far_frame = model_frame(*r.renderer, far, true);
    for (View v : {View::Top, View::Front, View::Side}) {
        // The same camera, moved with the model (targets exact in float: the picture is not
        // shifted by a rounded target, which no drawing can help).
        Camera at_origin = fit_camera(v, r.renderer->bounds(near_frame));
        at_origin.target = Eigen::Vector3f::Zero();
        Camera out_there = at_origin;
        out_there.target = kFar.cast<float>();
        const Image expected = r.view(near_frame, at_origin);
        const CompareResult same = compare_images(r.view(far_frame, out_there), expected);
        EXPECT_TRUE(same.passed) << view_name(v) << ": " << same.differing_pixels << " pixels differ";
        // The test can fail: the spheres rounded in world floats land in rows a sixteenth apart.
        const CompareResult old = compare_images(r.view(old_far_frame, out_there), expected);
        EXPECT_FALSE(old.passed) << view_name(v) << ": world floats drew the same picture";
    }
}

TEST(FarRender, DrawingOriginIsZeroNearTheOriginAndTheBoxCentreFarOut) {
    spt::TriangleMesh m = spt::test::torus(1.0, 0.35, 12, 6);
    EXPECT_EQ(Renderer::drawing_origin(m), Eigen::Vector3d::Zero()) << "pictures near the origin stay as they were";
    for (Eigen::Vector3d& p : m.positions) p += kFar;
    EXPECT_LE((Renderer::drawing_origin(m) - kFar).norm(), 1e-9);
}
