// Runs a scene with one object's tree and records its motion: poses, partners, the samples
// whose spheres took part in a contact, and the samples near a partner at evenly spread steps.
#include "base/parallel.hpp"
#include "spt/error.hpp"
#include "spt/motion.hpp"
#include "spt/query.hpp"
#include "spt/simulation.hpp"
#include <algorithm>
#include <cmath>
#include <sstream>

namespace spt {
namespace {

// Marks every sample of the recorded object whose sampling sphere overlaps one of the partner's.
void mark_contacts(const CollisionModel& object, const CollisionModel& partner, const Pose& partner_in_object,
                   QueryScratch& scratch, std::vector<uint32_t>& stamp, uint32_t step_stamp, std::vector<uint32_t>& counts) {
    QueryOptions all;
    all.mode = QueryMode::All;
    all.solids = false; // spheres that meet, not containment: the heat map shows surfaces
    collide_relative(object, partner, partner_in_object, all, scratch);
    const uint32_t* sample = object.tree().sample_index();
    for (const SpherePair& p : scratch.pairs()) {
        const uint32_t s = sample[p.a];
        if (stamp[s] == step_stamp) continue;
        stamp[s] = step_stamp;
        ++counts[s];
    }
}

// Gaps (model units, clamped at 0) of the object's sample points within `reach` of the partner's
// leaf bounding spheres, kept per sample in `gap` (min over partners and leaves). The points are the
// samples' own (`rigid`, the local frame) or, on a deformed object, its spheres' centres moved back
// out along their normals by their radii: either way what the object's tree is does not matter.
void measure_reach(const CollisionModel& object, const CollisionModel& partner, const Pose& partner_in_object,
                   float reach, const SampleSet* rigid, QueryScratch& scratch, std::vector<float>& gap,
                   std::vector<uint32_t>& touched) {
    QueryOptions leaves;
    leaves.level = QueryLevel::Bounds;
    leaves.mode = QueryMode::All;
    leaves.solids = false;
    leaves.inflate = reach;
    collide_relative(object, partner, partner_in_object, leaves, scratch);
    const CompactTree& a = object.tree();
    const CompactTree& b = partner.tree();
    const uint32_t* sample = a.sample_index();
    for (const SpherePair& p : scratch.pairs()) {
        const CompactNode& na = a.nodes()[p.node_a];
        const CompactNode& nb = b.nodes()[p.node_b];
        const Eigen::Vector3d cb =
            partner_in_object.apply(Eigen::Vector3d(nb.center[0], nb.center[1], nb.center[2]) + partner.origin()) -
            object.origin();
        for (uint32_t k = na.first; k < na.first + na.count; ++k) {
            const uint32_t s = sample[k];
            Eigen::Vector3d point;
            if (rigid) {
                point = rigid->points[s].cast<double>();
            } else {
                const bool two_sided = a.two_sided() && a.two_sided()[k];
                const Eigen::Vector3d n(a.nx()[k] / 127.0, a.ny()[k] / 127.0, a.nz()[k] / 127.0);
                point = a.sphere_center(na, k).cast<double>() + (two_sided ? 0.0 : double(na.ss_radius)) * n;
            }
            const double d = (point - cb).norm() - nb.bv_radius;
            const float g = float(std::max(0.0, d));
            if (!(g < reach)) continue;
            if (std::isinf(gap[s])) touched.push_back(s);
            gap[s] = std::min(gap[s], g);
        }
    }
}

} // namespace

uint32_t find_object(const Scene& scene, const std::string& name) {
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].name == name) return uint32_t(i);
    std::ostringstream why;
    why << scene.file << ": no object named '" << name << "'; it has";
    for (size_t i = 0; i < scene.objects.size(); ++i) why << (i ? ", '" : " '") << scene.objects[i].name << "'";
    if (scene.objects.empty()) why << " none";
    throw Error(ErrorKind::BadInput, why.str());
}

MotionRecording record_motion(const Scene& scene, const std::string& object, const MotionModel& model,
                              const MotionOptions& options) {
    const uint32_t index = find_object(scene, object);
    if (!model.document) throw Error(ErrorKind::BadInput, "record_motion: no document given");
    if (options.steps < 0 || options.threads < 1 || options.reach_steps < 0 || !(options.reach_fraction >= 0))
        throw Error(ErrorKind::Usage, "record_motion: steps, reach_steps and reach_fraction must be >= 0, threads >= 1");
    // A document of another mesh would run, and record another object's motion: refused. The
    // scene's own model of the object carries the diagonal of the mesh it was made from.
    if (const CollisionModel* own = scene.objects[index].model.get()) {
        const double mine = model.document->mesh.diagonal, theirs = own->diagonal();
        if (mine > 0 && theirs > 0 && std::abs(mine - theirs) > 1e-6 * std::max(mine, theirs)) {
            std::ostringstream why;
            why << scene.file << ": object '" << object << "': the document was not made from its model "
                << scene.objects[index].model_path << " (mesh diagonal " << mine << ", the model's " << theirs << ")";
            throw Error(ErrorKind::BadInput, why.str());
        }
    }
    auto run = std::make_shared<Scene>(scene);
    SceneObject& o = run->objects[index];
    // A rigid object's triangles only where the scene tests triangles: their tree is most of a large
    // model's setup, and spheres are what is recorded.
    const bool triangles = scene.level == QueryLevel::Exact || scene.effects.has(Effect::Exact);
    set_object_model(o, model.document, model.tree, o.animated || triangles ? model.mesh : nullptr);

    MotionRecording rec;
    rec.scene_file = scene.file;
    rec.object = object;
    rec.object_index = index;
    rec.tree = o.tree;
    rec.model = model;
    rec.model.tree = o.tree;
    if (!rec.model.mesh && o.animated) rec.model.mesh = o.animated_mesh;
    const bool deforms = o.animated && run->effects.has(Effect::Deform);
    if (deforms) rec.clip = o.animated_mesh->clips[o.clip].name;
    const int steps = options.steps > 0 ? options.steps : run->steps;
    const size_t samples = model.document->samples.size();
    rec.contact_steps.assign(samples, 0);
    rec.reach = (options.reach_fraction > 0 ? options.reach_fraction : 0.04) * model.document->mesh.diagonal;
    if (!(rec.reach > 0)) rec.reach = 0.04 * o.model->extent();

    Simulation sim(*run, run->effects, options.threads, options.tasks);
    // The steps that get a reach: evenly spread, the last one included.
    const int reach_every = options.reach_steps > 0 ? std::max(1, (steps + options.reach_steps - 1) / options.reach_steps) : 0;
    auto with_reach = [&](int k) { return reach_every > 0 && ((steps - 1 - k) % reach_every == 0); };
    const SampleSet* rigid_points = deforms ? nullptr : &model.document->samples;
    // Where no object deforms, every model stays as loaded: the samples of each step are found after
    // the run, the steps spread over the threads (each its own counts, added in the end: the same
    // for any count). A deforming object is posed step by step, so its samples are found as it goes.
    bool any_deforms = false;
    if (run->effects.has(Effect::Deform))
        for (const SceneObject& other : run->objects) any_deforms = any_deforms || other.animated;
    struct Marks {
        QueryScratch scratch;
        std::vector<uint32_t> stamp, counts, touched;
        std::vector<float> gap;
        explicit Marks(size_t n) : stamp(n, 0), counts(n, 0), gap(n, std::numeric_limits<float>::infinity()) {}
    };
    // Step k's samples against its partners (models as `objects` hold them now); its reach into `reach`.
    auto mark_step = [&](Marks& m, const std::vector<SceneObject>& objects, int k, const MotionStep& st, MotionReach* reach) {
        const CollisionModel& mine = *objects[index].model;
        for (const MotionPartner& p : st.partners) {
            const CollisionModel& theirs = *objects[p.object].model;
            if (p.contact) mark_contacts(mine, theirs, p.pose, m.scratch, m.stamp, uint32_t(k + 1), m.counts);
            if (reach) measure_reach(mine, theirs, p.pose, float(rec.reach), rigid_points, m.scratch, m.gap, m.touched);
        }
        if (!reach) return;
        std::sort(m.touched.begin(), m.touched.end());
        reach->step = uint32_t(k);
        reach->near.reserve(m.touched.size());
        for (uint32_t s : m.touched) reach->near.emplace_back(s, m.gap[s]), m.gap[s] = std::numeric_limits<float>::infinity();
        m.touched.clear();
    };
    std::vector<Marks> marks;
    marks.emplace_back(samples);
    rec.steps.reserve(size_t(steps));
    for (int k = 0; k < steps; ++k) {
        if (options.cancel && options.cancel->load()) throw Cancelled("recording the motion was cancelled");
        const StepResult& res = sim.step();
        const Scene& now = sim.scene();
        const std::vector<Pose>& poses = sim.ghost_poses();
        const std::vector<BroadSphere>& spheres = sim.broad_spheres();
        MotionStep st;
        st.step = res.step;
        st.time = res.time;
        st.pose = poses[index];
        bool in_contact = false;
        for (uint32_t j = 0; j < now.objects.size(); ++j) {
            if (j == index) continue;
            if (spheres.size() == now.objects.size() &&
                (!spheres_overlap(spheres[index], spheres[j]) || (spheres[index].is_static && spheres[j].is_static)))
                continue;
            MotionPartner p;
            p.object = j;
            p.pose = relative_pose(poses[index], poses[j]);
            for (const PairContact& c : res.contacts)
                if ((c.a == index && c.b == j) || (c.b == index && c.a == j)) p.contact = true;
            in_contact = in_contact || p.contact;
            st.partners.push_back(p);
        }
        if (in_contact) ++rec.steps_in_contact;
        if (any_deforms) {
            MotionReach reach;
            mark_step(marks.front(), now.objects, k, st, with_reach(k) ? &reach : nullptr);
            if (with_reach(k)) rec.reaches.push_back(std::move(reach));
        }
        rec.steps.push_back(std::move(st));
        if (options.progress) options.progress(k + 1, steps);
    }
    if (!any_deforms) {
        // Known now: the reaches go to steps that meet a partner, evenly spread over those.
        std::vector<int> met;
        for (int k = 0; k < steps; ++k)
            if (!rec.steps[size_t(k)].partners.empty()) met.push_back(k);
        const size_t wanted = std::min(met.size(), size_t(options.reach_steps));
        std::vector<int> reach_of(size_t(steps), -1);
        for (size_t i = 0; i < wanted; ++i) {
            const int k = met[met.size() - 1 - (wanted - 1 - i) * met.size() / wanted]; // the last one included
            if (reach_of[size_t(k)] < 0) reach_of[size_t(k)] = int(rec.reaches.size()), rec.reaches.emplace_back();
        }
        const int jobs = std::max(1, std::min(options.threads, steps));
        while (int(marks.size()) < jobs) marks.emplace_back(samples);
        // Contiguous runs of steps, one a job: a job's stamps stay valid within its run.
        detail::parallel_for(size_t(jobs), jobs, [&](size_t job, int) {
            Marks& m = marks[job];
            for (size_t k = job * size_t(steps) / size_t(jobs); k < (job + 1) * size_t(steps) / size_t(jobs); ++k) {
                if (options.cancel && options.cancel->load()) return;
                const int r = reach_of[k];
                mark_step(m, run->objects, int(k), rec.steps[k], r >= 0 ? &rec.reaches[size_t(r)] : nullptr);
            }
        }, options.tasks);
        if (options.cancel && options.cancel->load()) throw Cancelled("recording the motion was cancelled");
    }
    for (const Marks& m : marks)
        for (size_t i = 0; i < samples; ++i) rec.contact_steps[i] += m.counts[i];
    // Clip times: what the simulation posed the animated objects at, by the scene's rule.
    for (MotionStep& st : rec.steps) {
        const double t_query = st.time; // the step's queries run at the end-of-step time
        if (deforms) {
            const SceneObject& me = run->objects[index];
            st.clip_time = clip_time(me.animated_mesh->clips[me.clip], t_query, me.animation.speed, me.animation.offset,
                                     me.animation.loop);
        }
        for (MotionPartner& p : st.partners) {
            const SceneObject& other = run->objects[p.object];
            if (other.animated && other.animated_mesh && run->effects.has(Effect::Deform))
                p.clip_time = clip_time(other.animated_mesh->clips[other.clip], t_query, other.animation.speed,
                                        other.animation.offset, other.animation.loop);
        }
    }
    for (uint32_t c : rec.contact_steps) rec.most_contact_steps = std::max(rec.most_contact_steps, c);
    rec.scene = std::move(run);
    return rec;
}

} // namespace spt
