// Runs a scene with one object's tree and records its motion: poses, partners, the samples
// whose spheres took part in a contact, and the samples near a partner at evenly spread steps.
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

// Gaps (model units, clamped at 0) of the object's sampling spheres within `reach` of the
// partner's leaf bounding spheres, kept per sample in `gap` (min over partners and leaves).
void measure_reach(const CollisionModel& object, const CollisionModel& partner, const Pose& partner_in_object,
                   float reach, QueryScratch& scratch, std::vector<float>& gap, std::vector<uint32_t>& touched) {
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
            const double d = (a.sphere_center(na, k).cast<double>() - cb).norm() - nb.bv_radius - na.ss_radius;
            const float g = float(std::max(0.0, d));
            if (!(g < reach)) continue;
            const uint32_t s = sample[k];
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
    set_object_model(o, model.document, model.tree, model.mesh);

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
    QueryScratch scratch;
    std::vector<uint32_t> stamp(samples, 0);
    std::vector<float> gap(samples, std::numeric_limits<float>::infinity());
    std::vector<uint32_t> touched;
    // The steps that get a reach: evenly spread, the last one included.
    const int reach_every = options.reach_steps > 0 ? std::max(1, (steps + options.reach_steps - 1) / options.reach_steps) : 0;
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
        const bool with_reach = reach_every > 0 && ((steps - 1 - k) % reach_every == 0);
        MotionReach reach;
        reach.step = uint32_t(k);
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
            const CollisionModel& mine = *now.objects[index].model;
            const CollisionModel& theirs = *now.objects[j].model;
            if (p.contact) {
                in_contact = true;
                mark_contacts(mine, theirs, p.pose, scratch, stamp, uint32_t(k + 1), rec.contact_steps);
            }
            if (with_reach) measure_reach(mine, theirs, p.pose, float(rec.reach), scratch, gap, touched);
            st.partners.push_back(p);
        }
        if (in_contact) ++rec.steps_in_contact;
        if (with_reach) {
            std::sort(touched.begin(), touched.end());
            reach.near.reserve(touched.size());
            for (uint32_t s : touched) reach.near.emplace_back(s, gap[s]), gap[s] = std::numeric_limits<float>::infinity();
            touched.clear();
            rec.reaches.push_back(std::move(reach));
        }
        rec.steps.push_back(std::move(st));
        if (options.progress) options.progress(k + 1, steps);
    }
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
