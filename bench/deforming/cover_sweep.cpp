// Whether a lazy pose's balls near the root hold every sphere, on models spt was not written
// against: for each animated mesh given, converted with spt convert's defaults, every sphere of
// a full pose at frames along each clip must lie in each cover and node above it of a lazy pose,
// with the default and the tight covers (DeformingModel::set_tight_refit), in regions of 512 and
// of 16 samples. Prints a line a model and region size; exit 1 when a sphere escapes a ball.
// (docs/deforming.md, "Lazy refit")
#include "query/pending_pose.hpp"
#include "spt/animation.hpp"
#include "spt/convert.hpp"
#include "spt/deforming_model.hpp"
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace spt;

struct Tally {
    long spheres = 0, escaped = 0;
    double slack = 0; // how much larger than their spheres need the balls are, summed (model units)
};

// Every sphere of the full pose's tree `full` against each ball the lazy pose `lazy` fits at once
// (its covers and the nodes above them: PendingPose::loose).
void check(const CollisionModel& lazy, const CompactTree& full, Tally& t) {
    const detail::PendingPose* pending = detail::pending_of(lazy);
    if (!pending) return; // posed in full: no ball is fitted before its spheres
    const CompactTree& tree = lazy.tree();
    std::vector<uint32_t> stack;
    for (uint32_t a = 0; a < tree.nodes().size(); ++a) {
        if (!pending->loose(a)) continue;
        const CompactNode& n = tree.nodes()[a];
        const Eigen::Vector3f c(n.center[0], n.center[1], n.center[2]);
        float farthest = 0;
        stack.assign(1, a);
        while (!stack.empty()) {
            const uint32_t i = stack.back();
            stack.pop_back();
            const CompactNode& below = full.nodes()[i];
            if (!below.is_active()) {
                stack.push_back(i + 1), stack.push_back(below.first);
                continue;
            }
            for (uint32_t k = below.first; k < below.first + below.count; ++k) {
                const float reach = (full.sphere_center(below, k) - c).norm() + below.ss_radius;
                ++t.spheres;
                t.escaped += !(reach <= n.bv_radius);
                farthest = std::max(farthest, reach);
            }
        }
        t.slack += double(n.bv_radius) - double(farthest);
    }
}

} // namespace

int main(int argc, char** argv) {
    int frames = 24;
    std::vector<std::string> paths;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--frames" && i + 1 < argc) {
            frames = std::atoi(argv[++i]);
            if (frames < 1 || frames > 10000) return std::fprintf(stderr, "cover_sweep: --frames takes 1 to 10000\n"), 1;
        } else if (!a.empty() && a[0] == '-') {
            std::fprintf(stderr, "usage: cover_sweep [--frames N] ANIMATED_MESH...\n");
            return 1;
        } else {
            paths.push_back(a);
        }
    }
    if (paths.empty()) return std::fprintf(stderr, "usage: cover_sweep [--frames N] ANIMATED_MESH...\n"), 1;
    long escaped = 0;
    for (const std::string& path : paths) {
        try {
            auto mesh = std::make_shared<const AnimatedMesh>(import_animated_mesh(path));
            if (mesh->clips.empty()) continue; // nothing deforms it
            const SptDocument doc = make_document(mesh->imported.mesh);
            if (doc.samples.size() == 0) continue;
            for (uint32_t region : {512u, 16u}) {
                DeformingModel full(doc, mesh, "", false);
                Tally tally[2];
                for (int tight = 0; tight < 2; ++tight) {
                    DeformingModel lazy(doc, mesh, "", false);
                    lazy.set_lazy_region(region);
                    lazy.set_tight_refit(tight);
                    for (const Clip& clip : mesh->clips)
                        for (int k = 0; k <= frames; ++k) {
                            const double t = clip.duration * k / frames;
                            lazy.pose_lazily(&clip, t);
                            full.pose(&clip, t);
                            check(lazy.model(), full.model().tree(), tally[tight]);
                        }
                }
                escaped += tally[0].escaped + tally[1].escaped;
                std::printf("%s, regions of %u: %zu samples, %zu clips, %ld sphere checks a fit; escaped %ld (default) "
                            "%ld (tight); tight slack %.2f of the default's\n",
                            path.c_str(), region, doc.samples.size(), mesh->clips.size(), tally[0].spheres,
                            tally[0].escaped, tally[1].escaped, tally[1].slack / tally[0].slack);
                std::fflush(stdout);
            }
        } catch (const std::exception& e) {
            std::printf("%s: skipped (%s)\n", path.c_str(), e.what());
        }
    }
    return escaped ? 1 : 0;
}
