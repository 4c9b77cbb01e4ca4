// The build from motion against the automatic trees (leaf sizes 4, 8, 16) on a scene's motion
// and at random poses, trees taking turns in every round, each query keeping its best time:
// the figures of docs/editor.md, "Authoring from motion".
// usage: motion_bench SCENE.json OBJECT MODEL [--mesh MESH] [--rounds N] [--random N] [--steps N]
//   MODEL the object's .spt file or mesh (converted with spt convert's defaults); --mesh the
//   mesh a .spt file was made from (with its clips for an animated object).
#include "spt/spt.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace spt;

namespace {

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: motion_bench SCENE.json OBJECT MODEL [--mesh MESH] [--rounds N] [--random N] [--steps N]\n");
        return 2;
    }
    std::string scene_path = argv[1], object = argv[2], model_path = argv[3], mesh_path;
    int rounds = 5, random = 400, steps = 0;
    for (int i = 4; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--mesh")) mesh_path = argv[i + 1];
        else if (!std::strcmp(argv[i], "--rounds")) rounds = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--random")) random = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--steps")) steps = std::atoi(argv[i + 1]);
    }
    try {
        const Scene scene = load_scene(scene_path);
        const uint32_t index = find_object(scene, object);
        const SceneObject& o = scene.objects[index];
        auto doc = std::make_shared<SptDocument>(load_or_convert(model_path));
        auto mesh = std::make_shared<AnimatedMesh>();
        const std::string from = mesh_path.empty() ? (is_spt_file(model_path) ? std::string() : model_path) : mesh_path;
        if (!from.empty()) {
            if (o.animated) *mesh = import_animated_mesh(from);
            else mesh->imported = import_mesh(from);
        }
        MotionModel model{doc, o.tree, from.empty() ? nullptr : mesh};
        MotionOptions mo;
        mo.steps = steps;
        mo.threads = 2;
        // The scene alone, as spt simulate runs it: what the recording adds to it is the heat map's work.
        auto t0 = std::chrono::steady_clock::now();
        {
            Simulation sim(scene, scene.effects, 2);
            for (int k = 0, n = steps > 0 ? steps : scene.steps; k < n; ++k) sim.step();
        }
        const double simulate_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        t0 = std::chrono::steady_clock::now();
        const MotionRecording rec = record_motion(scene, object, model, mo);
        const double record_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("%s / %s: %zu steps (%u in contact), %zu samples, recorded in %.2f s (the scene alone %.2f s)\n",
                    scene_path.c_str(), object.c_str(), rec.steps.size(), rec.steps_in_contact, doc->samples.size(),
                    record_s, simulate_s);
        std::vector<SamplingTree> trees;
        std::vector<std::string> names;
        for (uint32_t leaf : {4u, 8u, 16u}) {
            BuildOptions b;
            b.leaf_size = leaf;
            b.threads = 2;
            t0 = std::chrono::steady_clock::now();
            trees.push_back(build_tree("auto" + std::to_string(leaf), doc->samples, b));
            std::printf("auto leaf %u built in %.3f s\n", leaf,
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
            names.push_back("auto leaf " + std::to_string(leaf));
        }
        for (uint32_t leaf : {4u, 8u}) {
            MotionBuildOptions mb;
            mb.build.leaf_size = leaf;
            mb.build.threads = 2;
            t0 = std::chrono::steady_clock::now();
            MotionBuildReport report;
            trees.push_back(build_motion_tree("motion" + std::to_string(leaf), doc->samples, rec, mb, &report));
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            names.push_back("motion leaf " + std::to_string(leaf));
            std::printf("motion leaf %u built in %.3f s: work %.1f (weight %g) against the automatic build's %.1f%s\n",
                        leaf, s, report.work_motion, report.random_weight, report.work_automatic,
                        report.kept_automatic ? ": kept the automatic build" : "");
        }
        std::vector<const SamplingTree*> ptrs;
        for (const SamplingTree& t : trees) ptrs.push_back(&t);
        const std::vector<MotionCost> on_motion = measure_motion_cost(rec, ptrs, QueryOptions{}, rounds);
        // Random poses of the partner met most against each tree (the object at its bind pose).
        std::vector<size_t> met(scene.objects.size(), 0);
        for (const MotionStep& st : rec.steps)
            for (const MotionPartner& p : st.partners) ++met[p.object];
        const uint32_t partner = uint32_t(std::max_element(met.begin(), met.end()) - met.begin());
        const CollisionModel& b = *rec.scene->objects[partner].model;
        SptDocument copy;
        copy.mesh = doc->mesh;
        copy.samples = doc->samples;
        copy.trees = trees;
        std::vector<CollisionModel> models;
        for (const SamplingTree& t : trees) models.emplace_back(copy, t.name());
        CostOptions co;
        co.random_poses = random;
        co.near_poses = 0;
        const CostPoses poses = cost_poses(models[1], b, co);
        std::vector<std::vector<double>> best(trees.size(), std::vector<double>(poses.random.size(), 1e300));
        std::vector<double> random_pairs(trees.size(), 0);
        QueryScratch scratch;
        for (int r = 0; r < rounds; ++r)
            for (size_t k = 0; k < poses.random.size(); ++k)
                for (size_t n = 0; n < trees.size(); ++n) {
                    const size_t t = (n + k + size_t(r)) % trees.size();
                    const auto q0 = std::chrono::steady_clock::now();
                    const QueryResult res = collide_relative(models[t], b, poses.random[k], QueryOptions{}, scratch);
                    if (r == 0) random_pairs[t] += double(res.counters.node_pairs) / double(poses.random.size());
                    best[t][k] = std::min(best[t][k],
                                          double(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                                     std::chrono::steady_clock::now() - q0).count()));
                }
        for (size_t t = 0; t < trees.size(); ++t) {
            std::vector<double> np;
            for (const QueryCounters& c : on_motion[t].counters) np.push_back(double(c.node_pairs));
            std::sort(np.begin(), np.end());
            if (!np.empty())
                std::printf("%s node pairs: p10 %.0f p50 %.0f p90 %.0f max %.0f\n", names[t].c_str(), np[np.size() / 10],
                            np[np.size() / 2], np[np.size() * 9 / 10], np.back());
        }
        size_t best_auto = 0;
        for (size_t t = 1; t < 3; ++t)
            if (on_motion[t].median_ns < on_motion[best_auto].median_ns) best_auto = t;
        const double random_auto = median(best[best_auto]);
        std::printf("| tree | motion: median ns | mean ns | p90 ns | node pairs | sphere tests | collide | vs best auto | random: median ns | node pairs | vs best auto |\n");
        std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
        for (size_t t = 0; t < trees.size(); ++t) {
            const double rnd = median(best[t]);
            std::printf("| %s%s | %.0f | %.0f | %.0f | %.1f | %.1f | %.2f | %.2f | %.0f | %.1f | %.2f |\n", names[t].c_str(),
                        t == best_auto ? " (best auto)" : "", on_motion[t].median_ns, on_motion[t].mean_ns, on_motion[t].p90_ns,
                        on_motion[t].mean_node_pairs,
                        on_motion[t].mean_sphere_tests, on_motion[t].collide_share,
                        on_motion[t].median_ns / on_motion[best_auto].median_ns, rnd, random_pairs[t], rnd / random_auto);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "motion_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
