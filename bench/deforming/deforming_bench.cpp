// deforming_bench: per frame of an animation clip, the update of a deforming object and one `any`
// query, spt (levels `spheres` and `exact`) against FCL and Bullet in the same process, in
// interleaved rounds (issue 38; figures and command in docs/deforming.md, "Benchmark").
//
// Every library gets the same deformed vertices: each frame is skinned once, before timing, with
// spt::pose_vertices (its cost is reported on its own). What is timed is what each library does
// with them: spt DeformingModel::pose_on (samples follow the surface, normals, refit, the exact
// level's triangles); FCL 0.7 BVHModel<OBBRSS> beginUpdateModel / updateSubModel /
// endUpdateModel(refit, bottom up); Bullet btGImpactMeshShape over a btTriangleIndexVertexArray
// whose float vertex buffer is overwritten, then postUpdate and updateBound. Then one query.
#include "exit_code.hpp"
#include "spt/animation.hpp"
#include "spt/convert.hpp"
#include "spt/deforming_model.hpp"
#include "spt/error.hpp"
#include "spt/query.hpp"
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <btBulletCollisionCommon.h>
#include <fcl/fcl.h>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace spt;
using Clock = std::chrono::steady_clock;
using Verts = std::vector<Eigen::Vector3d>;

double since_ns(Clock::time_point t0) {
    return double(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count());
}

double median(std::vector<double> v) {
    if (v.empty()) return std::nan("");
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string load_average() {
    std::ifstream f("/proc/loadavg");
    std::string a, b, c;
    f >> a >> b >> c;
    return a + " " + b + " " + c;
}

std::string utc_now() {
    const std::time_t t = std::time(nullptr);
    char b[64];
    std::strftime(b, sizeof b, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
    return b;
}

std::string cpu_name() {
    std::ifstream f("/proc/cpuinfo");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

std::string fixed(double v, int digits) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}

// Microseconds with three significant digits or so.
std::string us(double ns) {
    const double u = ns / 1e3;
    return fixed(u, u >= 100 ? 0 : u >= 10 ? 1 : 2);
}

std::string percent(size_t agree, size_t n) {
    if (n == 0) return "n/a (0)";
    return fixed(100.0 * double(agree) / double(n), 1) + "% (" + std::to_string(agree) + "/" + std::to_string(n) + ")";
}

// ---------------------------------------------------------------------------------------------
// Objects

// One animated object: its mesh and document (default conversion of the bind pose) and the
// vertices of every frame, skinned once with spt::pose_vertices.
struct Animated {
    std::shared_ptr<const AnimatedMesh> mesh;
    std::shared_ptr<const SptDocument> doc;
    const Clip* clip = nullptr;
    std::vector<double> times; // clip time of each frame, seconds
    std::vector<Verts> frames;
    double skin_ns = 0; // median time of pose_vertices over the frames
};

std::shared_ptr<const AnimatedMesh> load_mesh(const std::string& path) {
    return std::make_shared<const AnimatedMesh>(import_animated_mesh(path));
}

// `n` frames uniformly over the clip (clip time offset + i * duration / n, wrapped).
Animated animate(std::shared_ptr<const AnimatedMesh> mesh, std::shared_ptr<const SptDocument> doc,
                 const std::string& clip_name, size_t n, double offset) {
    Animated a;
    a.mesh = std::move(mesh), a.doc = std::move(doc);
    a.clip = &a.mesh->clips[a.mesh->find_clip(clip_name)];
    std::vector<double> ns;
    for (size_t i = 0; i < n; ++i) {
        const double t = clip_time(*a.clip, offset + a.clip->duration * double(i) / double(n));
        a.times.push_back(t);
        Verts v;
        const auto t0 = Clock::now();
        pose_vertices(*a.mesh, a.clip, t, v);
        ns.push_back(since_ns(t0));
        a.frames.push_back(std::move(v));
    }
    a.skin_ns = median(ns);
    return a;
}

// A box mesh, closed, wound outwards.
TriangleMesh box_mesh(const std::string& name, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
    std::vector<Eigen::Vector3d> p;
    for (int k = 0; k < 8; ++k) p.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
    const std::vector<Triangle> t = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                     {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return prepare_mesh(name, p, t).mesh;
}

// One side of a case: a deforming object, or a static mesh.
struct Body {
    const Animated* anim = nullptr;
    std::shared_ptr<const TriangleMesh> fixed_mesh; // static obstacle
    std::shared_ptr<const SptDocument> fixed_doc;
    const TriangleMesh& mesh() const { return anim ? anim->mesh->imported.mesh : *fixed_mesh; }
    const Verts& verts(size_t f) const { return anim ? anim->frames[f] : fixed_mesh->positions; }
    bool deforming() const { return anim != nullptr; }
};

// Two objects; A at the identity, B at base + s * u with rotation `rot`, in A's frame. u points
// away from A: B first touches A coming in from a large s. Near contact is measured along u.
struct Case {
    std::string name, title, about_b, placement;
    Body a, b;
    Eigen::Quaterniond rot = Eigen::Quaterniond::Identity();
    Eigen::Vector3d base = Eigen::Vector3d::Zero(), u = Eigen::Vector3d::UnitX();
    double s = 0;    // B's offset in the clip
    double diag = 0; // A's bind-pose diagonal: the unit of "near"
    size_t frames = 0;
    Pose pose(double at) const { return Pose::from(base + at * u, rot); }
};

// ---------------------------------------------------------------------------------------------
// FCL

using FclModel = fcl::BVHModel<fcl::OBBRSSd>;

std::shared_ptr<FclModel> fcl_model(const Verts& v, const std::vector<Triangle>& tris) {
    std::vector<fcl::Triangle> t;
    t.reserve(tris.size());
    for (const auto& tri : tris) t.emplace_back(tri[0], tri[1], tri[2]);
    auto m = std::make_shared<FclModel>();
    m->beginModel(int(tris.size()), int(v.size()));
    m->addSubModel(v, t);
    m->endModel();
    return m;
}

fcl::Transform3d fcl_transform(const Pose& p) {
    fcl::Transform3d t = fcl::Transform3d::Identity();
    t.linear() = p.rotation.toRotationMatrix();
    t.translation() = p.translation;
    return t;
}

bool fcl_collide(const fcl::CollisionObjectd& a, fcl::CollisionObjectd& b, const Pose& p) {
    b.setTransform(fcl_transform(p));
    fcl::CollisionRequestd req; // one contact: stops at the first, an `any` query
    fcl::CollisionResultd res;
    fcl::collide(&a, &b, req, res);
    return res.isCollision();
}

// Ground truth at one frame: FCL trees built afresh on the frame's vertices (never refit).
struct FclTruth {
    fcl::CollisionObjectd a, b;
    FclTruth(const Case& c, size_t f)
        : a(fcl_model(c.a.verts(f), c.a.mesh().triangles)), b(fcl_model(c.b.verts(f), c.b.mesh().triangles)) {}
    bool collide(const Pose& p) { return fcl_collide(a, b, p); }
};

// ---------------------------------------------------------------------------------------------
// The measured libraries: update to frame f, then one query at B's pose.

struct Runner {
    virtual ~Runner() = default;
    virtual void update(size_t f) = 0;
    virtual bool query(const Pose& b_in_a) = 0;
    QueryCounters work; // spt's: the last query's work
};

uint32_t g_lazy_region = 512; // --lazy-region (DeformingModel's default)
// --tolerance and --protrusion: fractions of each converted mesh's own diagonal (0: the default).
double g_tolerance = 0, g_protrusion = 0;
// --clip-poses STEP: deforming models' spheres limited at their clips' poses STEP seconds apart (0: not).
double g_clip_step = 0;

/// Converts a mesh as every model of the benchmark is converted: make_document's defaults, or the
/// tolerance and protrusion allowance given on the command line, each a fraction of the mesh's
/// diagonal; an animated mesh's radii limited at its clips' poses with --clip-poses.
SptDocument convert(const TriangleMesh& mesh, const AnimatedMesh* animated = nullptr) {
    ConvertOptions o;
    if (g_tolerance > 0) o.tolerance = g_tolerance * mesh.diagonal();
    if (g_protrusion > 0) o.protrusion = g_protrusion * mesh.diagonal();
    if (animated && g_clip_step > 0) o.poses = clip_poses(*animated, g_clip_step);
    return make_document(mesh, o);
}

class SptRunner : public Runner {
public:
    // `lazy`: DeformingModel::pose_lazily_on, the query posing the parts it descends into;
    // `tight`: DeformingModel::set_tight_refit.
    SptRunner(const Case& c, QueryLevel level, int threads = 1, bool lazy = false, bool tight = false)
        : c_(c), lazy_(lazy) {
        options_.level = level;
        options_.solids = false; // surfaces, as FCL and Bullet answer (a posed model has no solid anyway)
        // The spheres level poses the spheres only; exact poses the triangles too.
        const bool triangles = level == QueryLevel::Exact;
        a_.emplace(*c.a.anim->doc, c.a.anim->mesh, std::string(), triangles);
        a_->set_threads(threads);
        if (c.b.deforming()) b_.emplace(*c.b.anim->doc, c.b.anim->mesh, std::string(), triangles), b_->set_threads(threads);
        else b_fixed_ = CollisionModel(*c.b.fixed_doc, *c.b.fixed_mesh);
        a_->set_lazy_region(g_lazy_region), a_->set_tight_refit(tight);
        if (b_) b_->set_lazy_region(g_lazy_region), b_->set_tight_refit(tight);
    }
    void update(size_t f) override {
        if (lazy_) {
            a_->pose_lazily_on(c_.a.anim->frames[f]);
            if (b_) b_->pose_lazily_on(c_.b.anim->frames[f]);
            return;
        }
        a_->pose_on(c_.a.anim->frames[f]);
        if (b_) b_->pose_on(c_.b.anim->frames[f]);
    }
    bool query(const Pose& p) override {
        const QueryResult r = collide_relative(a_->model(), b_ ? b_->model() : b_fixed_, p, options_, scratch_);
        work = r.counters;
        return r.collide;
    }
    const CollisionModel& a() const { return a_->model(); }
    const CollisionModel& b() const { return b_ ? b_->model() : b_fixed_; }
    const QueryOptions& options() const { return options_; }

private:
    const Case& c_;
    bool lazy_;
    QueryOptions options_;
    std::optional<DeformingModel> a_, b_;
    CollisionModel b_fixed_;
    QueryScratch scratch_;
};

// The query alone on models made from the posed meshes from scratch (rigid), or on the
// deforming models posed outside the timed span: "a deformed pose's query against the rigid
// query at the same pose".
class RigidRunner : public Runner {
public:
    RigidRunner(const Case& c, QueryLevel level, const std::vector<CollisionModel>& a_frames,
                const std::vector<CollisionModel>* b_frames, const CollisionModel* b_fixed)
        : a_(a_frames), b_(b_frames), b_fixed_(b_fixed) {
        options_.level = level;
        options_.solids = false;
    }
    void update(size_t f) override { f_ = f; }
    bool query(const Pose& p) override {
        const QueryResult r = collide_relative(a_[f_], b_ ? (*b_)[f_] : *b_fixed_, p, options_, scratch_);
        work = r.counters;
        return r.collide;
    }

private:
    const std::vector<CollisionModel>& a_;
    const std::vector<CollisionModel>* b_;
    const CollisionModel* b_fixed_;
    QueryOptions options_;
    QueryScratch scratch_;
    size_t f_ = 0;
};

class FclRunner : public Runner {
public:
    explicit FclRunner(const Case& c)
        : c_(c), ma_(fcl_model(c.a.verts(0), c.a.mesh().triangles)), mb_(fcl_model(c.b.verts(0), c.b.mesh().triangles)),
          a_(ma_, fcl::Transform3d::Identity()), b_(mb_, fcl::Transform3d::Identity()) {}
    void update(size_t f) override {
        refit(*ma_, c_.a.verts(f));
        if (c_.b.deforming()) refit(*mb_, c_.b.verts(f));
    }
    bool query(const Pose& p) override { return fcl_collide(a_, b_, p); }

private:
    static void refit(FclModel& m, const Verts& v) {
        m.beginUpdateModel();
        m.updateSubModel(v);
        m.endUpdateModel(true, true); // refit, bottom up (FCL's default)
    }
    const Case& c_;
    std::shared_ptr<FclModel> ma_, mb_;
    fcl::CollisionObjectd a_, b_;
};

// Bullet GImpact on both sides, margin 0, as bench/accuracy/peers.cpp: collide if any contact has
// distance <= 0. A deforming side's float vertex buffer is overwritten, then postUpdate and updateBound.
class BulletRunner : public Runner {
public:
    // rebuild: a new shape (a box set built afresh) every frame instead of the refit.
    BulletRunner(const Case& c, bool rebuild) : c_(c), rebuild_(rebuild) {
        make(sa_, c.a.mesh(), c.a.verts(0));
        make(sb_, c.b.mesh(), c.b.verts(0));
        dispatcher_ = std::make_unique<btCollisionDispatcher>(&config_);
        btGImpactCollisionAlgorithm::registerAlgorithm(dispatcher_.get());
        static btGImpactCollisionAlgorithm::CreateFunc gimpact; // contactPairTest asks for closest points
        for (int i = 0; i < MAX_BROADPHASE_COLLISION_TYPES; ++i) {
            dispatcher_->registerClosestPointsCreateFunc(GIMPACT_SHAPE_PROXYTYPE, i, &gimpact);
            dispatcher_->registerClosestPointsCreateFunc(i, GIMPACT_SHAPE_PROXYTYPE, &gimpact);
        }
        world_ = std::make_unique<btCollisionWorld>(dispatcher_.get(), &broadphase_, &config_);
        a_.setCollisionShape(sa_.shape.get());
        b_.setCollisionShape(sb_.shape.get());
        world_->addCollisionObject(&a_);
        world_->addCollisionObject(&b_);
    }
    ~BulletRunner() override {
        world_->removeCollisionObject(&b_);
        world_->removeCollisionObject(&a_);
    }
    void update(size_t f) override {
        write(sa_, c_.a.verts(f), rebuild_);
        if (rebuild_) a_.setCollisionShape(sa_.shape.get());
        if (c_.b.deforming()) {
            write(sb_, c_.b.verts(f), rebuild_);
            if (rebuild_) b_.setCollisionShape(sb_.shape.get());
        }
    }
    bool query(const Pose& p) override {
        const Eigen::Quaterniond& q = p.rotation;
        b_.setWorldTransform(btTransform(btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w())),
                                         btVector3(btScalar(p.translation.x()), btScalar(p.translation.y()),
                                                   btScalar(p.translation.z()))));
        AnyContact cb;
        world_->contactPairTest(&a_, &b_, cb);
        return cb.hit;
    }

private:
    struct Shape {
        std::vector<int> indices;
        std::vector<btScalar> vertices;
        std::unique_ptr<btTriangleIndexVertexArray> array;
        std::unique_ptr<btGImpactMeshShape> shape;
    };
    struct AnyContact : btCollisionWorld::ContactResultCallback {
        bool hit = false;
        btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper*, int, int,
                                 const btCollisionObjectWrapper*, int, int) override {
            if (cp.getDistance() <= 0) hit = true;
            return 0;
        }
    };
    static void make(Shape& s, const TriangleMesh& m, const Verts& v) {
        s.vertices.assign(3 * v.size(), 0);
        for (const auto& t : m.triangles) s.indices.insert(s.indices.end(), {int(t[0]), int(t[1]), int(t[2])});
        s.array = std::make_unique<btTriangleIndexVertexArray>(int(m.triangles.size()), s.indices.data(), 3 * int(sizeof(int)),
                                                               int(v.size()), s.vertices.data(), 3 * int(sizeof(btScalar)));
        write(s, v, true);
    }
    static void write(Shape& s, const Verts& v, bool rebuild) {
        btScalar* out = s.vertices.data();
        for (const auto& p : v) *out++ = btScalar(p.x()), *out++ = btScalar(p.y()), *out++ = btScalar(p.z());
        if (rebuild) {
            s.shape = std::make_unique<btGImpactMeshShape>(s.array.get());
            s.shape->setMargin(0);
        } else {
            s.shape->postUpdate();
        }
        s.shape->updateBound();
    }
    const Case& c_;
    bool rebuild_;
    Shape sa_, sb_;
    btDefaultCollisionConfiguration config_;
    std::unique_ptr<btCollisionDispatcher> dispatcher_;
    btDbvtBroadphase broadphase_;
    std::unique_ptr<btCollisionWorld> world_;
    btCollisionObject a_, b_;
};

// ---------------------------------------------------------------------------------------------
// First contact along u, found with FCL: from an offset where A and B are apart, steps of 0.5%
// of the diagonal towards A until FCL reports a collision, then bisection to 1e-7 of the
// diagonal. NaN if they never touch over the whole pass.

double along(const Verts& v, const Eigen::Vector3d& u, bool highest, const Eigen::Quaterniond& r = Eigen::Quaterniond::Identity()) {
    double best = highest ? -INFINITY : INFINITY;
    for (const auto& p : v) best = highest ? std::max(best, u.dot(r * p)) : std::min(best, u.dot(r * p));
    return best;
}

double first_contact(const Case& c, size_t f, FclTruth& truth) {
    // Apart: B's lowest point along u beyond A's highest.
    const double a_hi = along(c.a.verts(f), c.u, true), a_lo = along(c.a.verts(f), c.u, false);
    const double b_lo = along(c.b.verts(f), c.u, false, c.rot), b_hi = along(c.b.verts(f), c.u, true, c.rot);
    const double far = a_hi - b_lo - c.u.dot(c.base) + 0.01 * c.diag;
    const double through = a_lo - b_hi - c.u.dot(c.base) - 0.01 * c.diag; // B wholly past A
    const double step = 0.005 * c.diag;
    double hi = far; // apart
    for (double s = far - step; s > through; s -= step) {
        if (truth.collide(c.pose(s))) {
            double lo = s; // touching
            while (hi - lo > 1e-7 * c.diag) {
                const double mid = 0.5 * (lo + hi);
                (truth.collide(c.pose(mid)) ? lo : hi) = mid;
            }
            return 0.5 * (lo + hi);
        }
        hi = s;
    }
    return std::nan("");
}

// ---------------------------------------------------------------------------------------------
// Measurement of one case

struct Timing {
    std::string name;
    std::unique_ptr<Runner> runner;
    bool in_main_table = true;                    // false: the rigid comparison's query-only rows
    bool time_update = true;                      // false: update outside the timed span
    std::vector<std::vector<double>> update_ns;   // [round][frame]
    std::vector<std::vector<double>> query_ns;    // [round][frame]
    std::vector<std::vector<double>> warm_ns;     // [round][frame]: query-only rows, the query repeated at once
    std::vector<int> answer;                      // per frame at the clip's pose (last round)
    std::vector<double> node_pairs, leaf_tests;   // per frame, spt's query work (last round)
    size_t inconsistent = 0;                      // frames whose answer changed between rounds
    std::vector<int> near_answer;                 // per pushed pose
    double round_median(size_t r, bool with_update) const {
        std::vector<double> t(query_ns[r].size());
        for (size_t f = 0; f < t.size(); ++f) t[f] = query_ns[r][f] + (with_update ? update_ns[r][f] : 0);
        return median(t);
    }
    double update_median(size_t r) const { return median(update_ns[r]); }
};

struct Summary {
    double update = 0, query = 0, total = 0, best = 0; // medians over rounds of per-frame medians (ns)
    double warm = 0, warm_best = 0;                      // the same of the repeated query (query-only rows)
    size_t agree_all = 0, agree_near = 0, near = 0, agree_pushed = 0, pushed = 0, fp = 0, fn = 0, frame_fp = 0, frame_fn = 0;
};

struct CaseResult {
    const Case* c = nullptr;
    std::vector<double> s_star;
    std::vector<int> truth, near;
    std::vector<Pose> pushed_pose;
    std::vector<int> pushed_truth;
    std::vector<size_t> pushed_frame;
    std::vector<Timing> timings;
    std::vector<Summary> summary;
    double convert_ns = 0, rigid_samples = 0;
    size_t deformed_samples = 0, fcl_refit_vs_fresh = 0;
};

const Timing& named(const CaseResult& r, const std::string& name) {
    for (const auto& t : r.timings)
        if (t.name == name) return t;
    throw std::logic_error("no timing named " + name);
}

Summary summarise(const CaseResult& r, const Timing& t) {
    Summary s;
    const size_t rounds = t.query_ns.size();
    std::vector<double> u, q, tot;
    for (size_t k = 0; k < rounds; ++k) {
        u.push_back(t.update_median(k));
        q.push_back(median(t.query_ns[k]));
        tot.push_back(t.round_median(k, t.time_update));
    }
    s.update = median(u), s.query = median(q), s.total = median(tot);
    s.best = *std::min_element(tot.begin(), tot.end());
    std::vector<double> w;
    for (size_t k = 0; k < rounds; ++k) w.push_back(median(t.warm_ns[k]));
    s.warm = median(w), s.warm_best = *std::min_element(w.begin(), w.end());
    for (size_t f = 0; f < r.truth.size(); ++f) {
        const bool ok = t.answer[f] == r.truth[f];
        s.agree_all += ok;
        s.frame_fp += t.answer[f] && !r.truth[f];
        s.frame_fn += !t.answer[f] && r.truth[f];
        if (r.near[f]) s.near++, s.agree_near += ok;
    }
    for (size_t k = 0; k < r.pushed_truth.size(); ++k) {
        const bool ok = t.near_answer[k] == r.pushed_truth[k];
        s.pushed++, s.agree_pushed += ok;
        s.fp += t.near_answer[k] && !r.pushed_truth[k];
        s.fn += !t.near_answer[k] && r.pushed_truth[k];
    }
    return s;
}

// Median over rounds of (x's per-frame median of the repeated query / y's) in the same round.
double warm_ratio(const Timing& x, const Timing& y) {
    std::vector<double> v;
    for (size_t k = 0; k < x.warm_ns.size(); ++k) v.push_back(median(x.warm_ns[k]) / median(y.warm_ns[k]));
    return median(v);
}

// Median over rounds of (x's per-frame median / y's) in the same round.
double ratio(const Timing& x, const Timing& y) {
    std::vector<double> v;
    for (size_t k = 0; k < x.query_ns.size(); ++k)
        v.push_back(x.round_median(k, x.time_update) / y.round_median(k, y.time_update));
    return median(v);
}

std::vector<CollisionModel> rigid_models(const Animated& an, size_t frames, double& convert_ns, double& samples);

struct RigidFrames {
    std::vector<CollisionModel> models;
    double convert_ns = 0, samples = 0;
};

// Models converted from scratch (default options) from every posed frame of `an`; made once per
// animated object and kept for the cases that share it.
const RigidFrames& rigid_frames(const Animated& an) {
    static std::vector<std::pair<const Animated*, std::unique_ptr<RigidFrames>>> cache;
    for (const auto& [key, value] : cache)
        if (key == &an) return *value;
    auto r = std::make_unique<RigidFrames>();
    r->models = rigid_models(an, an.frames.size(), r->convert_ns, r->samples);
    cache.emplace_back(&an, std::move(r));
    return *cache.back().second;
}

std::vector<CollisionModel> rigid_models(const Animated& an, size_t frames, double& convert_ns, double& samples) {
    std::vector<CollisionModel> out;
    std::vector<double> ns;
    samples = 0;
    for (size_t f = 0; f < frames; ++f) {
        const TriangleMesh& bind = an.mesh->imported.mesh;
        const auto t0 = Clock::now();
        const ImportedMesh posed = prepare_mesh(bind.name, an.frames[f], bind.triangles);
        const SptDocument doc = convert(posed.mesh);
        out.emplace_back(doc, posed.mesh);
        ns.push_back(since_ns(t0));
        samples += double(doc.samples.size());
    }
    convert_ns = median(ns);
    samples /= double(frames);
    return out;
}

CaseResult measure(const Case& c, int rounds, double near_band) {
    CaseResult r;
    r.c = &c;
    std::cerr << c.name << ": first contacts with FCL\n";
    for (size_t f = 0; f < c.frames; ++f) {
        FclTruth truth(c, f);
        const double s = first_contact(c, f, truth);
        r.s_star.push_back(s);
        r.truth.push_back(truth.collide(c.pose(c.s)));
        r.near.push_back(std::isfinite(s) && std::abs(c.s - s) <= near_band * c.diag);
        if (std::isfinite(s))
            for (double side : {-1.0, 1.0}) {
                const Pose p = c.pose(s + side * near_band * c.diag);
                r.pushed_pose.push_back(p);
                r.pushed_truth.push_back(truth.collide(p));
                r.pushed_frame.push_back(f);
            }
    }

    // Rigid models of every posed frame, converted from scratch (default options).
    std::cerr << c.name << ": rigid models of the posed frames\n";
    const RigidFrames& ra = rigid_frames(*c.a.anim);
    const std::vector<CollisionModel>& rigid_a = ra.models;
    r.convert_ns = ra.convert_ns, r.rigid_samples = ra.samples;
    const std::vector<CollisionModel>* rigid_b = c.b.deforming() ? &rigid_frames(*c.b.anim).models : nullptr;
    const CollisionModel fixed_b = c.b.deforming() ? CollisionModel() : CollisionModel(*c.b.fixed_doc, *c.b.fixed_mesh);
    r.deformed_samples = c.a.anim->doc->samples.size();

    auto add = [&](std::string name, std::unique_ptr<Runner> run, bool main_table, bool time_update) {
        Timing t;
        t.name = std::move(name), t.runner = std::move(run), t.in_main_table = main_table, t.time_update = time_update;
        r.timings.push_back(std::move(t));
    };
    add("spt spheres", std::make_unique<SptRunner>(c, QueryLevel::Spheres), true, true);
    add("spt exact", std::make_unique<SptRunner>(c, QueryLevel::Exact), true, true);
    add("spt exact, lazy refit", std::make_unique<SptRunner>(c, QueryLevel::Exact, 1, true), true, true);
    add("spt spheres, 2 threads", std::make_unique<SptRunner>(c, QueryLevel::Spheres, 2), true, true);
    add("spt spheres, lazy refit", std::make_unique<SptRunner>(c, QueryLevel::Spheres, 1, true), true, true);
    add("spt spheres, tight refit", std::make_unique<SptRunner>(c, QueryLevel::Spheres, 1, false, true), true, true);
    add("spt spheres, lazy tight", std::make_unique<SptRunner>(c, QueryLevel::Spheres, 1, true, true), true, true);
    add("FCL OBBRSS refit", std::make_unique<FclRunner>(c), true, true);
    add("Bullet GImpact", std::make_unique<BulletRunner>(c, false), true, true);
    add("Bullet GImpact rebuilt", std::make_unique<BulletRunner>(c, true), true, true);
    add("spheres query, deformed", std::make_unique<SptRunner>(c, QueryLevel::Spheres), false, false);
    add("spheres query, lazy refit", std::make_unique<SptRunner>(c, QueryLevel::Spheres, 1, true), false, false);
    add("spheres query, lazy tight", std::make_unique<SptRunner>(c, QueryLevel::Spheres, 1, true, true), false, false);
    add("spheres query, tight refit", std::make_unique<SptRunner>(c, QueryLevel::Spheres, 1, false, true), false, false);
    add("spheres query, rigid", std::make_unique<RigidRunner>(c, QueryLevel::Spheres, rigid_a, rigid_b, &fixed_b), false, false);
    add("exact query, deformed", std::make_unique<SptRunner>(c, QueryLevel::Exact), false, false);
    add("exact query, rigid", std::make_unique<RigidRunner>(c, QueryLevel::Exact, rigid_a, rigid_b, &fixed_b), false, false);

    const Pose at = c.pose(c.s);
    for (auto& t : r.timings) {
        t.update_ns.assign(size_t(rounds), std::vector<double>(c.frames, 0));
        t.query_ns.assign(size_t(rounds), std::vector<double>(c.frames, 0));
        t.warm_ns.assign(size_t(rounds), std::vector<double>(c.frames, 0));
        t.answer.assign(c.frames, -1);
        t.node_pairs.assign(c.frames, 0);
        t.leaf_tests.assign(c.frames, 0);
    }
    for (int k = 0; k < rounds; ++k) {
        std::cerr << c.name << ": round " << k + 1 << " of " << rounds << ", load " << load_average() << "\n";
        // Every library over all frames in turn, starting one further each round.
        for (size_t j = 0; j < r.timings.size(); ++j) {
            Timing& t = r.timings[(j + size_t(k)) % r.timings.size()];
            for (size_t f = 0; f < c.frames; ++f) {
                const auto t0 = Clock::now();
                t.runner->update(f);
                const auto t1 = Clock::now();
                const bool hit = t.runner->query(at);
                const auto t2 = Clock::now();
                t.update_ns[size_t(k)][f] = double(std::chrono::duration_cast<std::chrono::nanoseconds>(t1 - t0).count());
                t.query_ns[size_t(k)][f] = double(std::chrono::duration_cast<std::chrono::nanoseconds>(t2 - t1).count());
                if (!t.time_update) { // the query-only rows: the same query once more, its data now in cache
                    const auto t3 = Clock::now();
                    t.runner->query(at);
                    t.warm_ns[size_t(k)][f] = since_ns(t3);
                }
                if (t.answer[f] >= 0 && t.answer[f] != int(hit)) ++t.inconsistent;
                t.answer[f] = hit;
                t.node_pairs[f] = double(t.runner->work.node_pairs);
                t.leaf_tests[f] = double(t.runner->work.sphere_tests + t.runner->work.triangle_tests);
            }
        }
    }
    // Near-contact poses: not timed.
    for (auto& t : r.timings) {
        t.near_answer.assign(r.pushed_pose.size(), -1);
        size_t last = SIZE_MAX;
        for (size_t k = 0; k < r.pushed_pose.size(); ++k) {
            if (r.pushed_frame[k] != last) t.runner->update(last = r.pushed_frame[k]);
            t.near_answer[k] = t.runner->query(r.pushed_pose[k]);
        }
    }
    for (const auto& t : r.timings) r.summary.push_back(summarise(r, t));
    for (size_t f = 0; f < c.frames; ++f) r.fcl_refit_vs_fresh += named(r, "FCL OBBRSS refit").answer[f] != r.truth[f];
    return r;
}

// ---------------------------------------------------------------------------------------------
// Output

/// A CSV column name for a row's name: each run of characters other than letters and digits
/// becomes one '_' ("spt spheres, lazy refit" -> "spt_spheres_lazy_refit"), so that no name
/// holds the separator.
std::string column_name(const std::string& name) {
    std::string n;
    for (const char ch : name)
        if (std::isalnum(static_cast<unsigned char>(ch)))
            n += ch;
        else if (!n.empty() && n.back() != '_')
            n += '_';
    while (!n.empty() && n.back() == '_') n.pop_back();
    return n;
}

/// A CSV field as RFC 4180 writes it: quoted, its quotes doubled, when it holds a comma, a quote
/// or a line break ("spt spheres, 2 threads" is one field).
std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string q = "\"";
    for (const char ch : text) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return q + "\"";
}

void write_frames_csv(const std::string& path, const std::vector<CaseResult>& results) {
    std::ofstream o(path);
    if (!o) throw Error(ErrorKind::CannotWrite, path + ": cannot write");
    o << "case,frame,clip_time_s,offset_over_diag,first_contact_over_diag,near,fcl_fresh";
    for (const auto& t : results.front().timings)
        if (t.in_main_table) {
            const std::string n = column_name(t.name);
            o << "," << n << "," << n << "_median_us";
        }
    o << "\n";
    for (const auto& r : results) {
        const Case& c = *r.c;
        for (size_t f = 0; f < c.frames; ++f) {
            o << c.name << "," << f << "," << fixed(c.a.anim->times[f], 5) << "," << fixed(c.s / c.diag, 8) << ","
              << (std::isfinite(r.s_star[f]) ? fixed(r.s_star[f] / c.diag, 8) : "") << "," << r.near[f] << "," << r.truth[f];
            for (const auto& t : r.timings) {
                if (!t.in_main_table) continue;
                std::vector<double> v;
                for (size_t k = 0; k < t.query_ns.size(); ++k) v.push_back(t.update_ns[k][f] + t.query_ns[k][f]);
                o << "," << t.answer[f] << "," << fixed(median(v) / 1e3, 3);
            }
            o << "\n";
        }
    }
}

/// Each library's work at each frame, one row a library and frame (long form: every row of the
/// benchmark, the query-only ones too): its answer, node pairs and leaf tests (sphere and triangle
/// tests) of the frame's query. Counts, not times: the same on any host, so two builds' walks can
/// be compared frame by frame.
void write_work_csv(const std::string& path, const std::vector<CaseResult>& results) {
    std::ofstream o(path);
    if (!o) throw Error(ErrorKind::CannotWrite, path + ": cannot write");
    o << "case,frame,library,collide,node_pairs,leaf_tests\n";
    for (const auto& r : results)
        for (const auto& t : r.timings) {
            if (t.name.rfind("spt", 0) != 0 && t.name.find("query") == std::string::npos) continue; // FCL, Bullet: no counts
            for (size_t f = 0; f < r.c->frames; ++f)
                o << r.c->name << "," << f << "," << csv_field(t.name) << "," << t.answer[f] << "," << uint64_t(t.node_pairs[f])
                  << "," << uint64_t(t.leaf_tests[f]) << "\n";
        }
    if (!o) throw Error(ErrorKind::CannotWrite, path + ": cannot write");
}

void write_summary_csv(const std::string& path, const std::vector<CaseResult>& results) {
    std::ofstream o(path);
    if (!o) throw Error(ErrorKind::CannotWrite, path + ": cannot write");
    o << "case,library,update_us,query_us,update_query_us,best_round_us,agree_all_percent,near_frames,agree_near_frames_percent,"
         "near_poses,agree_near_poses_percent\n";
    for (const auto& r : results)
        for (size_t i = 0; i < r.timings.size(); ++i) {
            const Summary& s = r.summary[i];
            const auto pct = [](size_t a, size_t n) { return n ? fixed(100.0 * double(a) / double(n), 2) : std::string(); };
            o << r.c->name << "," << csv_field(r.timings[i].name) << "," << fixed(s.update / 1e3, 3) << "," << fixed(s.query / 1e3, 3)
              << "," << fixed(s.total / 1e3, 3) << "," << fixed(s.best / 1e3, 3) << "," << pct(s.agree_all, r.truth.size())
              << "," << s.near << "," << pct(s.agree_near, s.near) << "," << s.pushed << "," << pct(s.agree_pushed, s.pushed)
              << "\n";
        }
}

// Agreement near contact against the median time a frame (log scale), one panel a case, as
// docs/accuracy-vs-time.md plots its configurations: filled marks for the near-contact poses
// (first contact +-1% of the diagonal), hollow ones for the clip's own frames within +-1% of it.
// Plain SVG, no library.
void write_svg(const std::string& path, const std::vector<CaseResult>& results) {
    std::ofstream o(path);
    if (!o) throw Error(ErrorKind::CannotWrite, path + ": cannot write");
    const double pw = 360, ph = 260, ml = 60, mt = 40, mb = 50, gap = 45, legend = 50;
    const double W = ml + double(results.size()) * (pw + gap), H = mt + ph + mb + legend;
    const char* colours[] = {"#1f77b4", "#2ca02c", "#d62728", "#9467bd", "#8c564b"};
    // A mark of shape k (circle, square, diamond, triangle, cross) at (x, y).
    auto mark = [&](double x, double y, size_t k, bool filled) {
        const std::string c = colours[k % 5];
        const std::string paint = filled ? "fill=\"" + c + "\" stroke=\"" + c + "\" stroke-width=\"2\"" : "fill=\"white\" stroke=\"" + c + "\" stroke-width=\"1.5\"";
        std::ostringstream m;
        switch (k % 5) {
        case 0: m << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"5\" "; break;
        case 1: m << "<rect x=\"" << x - 4.5 << "\" y=\"" << y - 4.5 << "\" width=\"9\" height=\"9\" "; break;
        case 2: m << "<polygon points=\"" << x << "," << y - 6 << " " << x + 6 << "," << y << " " << x << "," << y + 6 << " " << x - 6 << "," << y << "\" "; break;
        case 3: m << "<polygon points=\"" << x << "," << y - 6 << " " << x + 6 << "," << y + 5 << " " << x - 6 << "," << y + 5 << "\" "; break;
        default: m << "<path d=\"M" << x - 5 << "," << y - 5 << "L" << x + 5 << "," << y + 5 << "M" << x - 5 << "," << y + 5 << "L" << x + 5 << "," << y - 5 << "\" "; break;
        }
        o << m.str() << paint << "/>\n";
    };
    o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    auto pct = [](size_t a, size_t n) { return n ? 100.0 * double(a) / double(n) : 100.0; };
    double lo = INFINITY, hi = 0, ymin = 100;
    for (const auto& r : results)
        for (size_t i = 0; i < r.timings.size(); ++i) {
            if (!r.timings[i].in_main_table) continue;
            const Summary& s = r.summary[i];
            lo = std::min(lo, s.total), hi = std::max(hi, s.total);
            ymin = std::min({ymin, pct(s.agree_pushed, s.pushed), pct(s.agree_near, s.near)});
        }
    const double x0 = std::floor(std::log10(lo / 1e3)), x1 = std::ceil(std::log10(hi / 1e3));
    const double y0 = std::min(90.0, std::floor(ymin / 5) * 5), y1 = 101;
    for (size_t p = 0; p < results.size(); ++p) {
        const CaseResult& r = results[p];
        const double ox = ml + double(p) * (pw + gap), oy = mt;
        auto X = [&](double ns) { return ox + pw * (std::log10(ns / 1e3) - x0) / (x1 - x0); };
        auto Y = [&](double pc) { return oy + ph * (y1 - pc) / (y1 - y0); };
        o << "<text x=\"" << ox + pw / 2 << "\" y=\"" << oy - 12 << "\" text-anchor=\"middle\" font-size=\"13\">" << r.c->title
          << "</text>\n";
        o << "<rect x=\"" << ox << "\" y=\"" << oy << "\" width=\"" << pw << "\" height=\"" << ph
          << "\" fill=\"none\" stroke=\"#444\"/>\n";
        for (double e = x0; e <= x1; e += 1) {
            const double x = X(std::pow(10, e) * 1e3);
            o << "<line x1=\"" << x << "\" y1=\"" << oy << "\" x2=\"" << x << "\" y2=\"" << oy + ph << "\" stroke=\"#ddd\"/>\n";
            o << "<text x=\"" << x << "\" y=\"" << oy + ph + 15 << "\" text-anchor=\"middle\">" << fixed(std::pow(10, e), e < 0 ? 1 : 0)
              << "</text>\n";
        }
        const double ystep = y1 - y0 > 30 ? 10 : 5;
        for (double y = std::ceil(y0 / ystep) * ystep; y <= 100; y += ystep) {
            o << "<line x1=\"" << ox << "\" y1=\"" << Y(y) << "\" x2=\"" << ox + pw << "\" y2=\"" << Y(y) << "\" stroke=\"#ddd\"/>\n";
            if (p == 0) o << "<text x=\"" << ox - 6 << "\" y=\"" << Y(y) + 4 << "\" text-anchor=\"end\">" << y << "</text>\n";
        }
        o << "<text x=\"" << ox + pw / 2 << "\" y=\"" << oy + ph + 32
          << "\" text-anchor=\"middle\">update + query, median µs a frame (log)</text>\n";
        size_t k = 0;
        for (size_t i = 0; i < r.timings.size(); ++i) {
            if (!r.timings[i].in_main_table) continue;
            const Summary& s = r.summary[i];
            mark(X(s.total), Y(pct(s.agree_near, s.near)), k, false);
            mark(X(s.total), Y(pct(s.agree_pushed, s.pushed)), k, true);
            ++k;
        }
    }
    // The legend: one entry a library, then what filled and hollow mean.
    double lx = ml;
    const double ly = mt + ph + mb + 12;
    size_t k = 0;
    for (const auto& t : results.front().timings) {
        if (!t.in_main_table) continue;
        mark(lx + 6, ly, k++, true);
        o << "<text x=\"" << lx + 16 << "\" y=\"" << ly + 4 << "\">" << t.name << "</text>\n";
        lx += 30 + 6.5 * double(t.name.size());
    }
    o << "<text x=\"" << ml << "\" y=\"" << ly + 24
      << "\">filled: the near-contact poses (first contact ±1% of the diagonal); hollow: the clip's frames within ±1% "
         "of first contact</text>\n";
    o << "<text x=\"14\" y=\"" << mt + ph / 2 << "\" transform=\"rotate(-90 14 " << mt + ph / 2
      << ")\" text-anchor=\"middle\">agree with FCL near contact (%)</text>\n</svg>\n";
}

void print_markdown(std::ostream& o, const std::vector<CaseResult>& results, const std::string& command,
                    const std::string& started, const std::string& load0, const std::string& load1, int rounds,
                    double seconds) {
    o << "Command: `" << command << "`; " << started << ", " << rounds << " interleaved rounds, " << fixed(seconds, 0)
      << " s, load average " << load0 << " at the start and " << load1 << " at the end; " << cpu_name() << ".\n\n";
    for (const auto& r : results) {
        const Case& c = *r.c;
        size_t colliding = 0, near = 0, no_contact = 0;
        for (size_t f = 0; f < c.frames; ++f) colliding += r.truth[f], near += r.near[f], no_contact += !std::isfinite(r.s_star[f]);
        o << "**" << c.title << ".** " << c.about_b << " " << c.placement << " " << c.frames << " frames over the clip, " << colliding
          << " colliding (FCL, trees built afresh), " << near << " within ±1% of the diagonal (" << fixed(c.diag, 3)
          << ") of first contact; " << r.pushed_pose.size() << " near-contact poses. A: "
          << c.a.mesh().positions.size() << " vertices, " << c.a.mesh().triangles.size() << " triangles, "
          << r.deformed_samples << " samples; skinning (spt::pose_vertices, once a frame, not in the times) "
          << us(c.a.anim->skin_ns) << " µs a frame";
        if (c.b.deforming()) o << " and as much for B";
        else
            o << "; B: " << c.b.mesh().triangles.size() << " triangles, " << c.b.fixed_doc->samples.size() << " samples";
        o << ". FCL refit answers that differ from FCL built afresh: " << r.fcl_refit_vs_fresh << ".";
        // Every frame on which a library disagrees with FCL, with its distance from first contact.
        for (const auto& t : r.timings) {
            if (!t.in_main_table) continue;
            std::vector<std::string> miss;
            for (size_t f = 0; f < c.frames; ++f)
                if (t.answer[f] != r.truth[f])
                    miss.push_back(std::to_string(f) + (r.truth[f] ? " (FN" : " (FP") +
                                   (std::isfinite(r.s_star[f]) ? ", " + fixed(100 * (c.s - r.s_star[f]) / c.diag, 3) + "%" : "") + ")");
            if (miss.empty()) continue;
            o << " " << t.name << " disagrees at frame" << (miss.size() > 1 ? "s " : " ");
            for (size_t k = 0; k < miss.size() && k < 8; ++k) o << (k ? ", " : "") << miss[k];
            if (miss.size() > 8) o << " and " << miss.size() - 8 << " more";
            o << ".";
        }
        o << " (A frame's percentage is B's offset minus first contact over the diagonal: negative is deeper than "
             "first contact.)\n\n";
    }
    o << "| case | library | update µs | query µs | update + query µs (best round) | spt / FCL | spt / Bullet | agree, all "
         "frames (FP/FN) | agree, near-contact frames | agree, near-contact poses (FP/FN) |\n";
    o << "|---|---|---:|---:|---:|---:|---:|---|---|---|\n";
    for (const auto& r : results) {
        const Timing &fcl = named(r, "FCL OBBRSS refit"), &bullet = named(r, "Bullet GImpact");
        for (size_t i = 0; i < r.timings.size(); ++i) {
            const Timing& t = r.timings[i];
            if (!t.in_main_table) continue;
            const Summary& s = r.summary[i];
            const bool ours = t.name.rfind("spt", 0) == 0;
            o << "| " << r.c->name << " | " << t.name << " | " << us(s.update) << " | " << us(s.query) << " | **" << us(s.total)
              << "** (" << us(s.best) << ") | " << (ours ? fixed(ratio(t, fcl), 3) : "") << " | "
              << (ours ? fixed(ratio(t, bullet), 1) : "") << " | " << percent(s.agree_all, r.truth.size()) << " (" << s.frame_fp
              << "/" << s.frame_fn << ") | "
              << percent(s.agree_near, s.near) << " | " << percent(s.agree_pushed, s.pushed) << " (" << s.fp << "/" << s.fn
              << ") |\n";
        }
    }
    o << "\nThe query alone at the same pose, on the deformed model (posed outside the timed span) and on a model "
         "converted from scratch from the posed mesh (default options): first its first call at the frame (after the "
         "pose, or after the previous frame's query on another model), then the same query repeated at once, its data "
         "in cache:\n\n";
    o << "| case | level | deformed query µs (best round) | rigid query µs (best round) | deformed / rigid | repeated: "
         "deformed / rigid µs | repeated: deformed / rigid | node pairs, deformed / rigid (median) | sphere or triangle "
         "tests, deformed / rigid (median) | rigid agrees with FCL, all frames / near-contact poses | rigid conversion ms a "
         "frame (samples) |\n";
    o << "|---|---|---:|---:|---:|---:|---:|---|---|---|---|\n";
    for (const auto& r : results)
        for (size_t i = 0; i < r.timings.size(); ++i) {
            const Timing& d = r.timings[i];
            if (d.in_main_table || d.name.find("rigid") != std::string::npos) continue;
            // "spheres query, deformed" and "spheres query, lazy refit" against "spheres query, rigid".
            const std::string level = d.name.substr(0, d.name.find(' '));
            const std::string how = d.name.substr(d.name.find(", ") + 2);
            const Timing& g = named(r, level + " query, rigid");
            const Summary &sd = r.summary[i], &sg = r.summary[size_t(&g - r.timings.data())];
            o << "| " << r.c->name << " | " << level << (how == "deformed" ? "" : ", " + how) << " | " << us(sd.total) << " (" << us(sd.best)
              << ") | " << us(sg.total) << " (" << us(sg.best) << ") | " << fixed(ratio(d, g), 2) << " | " << us(sd.warm)
              << " / " << us(sg.warm) << " | " << fixed(warm_ratio(d, g), 2) << " | " << fixed(median(d.node_pairs), 0) << " / " << fixed(median(g.node_pairs), 0) << " | "
              << fixed(median(d.leaf_tests), 0) << " / " << fixed(median(g.leaf_tests), 0) << " | "
              << percent(sg.agree_all, r.truth.size()) << " / " << percent(sg.agree_pushed, sg.pushed) << " | "
              << fixed(r.convert_ns / 1e6, 2) << " (" << fixed(r.rigid_samples, 0) << ") |\n";
        }
    size_t bad = 0;
    for (const auto& r : results)
        for (const auto& t : r.timings) bad += t.inconsistent;
    if (bad) o << "\nAnswers that changed between rounds at the same frame: " << bad << ".\n";
}

int usage() {
    std::fprintf(stderr,
                 "usage: deforming_bench [--frames N] [--rounds R] [--figure GLTF] [--fbx FBX] [--out-dir DIR] [--stem NAME]\n"
                 "                       [--lazy-region SAMPLES] [--open MODEL] [--tolerance F] [--protrusion F]\n"
                 "                       [--clip-poses STEP] [--case NAME]...\n"
                 "       (--open: a case more, MODEL's first clip against a box, as the FBX model's; for an open\n"
                 "       mesh, whose spheres are two-sided, e.g. /usr/share/assimp/models/X/BCN_Epileptic.X;\n"
                 "       --tolerance, --protrusion: every model converted with that tolerance or protrusion allowance,\n"
                 "       F a fraction of its own diagonal, instead of spt convert's defaults; --clip-poses: the deforming\n"
                 "       models' spheres limited at their clips' poses STEP seconds apart, ConvertOptions::poses;\n"
                 "       --case: only the named cases (figure-floor, fbx-box, open-box, figure-figure), once each)\n"
                 "       deforming_bench --profile-update ITERATIONS [--profile-fbx] [--profile-spheres] [--profile-tight] [--profile-lazy]\n"
                 "                       (spt's update alone, for perf; --profile-spheres: without the triangles;\n"
                 "                       --profile-tight: set_tight_refit; --profile-lazy: pose_lazily_on, the pose alone)\n");
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    size_t frames = 120;
    int rounds = 5;
    long profile = 0;
    bool profile_fbx = false;
    bool profile_spheres = false; // the spheres level's pose: no triangle tree
    bool profile_tight = false;   // DeformingModel::set_tight_refit
    bool profile_lazy = false;    // DeformingModel::pose_lazily_on (the pose alone: no query poses a region)
    std::string figure = SPT_SOURCE_DIR "/resources/models/walking_figure.gltf";
    std::string fbx = "/usr/share/assimp/models/FBX/animation_with_skeleton.fbx";
    std::string open_model; // --open: a case more
    std::string out_dir, stem = "deforming-bench";
    std::set<std::string> only_cases; // --case: empty for every case
    std::string command = argv[0];
    for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) std::exit(usage());
            return argv[++i];
        };
        auto number = [&](long lo, long hi) {
            const std::string v = value();
            char* end = nullptr;
            const long n = std::strtol(v.c_str(), &end, 10);
            if (*end || n < lo || n > hi) std::exit(usage());
            return n;
        };
        if (a == "--frames") frames = size_t(number(2, 100000));
        else if (a == "--rounds") rounds = int(number(1, 1000));
        else if (a == "--figure") figure = value();
        else if (a == "--fbx") fbx = value();
        else if (a == "--open") open_model = value();
        else if (a == "--out-dir") out_dir = value();
        else if (a == "--stem") stem = value();
        else if (a == "--profile-update") profile = number(1, 100000000);
        else if (a == "--profile-fbx") profile_fbx = true;
        else if (a == "--profile-spheres") profile_spheres = true;
        else if (a == "--profile-tight") profile_tight = true;
        else if (a == "--profile-lazy") profile_lazy = true;
        else if (a == "--case") {
            const std::string name = value();
            if (name != "figure-floor" && name != "fbx-box" && name != "open-box" && name != "figure-figure") {
                std::fprintf(stderr, "deforming_bench: no case '%s' (figure-floor, fbx-box, open-box, figure-figure)\n", name.c_str());
                return 1;
            }
            only_cases.insert(name);
        }
        else if (a == "--lazy-region") g_lazy_region = uint32_t(number(1, 100000000));
        else if (a == "--clip-poses") {
            const std::string v = value();
            char* end = nullptr;
            g_clip_step = std::strtod(v.c_str(), &end);
            if (*end || !(g_clip_step > 0 && g_clip_step < 1e6)) return usage();
        }
        else if (a == "--tolerance" || a == "--protrusion") {
            const std::string v = value();
            char* end = nullptr;
            const double f = std::strtod(v.c_str(), &end);
            if (*end || !(f > 0 && f < 1)) return usage();
            (a == "--tolerance" ? g_tolerance : g_protrusion) = f;
        }
        else return usage();
    }
    if (only_cases.count("open-box") && open_model.empty()) {
        std::fprintf(stderr, "deforming_bench: --case open-box needs --open MODEL\n");
        return 1;
    }
    try {
        const std::string started = utc_now(), load0 = load_average();
        const auto t_start = Clock::now();
        auto fig_mesh = load_mesh(figure);
        auto fig_doc = std::make_shared<const SptDocument>(convert(fig_mesh->imported.mesh, fig_mesh.get()));
        const Animated walker = animate(fig_mesh, fig_doc, "walk", frames, 0);

        if (profile) { // spt's update alone, for `perf record`
            auto mesh = profile_fbx ? load_mesh(fbx) : fig_mesh;
            auto doc = profile_fbx ? std::make_shared<const SptDocument>(convert(mesh->imported.mesh, mesh.get())) : fig_doc;
            const Animated an = profile_fbx ? animate(mesh, doc, "0", frames, 0) : walker;
            DeformingModel m(*doc, mesh, std::string(), !profile_spheres);
            m.set_tight_refit(profile_tight);
            std::vector<double> ns;
            for (long k = 0; k < profile; ++k) {
                const auto t0 = Clock::now();
                if (profile_lazy) m.pose_lazily_on(an.frames[size_t(k) % frames]);
                else m.pose_on(an.frames[size_t(k) % frames]);
                ns.push_back(since_ns(t0));
            }
            // What the last pose left, hashed (FNV-1a): a change meant to be faster, not different,
            // must leave it as it was.
            uint64_t hash = 1469598103934665603ull;
            auto mix = [&](const void* p, size_t n) {
                for (size_t k = 0; k < n; ++k) hash = (hash ^ static_cast<const unsigned char*>(p)[k]) * 1099511628211ull;
            };
            const CollisionModel& posed = m.model();
            const CompactTree& tree = posed.tree();
            for (const CompactNode& n : tree.nodes()) {
                mix(&n, sizeof n);
                if (n.is_active()) mix(tree.centers(n), 3 * sizeof(float) * n.count);
            }
            const size_t spheres = tree.nodes().empty() ? 0 : tree.sphere_count();
            mix(tree.nx(), spheres), mix(tree.ny(), spheres), mix(tree.nz(), spheres);
            mix(posed.bounds_reach().data(), posed.bounds_reach().size() * sizeof(float));
            const double extent = posed.extent(), reach = posed.reach();
            mix(&extent, sizeof extent), mix(&reach, sizeof reach);
            std::printf("%ld poses of %zu samples, median %s us, last pose's hash %016llx\n", profile,
                        doc->samples.size(), us(median(ns)).c_str(), static_cast<unsigned long long>(hash));
            return 0;
        }

        const double fig_diag = fig_mesh->imported.mesh.diagonal();
        std::vector<Case> cases;
        {   // The figure walking in place; a floor tile under its left foot's track, its top 0.5% of
            // the diagonal above the floor the soles stand on (y = 0: the lower foot touches it at
            // every frame): the left foot strikes the tile while it stands and clears it as it swings.
            Case c;
            c.name = "figure-floor";
            c.title = "walking figure, floor tile under its left foot";
            c.a.anim = &walker;
            c.b.fixed_mesh = std::make_shared<const TriangleMesh>(
                box_mesh("floor tile", {0.0, -0.2, -0.6}, {0.4, 0.0, 0.6}));
            c.b.fixed_doc = std::make_shared<const SptDocument>(convert(*c.b.fixed_mesh));
            c.u = -Eigen::Vector3d::UnitY(); // the tile comes up from below: its top at y = -s
            c.diag = fig_diag, c.frames = frames;
            c.about_b = "B: a box 0.4 × 0.2 × 1.2 (x from 0 to 0.4: under the left foot only, z from -0.6 to 0.6).";
            c.s = -0.005 * fig_diag;
            c.placement = "The tile's top at y = " + fixed(-c.s, 4) + " (0.5% of the diagonal above the soles' floor).";
            cases.push_back(std::move(c));
        }
        // A model and a box on the side its clip swings furthest to.
        auto box_case = [&](const std::string& name, const std::string& title, const Animated& anim) {
            Case c;
            c.name = name;
            c.title = title;
            c.a.anim = &anim;
            const double diag = anim.mesh->imported.mesh.diagonal();
            // The axis direction along which the clip's extreme point moves most over the frames.
            double best = -1;
            for (int axis = 0; axis < 3; ++axis)
                for (double sign : {-1.0, 1.0}) {
                    const Eigen::Vector3d u = sign * Eigen::Vector3d::Unit(axis);
                    double lo = INFINITY, hi = -INFINITY;
                    for (const Verts& v : anim.frames) {
                        const double e = along(v, u, true);
                        lo = std::min(lo, e), hi = std::max(hi, e);
                    }
                    if (hi - lo > best) best = hi - lo, c.u = u;
                }
            // A cube a third of the model's diagonal: its face towards A at B's origin, across u
            // centred on where the extreme point is on average over the frames.
            int axis = 0;
            while (c.u[axis] == 0) ++axis;
            Eigen::Vector3d across = Eigen::Vector3d::Zero();
            for (const Verts& v : anim.frames) {
                size_t k = 0;
                for (size_t i = 1; i < v.size(); ++i)
                    if (c.u.dot(v[i]) > c.u.dot(v[k])) k = i;
                across += v[k] - c.u.dot(v[k]) * c.u;
            }
            across /= double(anim.frames.size());
            const double side = diag / 3;
            Eigen::Vector3d blo = across - Eigen::Vector3d::Constant(side / 2), bhi = across + Eigen::Vector3d::Constant(side / 2);
            blo[axis] = c.u[axis] > 0 ? 0 : -side, bhi[axis] = c.u[axis] > 0 ? side : 0;
            c.b.fixed_mesh = std::make_shared<const TriangleMesh>(box_mesh("box", blo, bhi));
            c.about_b = "B: a cube a third of the diagonal on the side to which the clip's extreme point moves most, "
                        "centred across on that point's mean position.";
            c.b.fixed_doc = std::make_shared<const SptDocument>(convert(*c.b.fixed_mesh));
            c.diag = diag, c.frames = frames;
            cases.push_back(std::move(c));
        };
        auto fbx_mesh = load_mesh(fbx);
        auto fbx_doc = std::make_shared<const SptDocument>(convert(fbx_mesh->imported.mesh, fbx_mesh.get()));
        const Animated fbx_anim = animate(fbx_mesh, fbx_doc, "0", frames, 0);
        box_case("fbx-box", "animation_with_skeleton.fbx and a box", fbx_anim);
        std::unique_ptr<Animated> open_anim;
        if (!open_model.empty()) {
            auto mesh = load_mesh(open_model);
            auto doc = std::make_shared<const SptDocument>(convert(mesh->imported.mesh, mesh.get()));
            open_anim = std::make_unique<Animated>(animate(mesh, doc, "0", frames, 0));
            box_case("open-box", std::filesystem::path(open_model).filename().string() + " and a box", *open_anim);
        }
        // A second walker, half a cycle on, facing the first.
        const Animated walker2 = animate(fig_mesh, fig_doc, "walk", frames, 0.5 * walker.clip->duration);
        {
            Case c;
            c.name = "figure-figure";
            c.title = "two walking figures face to face";
            c.a.anim = &walker, c.b.anim = &walker2;
            c.rot = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY()));
            c.u = Eigen::Vector3d::UnitZ();
            c.about_b = "B: the same figure turned 180° about y, half a cycle (" + fixed(0.5 * walker.clip->duration, 2) +
                        " s) on in the clip, in front of A (+z).";
            c.diag = fig_diag, c.frames = frames;
            cases.push_back(std::move(c));
        }

        if (!only_cases.empty())
            cases.erase(std::remove_if(cases.begin(), cases.end(), [&](const Case& c) { return !only_cases.count(c.name); }),
                        cases.end());
        // Each case's offset: the median of the frames' first contacts, so that about half the
        // frames collide and the contact comes and goes along the clip.
        for (Case& c : cases) {
            if (!c.placement.empty()) continue; // placed by hand
            std::vector<double> s;
            for (size_t f = 0; f < c.frames; ++f) {
                FclTruth truth(c, f);
                const double v = first_contact(c, f, truth);
                if (std::isfinite(v)) s.push_back(v);
            }
            if (s.empty()) throw Error(ErrorKind::BadInput, c.name + ": the objects never touch along the approach");
            c.s = median(s);
            std::ostringstream p;
            const auto [mn, mx] = std::minmax_element(s.begin(), s.end());
            p << "B offset along (" << c.u.x() + 0.0 << ", " << c.u.y() + 0.0 << ", " << c.u.z() + 0.0 << ") by " << fixed(c.s, 4)
              << ", the median of the frames' first contacts (" << fixed(*mn, 4) << " to " << fixed(*mx, 4) << ").";
            c.placement = p.str();
            std::cerr << c.name << ": " << c.placement << "\n";
        }

        std::vector<CaseResult> results;
        for (const Case& c : cases) results.push_back(measure(c, rounds, 0.01));
        const double seconds = std::chrono::duration<double>(Clock::now() - t_start).count();
        print_markdown(std::cout, results, command, started, load0, load_average(), rounds, seconds);
        if (!out_dir.empty()) {
            const std::string md = out_dir + "/" + stem + ".md";
            std::ofstream o(md);
            o << "# Deforming objects: update + query per frame\n\nGenerated by `deforming_bench` (bench/deforming/"
                 "deforming_bench.cpp); what it measures and what the figures mean: [deforming.md](deforming.md), "
                 "\"Benchmark\". Do not edit by hand.\n\n";
            print_markdown(o, results, command, started, load0, load_average(), rounds, seconds);
            o << "\n![agreement near contact against time a frame](" << stem << ".svg)\n\nPer frame: [" << stem
              << "-frames.csv](" << stem << "-frames.csv); per library: [" << stem << ".csv](" << stem << ".csv).\n";
            if (!o) throw Error(ErrorKind::CannotWrite, md + ": cannot write");
            write_frames_csv(out_dir + "/" + stem + "-frames.csv", results);
            write_summary_csv(out_dir + "/" + stem + ".csv", results);
            write_work_csv(out_dir + "/" + stem + "-work.csv", results);
            write_svg(out_dir + "/" + stem + ".svg", results);
            std::cerr << "wrote " << out_dir << "/" << stem << "{.md,.csv,-frames.csv,-work.csv,.svg}\n";
        }
        return 0;
    } catch (const Error& e) {
        std::fprintf(stderr, "deforming_bench: %s\n", e.what());
        return cli::exit_code(e.kind());
    }
}
