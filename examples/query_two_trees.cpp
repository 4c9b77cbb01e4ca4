// Example: load two .spt files and collide B against A at one pose: any, deepest and the
// backtrack along B's motion, using only the installed public API.
// Usage: query_two_trees A.spt B.spt [tx ty tz [qw qx qy qz [dx dy dz]]]
#include <spt/spt.hpp>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s A.spt B.spt [tx ty tz [qw qx qy qz [dx dy dz]]]\n", argv[0]);
        return 1;
    }
    std::vector<double> v;
    for (int i = 3; i < argc; ++i) {
        char* end = nullptr;
        v.push_back(std::strtod(argv[i], &end));
        if (*end != '\0' || !std::isfinite(v.back())) {
            std::fprintf(stderr, "error: '%s' is not a finite number\n", argv[i]);
            return 1;
        }
    }
    v.resize(13, 0.0);
    if (argc <= 6) v[3] = 1; // no rotation given: the identity
    try {
        const spt::SptDocument a_doc = spt::load_spt(argv[1]), b_doc = spt::load_spt(argv[2]);
        const spt::CollisionModel a(a_doc), b(b_doc);
        // B's pose in the world; A stays at the identity. Model units.
        const spt::Pose pose_b =
            spt::Pose::from({v[0], v[1], v[2]}, Eigen::Quaterniond(v[3], v[4], v[5], v[6]));
        const Eigen::Vector3d motion(v[7], v[8], v[9]);

        spt::QueryScratch scratch; // one per thread, reused by every query
        spt::QueryOptions options;
        options.mode = spt::QueryMode::Any;
        const spt::QueryResult any = spt::collide(a, spt::Pose::identity(), b, pose_b, options, scratch);
        std::printf("any: %s (%llu node pairs, %llu sphere tests)\n", any.collide ? "collide" : "apart",
                    (unsigned long long)any.counters.node_pairs, (unsigned long long)any.counters.sphere_tests);

        options.mode = spt::QueryMode::Deepest;
        const spt::QueryResult deepest = spt::collide(a, spt::Pose::identity(), b, pose_b, options, scratch);
        if (deepest.collide) {
            const spt::Contact& c = deepest.deepest;
            std::printf("deepest: depth %.6g at (%.4g %.4g %.4g), normal (%.3f %.3f %.3f)\n", c.depth, c.point.x(),
                        c.point.y(), c.point.z(), c.normal.x(), c.normal.y(), c.normal.z());
        }
        if (deepest.collide && motion.norm() > 0) {
            const spt::BacktrackResult back = spt::backtrack(a, spt::Pose::identity(), b, pose_b, motion, options,
                                                             spt::BacktrackRule::Exact, scratch);
            std::printf("backtrack: move B back %.6g along its motion (%d queries)\n", back.distance, back.queries);
        }
        return 0;
    } catch (const spt::Error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return e.kind() == spt::ErrorKind::BadInput ? 2 : 1; // this program's exit codes
    }
}
