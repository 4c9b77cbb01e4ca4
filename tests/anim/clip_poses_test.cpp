// Sampling spheres limited at a deforming object's clip poses (ConvertOptions::poses, clip_poses).
#include "spt/animation.hpp"
#include "spt/compact_tree.hpp"
#include "spt/convert.hpp"
#include "spt/deforming_model.hpp"
#include "spt/error.hpp"
#include "spt/spt_file.hpp"
#include "bending_bar.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>

namespace spt {
namespace {

// The bending bar whose right half (x >= 0.25, all on joint "tip") is squeezed to 0.3 of its
// 0.4 thickness in y over one second: at the end it is the box [0.25, 1] x [-0.06, 0.06] x
// [-0.2, 0.2] there.
std::shared_ptr<AnimatedMesh> squeezed_bar() {
    auto m = bending::bending_bar();
    Clip c;
    c.name = "squeeze", c.duration = 1;
    NodeChannel ch;
    ch.node = 1;
    ch.scale.times = {0, 1};
    ch.scale.values = {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 0.3, 1)};
    c.nodes = {ch};
    m->clips = {c};
    return m;
}

// The most any sphere lying wholly in the squeezed box reaches beyond its nearest face (its radius
// less its centre's distance to the surface: what the radius limiter bounds), at the clip's end.
double worst_reach_when_squeezed(const std::shared_ptr<AnimatedMesh>& mesh, const SptDocument& doc, size_t* spheres) {
    DeformingModel m(doc, mesh);
    m.pose(&mesh->clips[0], 1.0);
    const CompactTree& t = m.model().tree();
    double worst = -INFINITY;
    *spheres = 0;
    for (const CompactNode& n : t.nodes()) {
        if (!n.is_active()) continue;
        for (uint32_t k = n.first; k < n.first + n.count; ++k) {
            const Eigen::Vector3d c = t.sphere_center(n, k).cast<double>() + t.origin();
            const double r = n.ss_radius;
            if (c.x() - r < 0.25) continue; // reaches the blended part, which is no box
            const double nearest = std::min({0.06 - std::abs(c.y()), 0.2 - std::abs(c.z()), 1 - c.x()});
            worst = std::max(worst, r - nearest);
            ++*spheres;
        }
    }
    return worst;
}

TEST(ClipPoses, ASqueezedPartsSpheresKeepTheAllowanceAtThePosesTheyWereLimitedAt) {
    const auto mesh = squeezed_bar();
    ConvertOptions plain;
    const SptDocument bind_only = make_document(mesh->imported.mesh, plain);
    ConvertOptions posed;
    posed.poses = clip_poses(*mesh, 1.0 / 30);
    const SptDocument limited = make_document(mesh->imported.mesh, posed);
    const double allowance = kDefaultProtrusion * mesh->imported.mesh.diagonal();

    size_t n = 0;
    // The premise: radii fitted to the bar 0.4 thick poke through it at 0.12.
    EXPECT_GT(worst_reach_when_squeezed(mesh, bind_only, &n), 4 * allowance);
    EXPECT_GT(n, 20u);
    // Limited at the clip's poses (its end among them), none reaches beyond the allowance; the
    // margin is the float layout's rounding.
    EXPECT_LE(worst_reach_when_squeezed(mesh, limited, &n), allowance + 1e-5);
    EXPECT_GT(n, 20u);
    // Smaller spheres, and the faces sampled more densely for them (the tolerance still holds).
    EXPECT_GT(limited.samples.size(), bind_only.samples.size());
}

// The bar's 768 faces are sampled in several runs, each limited at every pose, on however many
// threads: the file must not show how many.
TEST(ClipPoses, TheFileIsTheSameOnEveryThreadCount) {
    const auto mesh = squeezed_bar();
    ConvertOptions o;
    o.poses = clip_poses(*mesh, 1.0 / 10);
    o.threads = 1;
    const std::vector<uint8_t> one = encode_spt(make_document(mesh->imported.mesh, o));
    for (int threads : {2, 5}) {
        o.threads = threads;
        EXPECT_EQ(encode_spt(make_document(mesh->imported.mesh, o)), one) << threads;
    }
}

TEST(ClipPoses, ThePoseOfTheMeshItselfChangesNoRadius) {
    const auto mesh = squeezed_bar();
    ConvertOptions plain;
    plain.auto_tolerance = false;
    ConvertOptions same = plain;
    same.poses = {posed_mesh(*mesh, &mesh->clips[0], 0.0)}; // the bind pose, as the clip starts
    const SptDocument a = make_document(mesh->imported.mesh, plain), b = make_document(mesh->imported.mesh, same);
    ASSERT_EQ(a.samples.size(), b.samples.size());
    EXPECT_EQ(a.samples.max_radius, b.samples.max_radius);
}

TEST(ClipPoses, ComeStepsApartFromEachClipsStartAndAtItsEnd) {
    const auto mesh = squeezed_bar();
    EXPECT_EQ(clip_poses(*mesh, 1.0 / 30).size(), 31u);
    EXPECT_EQ(clip_poses(*mesh, 0.3).size(), 5u); // 0, 0.3, 0.6, 0.9 and the end
    EXPECT_EQ(clip_poses(*mesh, 5).size(), 2u);   // the start and the end
    // A long clip keeps at most max_per_clip poses, spread evenly, the last at its end.
    const std::vector<TriangleMesh> few = clip_poses(*mesh, 1e-4, 4);
    ASSERT_EQ(few.size(), 4u);
    EXPECT_EQ(few.back().positions, posed_mesh(*mesh, &mesh->clips[0], 1.0).positions);
    EXPECT_EQ(few[1].positions, posed_mesh(*mesh, &mesh->clips[0], 1.0 / 3).positions);
    // Poses that would take more memory than allowed are fewer, the start and end kept.
    const std::vector<TriangleMesh> bounded = clip_poses(*mesh, 1.0 / 30, 240, 1);
    ASSERT_EQ(bounded.size(), 2u);
    EXPECT_EQ(bounded.back().positions, posed_mesh(*mesh, &mesh->clips[0], 1.0).positions);
    EXPECT_EQ(clip_poses(*mesh, 1.0 / 30, 240, size_t(1) << 40).size(), 31u);
    EXPECT_THROW(clip_poses(*mesh, 0), Error);
    EXPECT_THROW(clip_poses(*mesh, NAN), Error);
    AnimatedMesh still = *mesh;
    still.clips.clear();
    EXPECT_TRUE(clip_poses(still, 0.1).empty());
}

TEST(ClipPoses, APoseOfAnotherMeshIsRefused) {
    const auto bar = squeezed_bar();
    const auto tube = bending::bending_bar(true);
    ConvertOptions o;
    o.poses = {tube->imported.mesh};
    try {
        make_document(bar->imported.mesh, o);
        FAIL() << "a pose of another mesh was taken";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Usage);
        EXPECT_NE(std::string(e.what()).find("not this mesh moved"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace spt
