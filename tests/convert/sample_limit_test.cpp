// A tolerance far below a mesh's detail is refused before it samples for hours into all memory.
#include "mesh/shapes.hpp"
#include "sampling/radius_class.hpp"
#include "sampling/surface_samples.hpp"
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include "test_support.hpp"
#include <gtest/gtest.h>

using namespace spt;

namespace {

struct Case {
    std::string name;
    TriangleMesh mesh;
    double coarser = 1; // tolerances this many times larger (two-sided samples grow as 1/tolerance^2)
};

// Closed and open, fine and coarse, one-sided and two-sided faces.
std::vector<Case> meshes() {
    std::vector<Case> c;
    c.push_back({"torus", make_torus(1.0, 0.35, 24, 12), 1});
    c.push_back({"box", make_box({0.5, 0.2, 0.3}, 1), 1});
    c.push_back({"sheet (open)", make_sheet(2.0, 3), 5});
    c.push_back({"bracket", make_bracket(), 1});
    c.push_back({"cad_part", import_mesh(test::project_meshes() + "/cad_part.stl").mesh, 1});
    return c;
}

TEST(SampleLimit, LeastFaceSamplesIsALowerBoundOnTheSamplesMadeAndNotFarBelowThem) {
    for (const Case& c : meshes())
        for (double relative : {0.05, 0.01, 0.004}) {
            const double tolerance = c.coarser * relative * c.mesh.diagonal(), eps = tolerance / 2;
            // As make_document sets the limiter for a tolerance.
            const RadiusLimiter limiter(c.mesh, tolerance / 8, tolerance / 4);
            const float factor = 1.0f / kRadiusClassRatio;
            const double least = least_face_samples(limiter, eps, {}, factor);
            const size_t made = face_samples(limiter, Eigen::Vector3d::Zero(), eps, {}, factor, 1).size();
            EXPECT_LE(least, double(made)) << c.name << " at " << relative;
            // A bound that grows with the count, not a vacuous one: radii below the rule's
            // (sharp edges, thin walls) and bisection's leaves below the largest accepted keep
            // it 2.5-300x under the count on these meshes; the running limit covers the rest.
            if (made > 20000) {
                EXPECT_GT(least, 0.002 * double(made)) << c.name << " at " << relative;
            }
        }
}

TEST(SampleLimit, ToleranceFarBelowTheMeshsDetailIsBadInputNamingItBeforeFacesAreSampled) {
    TriangleMesh mesh = make_torus(1.0, 0.35, 24, 12);
    mesh.name = "ring.obj";
    ConvertOptions o;
    o.tolerance = 1e-7; // model units: 4e-8 of the diagonal, about 1e13 face samples
    std::vector<std::string> stages;
    o.on_stage = [&](const std::string& s) { stages.push_back(s); };
    try {
        make_document(mesh, o);
        FAIL() << "a tolerance needing 1e13 samples was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::BadInput);
        const std::string what = e.what();
        EXPECT_NE(what.find("ring.obj"), std::string::npos) << what;
        EXPECT_NE(what.find("tolerance"), std::string::npos) << what;
        EXPECT_NE(what.find(std::to_string(kMaxSamples)), std::string::npos) << what;
    }
    EXPECT_EQ(std::find(stages.begin(), stages.end(), "sampling faces"), stages.end());
}

TEST(SampleLimit, FaceSamplesStopOnceTheyPassTheirLimitOnOneThreadOrMore) {
    const TriangleMesh mesh = make_torus(1.0, 0.35, 24, 12);
    const RadiusLimiter limiter(mesh, 0.002);
    const size_t all = face_samples(limiter, Eigen::Vector3d::Zero(), 0.01, {}, 0.5f, 1).size();
    ASSERT_GT(all, 1000u);
    for (int threads : {1, 2}) {
        try {
            face_samples(limiter, Eigen::Vector3d::Zero(), 0.01, {}, 0.5f, threads, nullptr, 1000);
            FAIL() << "no stop at 1,000 samples on " << threads << " threads";
        } catch (const TooManySamples& t) {
            EXPECT_GT(t.reached, 1000u);
            EXPECT_LE(t.reached, all);
        }
        // At the count itself nothing stops.
        EXPECT_EQ(face_samples(limiter, Eigen::Vector3d::Zero(), 0.01, {}, 0.5f, threads, nullptr, all).size(), all);
    }
}

TEST(SampleLimit, OneFaceStopsWithinItselfOnceItsSamplesPassItsRoom) {
    // A single face can ask for more samples than memory holds: it stops at the limit, not
    // after it has made them all.
    const TriangleMesh mesh = make_box({0.5, 0.5, 0.5}, 1);
    const RadiusLimiter limiter(mesh, 1e-5);
    SampleSet all;
    add_face_samples(all, limiter, 0, 2e-3, {}, 0.5f);
    ASSERT_GT(all.size(), 500u);
    SampleSet some;
    try {
        add_face_samples(some, limiter, 0, 2e-3, {}, 0.5f, 500);
        FAIL() << "a face of " << all.size() << " samples did not stop at 500";
    } catch (const TooManySamples& t) {
        EXPECT_EQ(t.reached, 501u);
        EXPECT_EQ(some.size(), 500u);
    }
    SampleSet exactly;
    add_face_samples(exactly, limiter, 0, 2e-3, {}, 0.5f, all.size());
    EXPECT_EQ(exactly.size(), all.size());
}

} // namespace
