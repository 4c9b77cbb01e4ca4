// Far from the origin: a mesh exported in world units (vertices 1e3 to 1e6 from its file's
// origin), and objects placed far out in the world, answer as the same pair at the origin.
#include "hard_support.hpp"
#include "spt/ccd.hpp"
#include "spt/response.hpp"
#include <gtest/gtest.h>

namespace spt {
namespace {

using hard::NearContact;

const double kOffsets[] = {1e3, 1e4, 1e5, 1e6};
const Eigen::Vector3d kAway = Eigen::Vector3d(1, -0.6, 0.3).normalized();

struct Subject {
    const char* name;
    TriangleMesh mesh;
};

std::vector<Subject> subjects() {
    return {{"bracket", scale_to_unit_cube(make_bracket())}, {"torus", make_torus(1.0, 0.35, 40, 20)}};
}

// The same model with its geometry 1e3 to 1e6 from the object origin (its local origin moved,
// its mesh moved): only the query's frames differ, so every answer must match the model at
// the origin, and the far walk visits the same node pairs.
TEST(FarFromOrigin, SameModelFarFromItsObjectOriginAnswersAsAtTheOrigin) {
    for (const Subject& subject : subjects()) {
        const auto at_origin = hard::make_object(subject.mesh);
        const double diag = subject.mesh.diagonal();
        const Eigen::Vector3d c0 = 0.5 * (subject.mesh.bounds().first + subject.mesh.bounds().second);
        const auto contacts = hard::near_contacts(at_origin->model, at_origin->model, c0, diag, 30, 5);
        for (double offset : kOffsets) {
            SptDocument doc = at_origin->doc;
            doc.samples.origin += offset * kAway;
            TriangleMesh mesh = at_origin->mesh;
            for (auto& p : mesh.positions) p += offset * kAway;
            const CollisionModel far(doc); // bounds and spheres need no mesh
            const CollisionModel far_exact = [&] {
                // The content hash is of float positions, which the move changes.
                SptDocument d = doc;
                d.mesh.hash = mesh.content_hash();
                return CollisionModel(d, mesh);
            }();
            const Eigen::Vector3d cf = c0 + offset * kAway;
            QueryScratch s;
            for (QueryLevel level : {QueryLevel::Bounds, QueryLevel::Spheres, QueryLevel::Exact}) {
                QueryOptions o;
                o.level = level;
                const CollisionModel& m = level == QueryLevel::Exact ? far_exact : far;
                uint64_t pairs0 = 0, pairsf = 0;
                for (const NearContact& c : contacts)
                    for (double delta : {-0.01, 0.01, -0.001, 0.001}) {
                        const double d = c.contact + delta * diag;
                        const QueryResult r0 =
                            collide_relative(at_origin->model, at_origin->model, hard::pose_at(c, d, c0), o, s);
                        const QueryResult rf = collide_relative(m, m, hard::pose_at(c, d, cf), o, s);
                        EXPECT_EQ(r0.collide, rf.collide) << subject.name << " offset " << offset << " level " << int(level);
                        pairs0 += r0.counters.node_pairs, pairsf += rf.counters.node_pairs;
                    }
                EXPECT_LE(pairsf, 2 * pairs0) << subject.name << " offset " << offset << " level " << int(level);
                EXPECT_GE(2 * pairsf, pairs0) << subject.name << " offset " << offset << " level " << int(level);
            }
            // Depth, contact point, backtrack and time of impact of the sphere model.
            QueryOptions deepest;
            deepest.mode = QueryMode::Deepest;
            for (const NearContact& c : contacts) {
                const double d = c.contact - 0.02 * diag;
                const Pose p0 = hard::pose_at(c, d, c0), pf = hard::pose_at(c, d, cf);
                const QueryResult r0 = collide_relative(at_origin->model, at_origin->model, p0, deepest, s);
                const QueryResult rf = collide_relative(far, far, pf, deepest, s);
                ASSERT_EQ(r0.collide, rf.collide);
                if (!r0.collide) continue;
                EXPECT_NEAR(r0.deepest.depth, rf.deepest.depth, 1e-5 * diag);
                EXPECT_LE((r0.deepest.point + offset * kAway - rf.deepest.point).norm(), 1e-5 * diag) << "contact in A's frame";
                const BacktrackResult b0 =
                    backtrack_relative(at_origin->model, at_origin->model, p0, -c.direction, {}, BacktrackRule::Exact, s);
                const BacktrackResult bf = backtrack_relative(far, far, pf, -c.direction, {}, BacktrackRule::Exact, s);
                EXPECT_NEAR(b0.distance, bf.distance, 1e-5 * diag);
                const double start = c.contact + 0.05 * diag;
                const CcdResult t0 = first_contact(at_origin->model, at_origin->model, hard::pose_at(c, start, c0), p0, {}, s);
                const CcdResult tf = first_contact(far, far, hard::pose_at(c, start, cf), pf, {}, s);
                EXPECT_EQ(t0.hit, tf.hit);
                // Both are within the search's resolution below the same first contact.
                const double resolution = 4 * 1e-4 * diag / (start - d);
                EXPECT_NEAR(t0.toi, tf.toi, resolution);
            }
        }
    }
}

// A mesh exported in world units converts to an equivalent model: its local origin sits with
// the geometry, and near contact the sphere and exact levels answer as for the mesh at the
// origin (the two conversions differ only by rounding, so the trees may differ).
TEST(FarFromOrigin, MeshExportedInWorldUnitsConvertsToAnEquivalentModel) {
    for (const Subject& subject : subjects()) {
        const auto at_origin = hard::make_object(subject.mesh);
        const double diag = subject.mesh.diagonal();
        const Eigen::Vector3d c0 = 0.5 * (subject.mesh.bounds().first + subject.mesh.bounds().second);
        const auto contacts = hard::near_contacts(at_origin->model, at_origin->model, c0, diag, 30, 7);
        for (double offset : kOffsets) {
            const auto far = hard::make_object(hard::transformed(subject.mesh, 1.0, offset * kAway));
            EXPECT_LE((far->doc.samples.origin - offset * kAway).norm(), 2 * diag) << "the local origin sits with the mesh";
            const double n0 = double(at_origin->doc.samples.size()), nf = double(far->doc.samples.size());
            EXPECT_NEAR(nf, n0, 0.01 * n0) << subject.name << " offset " << offset;
            const Eigen::Vector3d cf = c0 + offset * kAway;
            QueryScratch s;
            for (QueryLevel level : {QueryLevel::Spheres, QueryLevel::Exact}) {
                QueryOptions o;
                o.level = level;
                uint64_t pairs0 = 0, pairsf = 0;
                for (const NearContact& c : contacts)
                    for (double delta : {-0.01, 0.01}) {
                        const double d = c.contact + delta * diag;
                        const QueryResult r0 =
                            collide_relative(at_origin->model, at_origin->model, hard::pose_at(c, d, c0), o, s);
                        const QueryResult rf = collide_relative(far->model, far->model, hard::pose_at(c, d, cf), o, s);
                        EXPECT_EQ(r0.collide, rf.collide) << subject.name << " offset " << offset << " level " << int(level);
                        pairs0 += r0.counters.node_pairs, pairsf += rf.counters.node_pairs;
                    }
                EXPECT_LE(pairsf, 2 * pairs0) << subject.name << " offset " << offset << " level " << int(level);
            }
        }
    }
}

// The pair placed far out in the world (1e3 to 1e9) answers as at the world origin: poses are
// composed in double and only the difference of the two reaches the float walk.
TEST(FarFromOrigin, PairPlacedFarOutInTheWorldAnswersAsAtTheOrigin) {
    const Subject subject = subjects()[0];
    const auto o = hard::make_object(subject.mesh);
    const double diag = subject.mesh.diagonal();
    const Eigen::Vector3d c0 = 0.5 * (subject.mesh.bounds().first + subject.mesh.bounds().second);
    const auto contacts = hard::near_contacts(o->model, o->model, c0, diag, 30, 9);
    QueryScratch s;
    for (double world : {1e3, 1e6, 1e9})
        for (const NearContact& c : contacts)
            for (double delta : {-0.01, 0.01}) {
                const Pose rel = hard::pose_at(c, c.contact + delta * diag, c0);
                const Pose place = Pose::from(world * kAway, Eigen::Quaterniond(Eigen::AngleAxisd(0.7, kAway)));
                const QueryResult r0 = collide(o->model, Pose{}, o->model, rel, {}, s);
                const QueryResult rw = collide(o->model, place, o->model, place * rel, {}, s);
                EXPECT_EQ(r0.collide, rw.collide) << "world offset " << world;
                EXPECT_LE(rw.counters.node_pairs, 2 * r0.counters.node_pairs + 10) << "world offset " << world;
            }
}

} // namespace
} // namespace spt
