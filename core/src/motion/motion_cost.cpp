// Trees timed on a recorded motion: every step's queries of the recorded object against its
// partners, the trees taking turns within each round, each query keeping its best time.
#include "spt/deforming_model.hpp"
#include "spt/error.hpp"
#include "spt/motion.hpp"
#include <algorithm>
#include <chrono>
#include <limits>

namespace spt {
namespace {

// One tree's model, posed per step when the object deforms.
struct TimedTree {
    std::unique_ptr<CollisionModel> rigid;
    std::unique_ptr<DeformingModel> deforming;
    const CollisionModel& model() const { return deforming ? deforming->model() : *rigid; }
};

} // namespace

std::vector<MotionCost> measure_motion_cost(const MotionRecording& rec, const std::vector<const SamplingTree*>& trees,
                                            const QueryOptions& query, int rounds, const std::atomic<bool>* cancel,
                                            const std::function<void(double)>& progress) {
    if (!rec.model.document || !rec.scene) throw Error(ErrorKind::BadInput, "measure_motion_cost: an empty recording");
    const Scene& scene = *rec.scene;
    const SptDocument& recorded = *rec.model.document;
    const bool exact = query.level == QueryLevel::Exact;
    const bool deforms = !rec.clip.empty();
    if (exact && !rec.model.mesh)
        throw Error(ErrorKind::BadInput, "level 'exact' needs the mesh the document was made from");
    // The trees in a document of their own over the recorded samples, named t0, t1, ...
    SptDocument doc;
    doc.mesh = recorded.mesh;
    doc.samples = recorded.samples;
    for (size_t t = 0; t < trees.size(); ++t) {
        if (!trees[t]) throw Error(ErrorKind::BadInput, "measure_motion_cost: a null tree");
        if (const std::string why = trees[t]->validate(uint32_t(doc.samples.size())); !why.empty())
            throw Error(ErrorKind::BadInput, "tree '" + trees[t]->name() + "' is not a tree over the recorded samples: " + why);
        SamplingTree copy = *trees[t];
        copy.set_name("t" + std::to_string(t));
        doc.trees.push_back(std::move(copy));
    }
    std::vector<TimedTree> models(trees.size());
    const Clip* clip = nullptr;
    if (deforms) clip = &rec.model.mesh->clips[rec.model.mesh->find_clip(rec.clip)];
    for (size_t t = 0; t < trees.size(); ++t) {
        const std::string name = "t" + std::to_string(t);
        if (deforms)
            models[t].deforming = std::make_unique<DeformingModel>(doc, rec.model.mesh, name, exact);
        else
            // The triangles only for `exact`: their tree is most of a large model's setup.
            models[t].rigid = exact ? std::make_unique<CollisionModel>(doc, rec.model.mesh->imported.mesh, name)
                                    : std::make_unique<CollisionModel>(doc, name);
    }
    // Animated partners are posed at their recorded clip times, each its own model.
    std::vector<std::unique_ptr<DeformingModel>> partner_pose(scene.objects.size());
    const bool deform_effect = scene.effects.has(Effect::Deform);
    for (size_t j = 0; j < scene.objects.size(); ++j) {
        const SceneObject& o = scene.objects[j];
        if (j != rec.object_index && deform_effect && o.animated && o.animated_mesh && o.document)
            partner_pose[j] = std::make_unique<DeformingModel>(*o.document, o.animated_mesh, o.tree, exact);
    }
    size_t queries = 0;
    for (const MotionStep& st : rec.steps) queries += st.partners.size();
    std::vector<MotionCost> out(trees.size());
    std::vector<std::vector<double>> best(trees.size(), std::vector<double>(queries, std::numeric_limits<double>::infinity()));
    std::vector<double> node_pairs(trees.size()), sphere_tests(trees.size());
    std::vector<size_t> collided(trees.size());
    QueryScratch scratch;
    using Clock = std::chrono::steady_clock;
    const int R = std::max(1, rounds);
    size_t met = 0; // steps with queries: what the progress counts
    for (const MotionStep& st : rec.steps) met += !st.partners.empty();
    const double total = double(R) * double(std::max<size_t>(1, met));
    size_t done_steps = 0;
    for (int r = 0; r < R; ++r) {
        size_t q = 0;
        for (size_t s = 0; s < rec.steps.size(); ++s) {
            if (cancel && cancel->load()) {
                for (MotionCost& c : out) c.cancelled = true;
                return out;
            }
            const MotionStep& st = rec.steps[s];
            if (st.partners.empty()) continue;
            for (const MotionPartner& p : st.partners)
                if (partner_pose[p.object]) {
                    const SceneObject& o = scene.objects[p.object];
                    partner_pose[p.object]->pose(&o.animated_mesh->clips[o.clip], p.clip_time);
                }
            // The trees take turns, starting one later each step and round.
            for (size_t n = 0; n < models.size(); ++n) {
                const size_t t = (n + s + size_t(r)) % models.size();
                // Posed right before its queries, as a simulation poses an object, and each query run
                // once untimed first: every tree is timed warm, whichever was posed last.
                if (deforms) models[t].deforming->pose(clip, st.clip_time);
                size_t qt = q;
                for (const MotionPartner& p : st.partners) {
                    const CollisionModel& b =
                        partner_pose[p.object] ? partner_pose[p.object]->model() : *scene.objects[p.object].model;
                    collide_relative(models[t].model(), b, p.pose, query, scratch);
                    const auto t0 = Clock::now();
                    const QueryResult res = collide_relative(models[t].model(), b, p.pose, query, scratch);
                    const double ns = double(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count());
                    best[t][qt] = std::min(best[t][qt], ns);
                    if (r == 0) {
                        out[t].counters.push_back(res.counters);
                        node_pairs[t] += double(res.counters.node_pairs);
                        sphere_tests[t] += double(res.counters.sphere_tests);
                        collided[t] += res.collide;
                    }
                    ++qt;
                }
            }
            q += st.partners.size();
            if (progress) progress(double(++done_steps) / total);
        }
    }
    for (size_t t = 0; t < trees.size(); ++t) {
        MotionCost& c = out[t];
        c.queries = queries;
        if (queries == 0) continue;
        // A step's time is the sum of its queries' (one per partner); the median is over the steps.
        std::vector<double> per_step;
        size_t q = 0;
        for (const MotionStep& st : rec.steps) {
            if (st.partners.empty()) continue;
            double sum = 0;
            for (size_t k = 0; k < st.partners.size(); ++k) sum += best[t][q++];
            per_step.push_back(sum);
        }
        std::sort(per_step.begin(), per_step.end());
        for (double v : per_step) c.mean_ns += v / double(per_step.size());
        c.median_ns = per_step[per_step.size() / 2];
        c.p90_ns = per_step[per_step.size() * 9 / 10];
        c.mean_node_pairs = node_pairs[t] / double(queries);
        c.mean_sphere_tests = sphere_tests[t] / double(queries);
        c.collide_share = double(collided[t]) / double(queries);
    }
    return out;
}

} // namespace spt
