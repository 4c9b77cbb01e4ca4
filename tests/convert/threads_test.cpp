// A conversion samples on several threads (ConvertOptions::threads): the file must not show it.
#include "meshgen.hpp"
#include "mesh/hard_shapes.hpp"
#include "mesh/shapes.hpp"
#include "sampling/surface_samples.hpp"
#include "spt/convert.hpp"
#include "host_task_system.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>

using namespace spt;

namespace {

std::vector<uint8_t> converted(const TriangleMesh& mesh, int threads, std::optional<double> tolerance = {}) {
    ConvertOptions o;
    o.threads = threads;
    o.tolerance = tolerance;
    return encode_spt(make_document(mesh, o));
}

void expect_same_bytes_on_every_thread_count(const TriangleMesh& mesh, std::optional<double> tolerance = {}) {
    const std::vector<uint8_t> one = converted(mesh, 1, tolerance);
    for (int threads : {2, 5}) EXPECT_EQ(converted(mesh, threads, tolerance), one) << mesh.name << ", " << threads;
}

// More vertices than one run of samples (kSampleRun), so that several threads each take some.
TEST(ConvertThreads, ManyRunsOfVertexSamplesGiveTheSameFileOnEveryThreadCount) {
    const TriangleMesh torus = meshgen::prepare(meshgen::torus(1, 0.35, 160, 80), "torus").mesh;
    ASSERT_GT(torus.positions.size(), kSampleRun * 32);
    expect_same_bytes_on_every_thread_count(torus);
}

// More faces than one run, each sampled to a tolerance: face samples in many runs.
TEST(ConvertThreads, ManyRunsOfFaceSamplesGiveTheSameFileOnEveryThreadCount) {
    const TriangleMesh torus = meshgen::prepare(meshgen::torus(1, 0.35, 120, 80), "torus").mesh;
    ASSERT_GT(torus.triangles.size(), kSampleRun * 64);
    expect_same_bytes_on_every_thread_count(torus, 0.005 * torus.diagonal());
}

// The automatic tolerance (large flat faces) and the two-sided samples of open parts.
TEST(ConvertThreads, AutomaticToleranceAndOpenPartsGiveTheSameFileOnEveryThreadCount) {
    expect_same_bytes_on_every_thread_count(import_mesh(test::project_meshes() + "/cad_part.stl").mesh);
    TriangleMesh box = make_open_box(Eigen::Vector3d(1, 0.5, 0.7), 12);
    box.name = "open box";
    expect_same_bytes_on_every_thread_count(box);
}

// A host's task system (ConvertOptions::tasks, ImportOptions::tasks) runs the sampling, the
// tree's build and its bounds, and the mesh's preparation, with the same bytes as one thread.
TEST(ConvertThreads, AHostsTaskSystemRunsTheImportAndConversionWithTheSameFile) {
    const meshgen::RawMesh raw = meshgen::torus(1, 0.35, 400, 200); // enough for parallel subtrees and bounds
    ImportOptions one_import;
    one_import.threads = 1;
    const TriangleMesh one_mesh = prepare_mesh("torus", raw.positions, raw.triangles, one_import).mesh;
    test::HostTaskSystem host(3);
    ImportOptions host_import;
    host_import.threads = 3;
    host_import.tasks = &host;
    const TriangleMesh host_mesh = prepare_mesh("torus", raw.positions, raw.triangles, host_import).mesh;
    EXPECT_EQ(host_mesh.positions, one_mesh.positions);
    EXPECT_EQ(host_mesh.triangles, one_mesh.triangles);
    const int after_import = host.runs.load();
    EXPECT_GT(after_import, 0) << "the mesh was prepared without the host";
    for (const std::optional<double> tolerance : {std::optional<double>{}, std::optional<double>(0.01)}) {
        ConvertOptions on_host;
        on_host.threads = 4;
        on_host.tolerance = tolerance;
        on_host.tasks = &host;
        const int before = host.runs.load();
        EXPECT_EQ(encode_spt(make_document(one_mesh, on_host)), converted(one_mesh, 1, tolerance));
        EXPECT_GT(host.runs.load(), before + 2) << "sampling and tree building ran without the host";
    }
}

TEST(ConvertThreads, FaceSamplesOfEveryFaceComeInFaceOrderWhateverTheThreads) {
    const TriangleMesh mesh = meshgen::prepare(meshgen::torus(1, 0.35, 100, 50), "torus").mesh;
    const RadiusLimiter limiter(mesh, 0.0025 * mesh.diagonal());
    const Eigen::Vector3d origin = local_origin(mesh);
    SampleSet one_by_one;
    one_by_one.origin = origin;
    for (uint32_t f = 0; f < mesh.triangles.size(); ++f)
        add_face_samples(one_by_one, limiter, f, 0.001 * mesh.diagonal(), {}, 0.5f);
    for (int threads : {1, 2, 5}) {
        const SampleSet s = face_samples(limiter, origin, 0.001 * mesh.diagonal(), {}, 0.5f, threads);
        EXPECT_EQ(s.sources, one_by_one.sources) << threads;
        EXPECT_EQ(s.points, one_by_one.points) << threads;
        EXPECT_EQ(s.max_radius, one_by_one.max_radius) << threads;
    }
}

// A mesh of a few hundred faces, each carrying many samples probed at many poses: it was one run,
// so one thread did all of it (the walking figure's 4,872 faces with its clips' 94 poses took
// 10 s on one core of two). Its runs now go to the host's threads, and give the same samples.
TEST(ConvertThreads, AFewHundredFacesAreSampledInRunsOnTheHostsThreads) {
    const TriangleMesh mesh = meshgen::prepare(meshgen::box(2, 0.4, 0.4, 8), "bar").mesh;
    ASSERT_GT(mesh.triangles.size(), 2 * kSampleRun);
    ASSERT_LT(mesh.triangles.size(), 8 * kSampleRun);
    const RadiusLimiter limiter(mesh, 0.0025 * mesh.diagonal());
    const Eigen::Vector3d origin = local_origin(mesh);
    const double eps = 0.002 * mesh.diagonal();
    const SampleSet one = face_samples(limiter, origin, eps, {}, 0.5f, 1);
    test::HostTaskSystem host(3);
    const SampleSet on_host = face_samples(limiter, origin, eps, {}, 0.5f, 3, nullptr, kMaxSamples, &host);
    EXPECT_GE(host.runs.load(), 1) << "the runs stayed on the calling thread";
    EXPECT_EQ(on_host.sources, one.sources);
    EXPECT_EQ(on_host.points, one.points);
    EXPECT_EQ(on_host.max_radius, one.max_radius);
}

// A unit box's first face at a tolerance that gives it thousands of samples.
struct LargeFace {
    const TriangleMesh mesh = make_box({0.5, 0.5, 0.5}, 1);
    const RadiusLimiter limiter{mesh, 1e-4};
    const double eps = 2e-3;
    SampleSet samples_on_one_thread() const {
        SampleSet s;
        add_face_samples(s, limiter, 0, eps, {}, 0.5f);
        return s;
    }
};

// One large face carries thousands of samples (a floor, a CAD part's side, a morph target's
// cube): its refinement's probes go to the threads a step at a time, and the samples come in the
// order one thread gives them. Past its room it stops before adding any.
TEST(ConvertThreads, OneLargeFacesSamplesAreProbedOnTheHostsThreadsInTheSameOrder) {
    const LargeFace face;
    const RadiusLimiter& limiter = face.limiter;
    const double eps = face.eps;
    const SampleSet one = face.samples_on_one_thread();
    ASSERT_GT(one.size(), 1000u);
    test::HostTaskSystem host(3);
    SampleSet planned;
    add_face_samples(planned, limiter, 0, eps, {}, 0.5f, SIZE_MAX, 3, &host);
    EXPECT_GE(host.runs.load(), 1) << "every probe ran on the calling thread";
    EXPECT_EQ(planned.points, one.points);
    EXPECT_EQ(planned.normals, one.normals);
    EXPECT_EQ(planned.sources, one.sources);
    EXPECT_EQ(planned.spacing, one.spacing);
    EXPECT_EQ(planned.max_radius, one.max_radius);
    SampleSet some;
    try {
        add_face_samples(some, limiter, 0, eps, {}, 0.5f, 500, 3, &host);
        FAIL() << "a face of " << one.size() << " samples did not stop at 500";
    } catch (const TooManySamples& t) {
        EXPECT_EQ(t.reached, 501u);
        EXPECT_EQ(some.size(), 0u);
    }
    SampleSet exactly;
    add_face_samples(exactly, limiter, 0, eps, {}, 0.5f, one.size(), 3, &host);
    EXPECT_EQ(exactly.points, one.points);
    // A step wider than the plan may take (a face of hundreds of thousands of samples) leaves the
    // rest of the refinement to the calling thread: the same samples again.
    const size_t most = detail::most_planned_sub_triangles;
    detail::most_planned_sub_triangles = 64;
    SampleSet partly;
    add_face_samples(partly, limiter, 0, eps, {}, 0.5f, SIZE_MAX, 3, &host);
    detail::most_planned_sub_triangles = most;
    EXPECT_EQ(partly.points, one.points);
    EXPECT_EQ(partly.max_radius, one.max_radius);
    EXPECT_EQ(partly.sources, one.sources);
}

// A host whose Cancel is pressed while its threads run the n-th hand-over of work.
class CancelOnRun final : public TaskSystem {
public:
    CancelOnRun(std::atomic<bool>& cancel, int nth) : cancel_(cancel), nth_(nth) {}
    void run(int count, const std::function<void(int)>& job) override {
        if (++runs == nth_) cancel_.store(true);
        for (int w = 0; w < count; ++w) job(w);
    }
    int runs = 0;

private:
    std::atomic<bool>& cancel_;
    int nth_;
};

// The editor's Cancel is answered inside one large face (a floor or a CAD part's side of
// hundreds of thousands of samples), not only between faces: its planned steps and its
// refinement look at the flag and leave the face unfinished (the caller discards the set).
TEST(ConvertThreads, CancellingStopsAFaceUnderWayOnOneThreadOrMany) {
    const LargeFace face;
    const size_t whole = face.samples_on_one_thread().size();
    ASSERT_GT(whole, 1000u);
    std::atomic<bool> cancel{true};
    SampleSet alone; // one thread: the refinement stops at its first probe's look at the flag
    add_face_samples(alone, face.limiter, 0, face.eps, {}, 0.5f, SIZE_MAX, 1, nullptr, &cancel);
    EXPECT_LE(alone.size(), 3u);
    cancel = false;
    CancelOnRun host(cancel, 3); // pressed during the third planned step's probes
    SampleSet planned;
    add_face_samples(planned, face.limiter, 0, face.eps, {}, 0.5f, SIZE_MAX, 2, &host, &cancel);
    EXPECT_EQ(host.runs, 3) << "the plan went on past the step in which Cancel was pressed";
    EXPECT_EQ(planned.size(), 0u);
    // And through face_samples, as a conversion calls it: the face stops, the set is partial.
    cancel = false;
    CancelOnRun again(cancel, 3);
    const SampleSet some = face_samples(face.limiter, local_origin(face.mesh), face.eps, {}, 0.5f, 2, &cancel, kMaxSamples, &again);
    EXPECT_TRUE(cancel.load());
    EXPECT_LT(some.size(), whole);
}

} // namespace
