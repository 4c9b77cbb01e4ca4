// A step: motion, broad phase, continuous and discrete contact queries, depth and pairs;
// each stage runs only when its effect is listed.
#include "spt/simulation.hpp"
#include "base/hash.hpp"
#include "base/parallel.hpp"
#include "dynamics/dynamics_world.hpp"
#include "scene/pair_work.hpp"
#include "scene/same_pose.hpp"
#include "query/query_run.hpp"
#include "query/scratch.hpp"
#include "spt/ccd.hpp"
#include "spt/error.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

namespace spt {
namespace {

using Clock = std::chrono::steady_clock;
int64_t ns_since(Clock::time_point t0) {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count();
}

// Whether a moved object's state is one a query takes and a CSV writes: no coordinate beyond
// kMaxMeshCoordinate, nothing infinite or NaN.
bool representable(const Pose& p, const Eigen::Vector3d& velocity, const Eigen::Vector3d& angular) {
    return p.translation.cwiseAbs().maxCoeff() <= kMaxMeshCoordinate && p.rotation.coeffs().allFinite() &&
           velocity.allFinite() && angular.allFinite();
}

// The refusal of a step that would carry `object` out of that range; `causes`: what may be too large.
std::string beyond_range(const std::string& file, const std::string& object, int step, const char* causes) {
    return file + ": object '" + object + "' leaves the representable range at step " + std::to_string(step) +
           " (a coordinate beyond 1e16 or not finite): " + causes + " is too large";
}

} // namespace

uint64_t state_hash(const std::vector<Pose>& poses) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (const Pose& p : poses) {
        const double v[7] = {p.translation.x(), p.translation.y(), p.translation.z(), p.rotation.w(),
                             p.rotation.x(),    p.rotation.y(),    p.rotation.z()};
        h = detail::fnv1a(v, sizeof v, h);
    }
    return h;
}

Simulation::Simulation(Scene scene, EffectSet effects, int threads, TaskSystem* tasks)
    : scene_(std::move(scene)), effects_(effects), threads_(std::max(1, threads)), tasks_(tasks) {
    const bool exact = effects_.has(Effect::Exact) || scene_.level == QueryLevel::Exact;
    for (size_t i = 0; i < scene_.objects.size(); ++i) {
        const SceneObject& o = scene_.objects[i];
        if (!o.model) throw Error(ErrorKind::Usage, scene_.file + ": object '" + o.name + "' has no model loaded");
        if (exact && !o.model->has_mesh())
            throw Error(ErrorKind::BadInput, scene_.file + ": at /objects/" + std::to_string(i) +
                                                 "/model: the exact level needs the mesh; a .spt file holds no triangles");
        poses_.push_back(o.pose);
        velocity_.push_back(o.motion == MotionKind::Velocity ? o.velocity : Eigen::Vector3d::Zero());
        angular_.push_back(o.motion == MotionKind::Velocity ? o.angular_velocity : Eigen::Vector3d::Zero());
    }
    previous_ = ghost_ = poses_;
    scratch_.resize(size_t(threads_));
    deforming_.resize(scene_.objects.size());
    clip_time_.assign(scene_.objects.size(), 0);
    posed_.assign(scene_.objects.size(), 0);
    if (effects_.has(Effect::Deform)) {
        for (size_t i = 0; i < scene_.objects.size(); ++i) {
            SceneObject& o = scene_.objects[i];
            if (!o.animated || !o.animated_mesh || !o.document) continue;
            deforming_[i] = std::make_shared<DeformingModel>(*o.document, o.animated_mesh, o.tree, exact);
            // Queries read the object's model: from now on, the deforming one's current pose.
            o.model = std::shared_ptr<const CollisionModel>(deforming_[i], &deforming_[i]->model());
        }
        // Posed lazily when the step's only queries are contact walks (no depth, pairs, response or
        // continuous detection): at `spheres` they pose what they read, at `exact` (the level, or
        // the effect's confirmation) the triangles alone, on any thread. Depth and the rest read
        // the whole of a colliding object, and posing it part by part, then the rest, costs more
        // than posing it at once (docs/deforming.md, "Scenes").
        lazy_pose_ = scene_.level != QueryLevel::Bounds && !effects_.has(Effect::Depth) && !effects_.has(Effect::Dynamics) &&
                     !effects_.has(Effect::Pairs) && !effects_.has(Effect::Response) && !effects_.has(Effect::Ccd);
        deform(0); // the broad-phase spheres before the first step: the clips at time 0
    }
    if (effects_.has(Effect::Dynamics)) {
        // Checked here too: `--effects` may add dynamics to a scene whose level is not spheres.
        if (scene_.level != QueryLevel::Spheres)
            throw Error(ErrorKind::BadInput, scene_.file + ": effect 'dynamics' takes its contact manifolds from the "
                                                           "sampling spheres: the scene's level must be 'spheres'");
        dynamics_ = std::make_unique<detail::DynamicsWorld>(scene_, effects_.has(Effect::Gravity), effects_.has(Effect::Pairs),
                                                            threads_, tasks_, &scratch_);
    }
}

void Simulation::deform(double t) {
    // Only the broad phase's spheres now, from the joints; an object is posed when a query needs
    // it (pose_needed), as the paper updates only what a test needs.
    for (size_t i = 0; i < deforming_.size(); ++i) {
        if (!deforming_[i]) continue;
        SceneObject& o = scene_.objects[i];
        const Clip& clip = o.animated_mesh->clips[o.clip];
        const AnimationSettings& a = o.animation;
        clip_time_[i] = clip_time(clip, t, a.speed, a.offset, a.loop);
        posed_[i] = 0;
        const auto [centre, radius] = deforming_[i]->bound_at(&clip, clip_time_[i]);
        o.bound_center = centre;
        o.bound_radius = radius;
    }
}

void Simulation::pose_needed(const std::vector<CandidatePair>& pairs) {
    std::vector<uint32_t> wanted;
    for (const CandidatePair& p : pairs)
        for (uint32_t i : {p.a, p.b})
            if (deforming_[i] && !posed_[i]) posed_[i] = 1, wanted.push_back(i);
    detail::parallel_for(wanted.size(), threads_, [&](size_t k, int) {
        const uint32_t i = wanted[k];
        const SceneObject& o = scene_.objects[i];
        if (lazy_pose_)
            deforming_[i]->pose_lazily(&o.animated_mesh->clips[o.clip], clip_time_[i]);
        else
            deforming_[i]->pose(&o.animated_mesh->clips[o.clip], clip_time_[i]);
    }, tasks_);
}

Simulation::~Simulation() = default;

std::pair<Eigen::Vector3d, Eigen::Vector3d> Simulation::object_velocity(size_t i) const {
    const SceneObject& o = scene_.objects.at(i);
    if (!effects_.has(Effect::Motion) || o.motion == MotionKind::Static)
        return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    if (o.motion == MotionKind::Path) return path_velocity(o.path, steps_ * scene_.dt);
    return {velocity_[i], angular_[i]};
}

void Simulation::move(double t1) {
    const double dt = scene_.dt;
    const bool gravity = effects_.has(Effect::Gravity);
    for (size_t i = 0; i < poses_.size(); ++i) {
        const SceneObject& o = scene_.objects[i];
        if (o.motion == MotionKind::Path) {
            poses_[i] = path_pose(o.path, t1);
        } else if (o.motion == MotionKind::Velocity) {
            // Semi-implicit Euler: the velocity the step ends with moves the object.
            if (gravity) velocity_[i] += scene_.gravity * dt;
            poses_[i].translation += velocity_[i] * dt;
            const double w = angular_[i].norm();
            if (w > 0)
                poses_[i].rotation =
                    (Eigen::Quaterniond(Eigen::AngleAxisd(w * dt, angular_[i] / w)) * poses_[i].rotation).normalized();
        }
        // Refused, not written: a huge dt, velocity or gravity would carry the object past what a
        // query accepts, or to infinity.
        if (!representable(poses_[i], velocity_[i], angular_[i]))
            throw Error(ErrorKind::BadInput, beyond_range(scene_.file, o.name, steps_ + 1, "dt, its velocity or gravity"));
    }
}

const StepResult& Simulation::step() {
    // The time at the step's end, for the paths and the result. Refused before anything changes,
    // as a move beyond the range is: a step's time is written out, and no infinity ever is.
    const double t1 = double(steps_ + 1) * scene_.dt;
    if (!std::isfinite(t1))
        throw Error(ErrorKind::BadInput, scene_.file + ": the time of step " + std::to_string(steps_ + 1) +
                                             " is beyond the largest double: dt is too large");
    if (!dynamics_failure_.empty()) throw Error(ErrorKind::BadInput, dynamics_failure_);
    StepResult& r = result_;
    r.contacts.clear();
    r.counters = {};
    previous_ = poses_;
    if (effects_.has(Effect::Motion) && !dynamics_) {
        const std::vector<Eigen::Vector3d> velocity_before = velocity_;
        try {
            move(t1);
        } catch (const Error&) {
            poses_ = previous_, velocity_ = velocity_before; // refused: the state stays that of the last step
            throw;
        }
    }
    if (effects_.has(Effect::Deform)) {
        const auto t0 = Clock::now();
        deform(t1);
        r.counters.ns_deform += ns_since(t0);
    }
    if (dynamics_) step_dynamics(t1, r.counters);
    ++steps_;
    r.step = steps_;
    r.time = t1;
    if (dynamics_) {
        ghost_ = poses_;
        r.state_hash = state_hash(poses_);
        return r;
    }
    if (effects_.has(Effect::Contacts)) run_contacts(r.counters);
    ghost_ = poses_;
    if (effects_.has(Effect::Response)) respond(r.counters);
    r.state_hash = state_hash(poses_);
    return r;
}

void Simulation::step_dynamics(double t1, StepCounters& c) {
    auto pose_for_narrow = [&](const std::vector<CandidatePair>& pairs) {
        if (!effects_.has(Effect::Deform)) return;
        const auto t0 = Clock::now();
        pose_needed(pairs);
        c.ns_deform += ns_since(t0);
    };
    dynamics_->step(t1, effects_.has(Effect::Depth), pose_for_narrow, c, result_.contacts);
    std::vector<Pose> poses = poses_;
    std::vector<Eigen::Vector3d> velocity = velocity_, angular = angular_;
    for (size_t i = 0; i < poses.size(); ++i) {
        const SceneObject& o = scene_.objects[i];
        if (o.motion == MotionKind::Static) continue;
        if (o.motion == MotionKind::Path) {
            poses[i] = path_pose(o.path, t1);
            continue;
        }
        poses[i] = dynamics_->pose(i);
        std::tie(velocity[i], angular[i]) = dynamics_->velocity(i);
        if (!representable(poses[i], velocity[i], angular[i])) {
            // Bullet's world has moved on and cannot be stepped back: the state stays that of the
            // last step, and every later step is refused alike.
            dynamics_failure_ = beyond_range(scene_.file, o.name, steps_ + 1, "dt, its velocity, mass or gravity");
            throw Error(ErrorKind::BadInput, dynamics_failure_);
        }
    }
    poses_ = std::move(poses), velocity_ = std::move(velocity), angular_ = std::move(angular);
}

double Simulation::mass(size_t i) const {
    return dynamics_ && dynamic(uint32_t(i)) ? dynamics_->mass(i) : 1.0;
}

double Simulation::mechanical_energy() const {
    const Eigen::Vector3d g = effects_.has(Effect::Gravity) ? scene_.gravity : Eigen::Vector3d::Zero();
    if (dynamics_) return dynamics_->energy(g);
    double e = 0;
    for (size_t i = 0; i < poses_.size(); ++i)
        if (dynamic(uint32_t(i))) e += 0.5 * velocity_[i].squaredNorm() - g.dot(poses_[i].translation);
    return e;
}

void Simulation::run_contacts(StepCounters& c) {
    const size_t n = poses_.size();
    const bool ccd = effects_.has(Effect::Ccd);
    std::vector<uint8_t> moved(n);
    auto t0 = Clock::now();
    spheres_.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const SceneObject& o = scene_.objects[i];
        moved[i] = !detail::same_pose(poses_[i], previous_[i]) || deforming_[i];
        BroadSphere& s = spheres_[i];
        // A static object that deforms still moves its surface: it meets other static objects.
        s.is_static = o.motion == MotionKind::Static && !deforming_[i];
        s.center = poses_[i].apply(o.bound_center);
        s.radius = o.bound_radius;
        if (ccd && moved[i]) {
            // Sphere around the path of the bounding sphere over the step (see docs/scenes.md).
            const Eigen::Vector3d c0 = previous_[i].apply(o.bound_center);
            s.radius += 0.5 * (s.center - c0).norm() + rotation_angle(previous_[i], poses_[i]) * o.bound_center.norm();
            s.center = 0.5 * (s.center + c0);
        }
    }
    const std::vector<CandidatePair>& cand = broad_.find(spheres_);
    c.ns_broad = ns_since(t0);
    c.candidate_pairs = cand.size();
    if (effects_.has(Effect::Deform)) {
        t0 = Clock::now();
        pose_needed(cand);
        c.ns_deform += ns_since(t0);
    }
    std::vector<detail::PairWork> work(cand.size());
    const QueryLevel level = scene_.level;
    const QueryLevel sphere_level = level == QueryLevel::Bounds ? QueryLevel::Bounds : QueryLevel::Spheres;
    auto model = [&](uint32_t i) -> const CollisionModel& { return *scene_.objects[i].model; };

    if (ccd) {
        t0 = Clock::now();
        detail::parallel_for(cand.size(), threads_, [&](size_t k, int w) {
            const CandidatePair p = cand[k];
            if (!moved[p.a] && !moved[p.b]) return;
            CcdOptions o;
            o.level = sphere_level;
            const CcdResult res = first_contact(model(p.a), model(p.b), relative_pose(previous_[p.a], previous_[p.b]),
                                                relative_pose(poses_[p.a], poses_[p.b]), o, scratch_[size_t(w)]);
            work[k].ccd_ran = true;
            detail::add_counters(work[k].qc, res.counters);
            work[k].ccd_hit = res.hit;
            work[k].toi = res.hit ? res.toi : 1.0;
            work[k].ccd_band = 2e-4 * model(p.b).diagonal(); // twice first_contact's default tolerance
        }, tasks_);
        // Dynamic objects stop at their earliest time of impact; paths and static objects keep their poses.
        std::vector<double> stop(n, 1.0);
        for (size_t k = 0; k < cand.size(); ++k) {
            c.ccd_queries += work[k].ccd_ran;
            if (work[k].ccd_hit)
                for (uint32_t i : {cand[k].a, cand[k].b})
                    if (dynamic(i)) stop[i] = std::min(stop[i], work[k].toi);
        }
        for (size_t i = 0; i < n; ++i)
            if (stop[i] < 1.0) poses_[i] = interpolate(previous_[i], poses_[i], stop[i]);
        c.ns_ccd = ns_since(t0);
    }

    t0 = Clock::now();
    detail::parallel_for(cand.size(), threads_, [&](size_t k, int w) {
        const CandidatePair p = cand[k];
        QueryScratch& s = scratch_[size_t(w)];
        QueryOptions q;
        q.level = level;
        const QueryResult res = collide(model(p.a), poses_[p.a], model(p.b), poses_[p.b], q, s);
        detail::add_counters(work[k].qc, res.counters);
        work[k].collide = res.collide;
        if (res.collide && effects_.has(Effect::Exact) && level != QueryLevel::Exact) {
            q.level = QueryLevel::Exact; // confirmed by the triangles
            const QueryResult ex = collide(model(p.a), poses_[p.a], model(p.b), poses_[p.b], q, s);
            detail::add_counters(work[k].qc, ex.counters);
            work[k].collide = ex.collide;
        }
        if (effects_.has(Effect::Pairs) && (work[k].collide || work[k].ccd_hit)) {
            q.level = sphere_level;
            q.mode = QueryMode::All;
            const QueryResult all = collide(model(p.a), poses_[p.a], model(p.b), poses_[p.b], q, s);
            detail::add_counters(work[k].qc, all.counters);
            work[k].pairs = s.pairs();
            work[k].all_collide = all.collide, work[k].all_point = all.deepest.point;
        }
    }, tasks_);
    c.ns_narrow = ns_since(t0);

    std::vector<size_t> colliding;
    for (size_t k = 0; k < cand.size(); ++k)
        if (work[k].collide || work[k].ccd_hit) colliding.push_back(k);
    c.colliding_pairs = colliding.size();

    // The response's backtrack starts with the `all` query depth runs (rule exact, level bounds
    // or spheres, spheres not grown): depth keeps its pairs for it.
    const bool keep_pairs = effects_.has(Effect::Response) && scene_.response.rule == BacktrackRule::Exact &&
                            level != QueryLevel::Exact;
    for (std::vector<SpherePair>& p : start_pairs_) p.clear();
    if (start_pairs_.size() < colliding.size()) start_pairs_.resize(colliding.size());
    if (effects_.has(Effect::Depth)) {
        t0 = Clock::now();
        detail::parallel_for(colliding.size(), threads_, [&](size_t j, int w) {
            const size_t k = colliding[j];
            QueryScratch& s = scratch_[size_t(w)];
            const double band = work[k].collide ? 0.0 : work[k].ccd_band;
            const CandidatePair p = cand[k];
            const bool reuse = band == 0 && effects_.has(Effect::Pairs); // the pairs effect ran this very query
            if (reuse)
                detail::contact_from_pairs(model(p.a), poses_[p.a], model(p.b), poses_[p.b], sphere_level, band,
                                           dynamic(p.a), dynamic(p.b), work[k].pairs, work[k].all_collide,
                                           work[k].all_point, work[k], s);
            else
                detail::deepest_contact(model(p.a), poses_[p.a], model(p.b), poses_[p.b], sphere_level, band,
                                        dynamic(p.a), dynamic(p.b), work[k], s);
            if (keep_pairs && band == 0 && (dynamic(p.a) || dynamic(p.b))) { // a response moves one of them
                // A deep overlap's pairs are not all of them: its backtrack makes its own first
                // look, starting from its deepest pair (Simulation::respond_pair).
                if (work[k].deep)
                    start_pairs_[j].assign(1, work[k].deepest);
                else if (reuse)
                    start_pairs_[j].assign(work[k].pairs.begin(), work[k].pairs.end());
                else // taken from the scratch, which clears what it gets back at its next query
                    start_pairs_[j].swap(detail::buffers_of(s).pairs);
            }
        }, tasks_);
        c.depth_queries = colliding.size();
        c.ns_depth = ns_since(t0);
    }

    for (const detail::PairWork& w : work) {
        c.node_pairs += w.qc.node_pairs;
        c.sphere_tests += w.qc.sphere_tests;
        c.triangle_tests += w.qc.triangle_tests;
    }
    for (size_t k : colliding) {
        PairContact pc;
        pc.a = cand[k].a, pc.b = cand[k].b;
        pc.has_depth = effects_.has(Effect::Depth);
        if (pc.has_depth)
            pc.depth = work[k].depth, pc.point = work[k].point, pc.normal = work[k].normal, pc.deep = work[k].deep;
        pc.has_toi = ccd; // a pair that did not move this step was in contact from its start
        pc.toi = work[k].ccd_ran ? work[k].toi : 0.0;
        pc.pairs = std::move(work[k].pairs);
        result_.contacts.push_back(std::move(pc));
    }
}

} // namespace spt
