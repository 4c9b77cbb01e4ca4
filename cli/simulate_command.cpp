// spt simulate SCENE.json [--steps N] [--effects LIST] [-o STEPS.csv] [--contacts CONTACTS.csv]
//              [--poses-out POSES.csv] [--threads N]
#include "commands.hpp"
#include "spt/error.hpp"
#include "spt/simulation.hpp"
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace spt::cli {
namespace {

struct SimulateArgs {
    std::string scene, effects, output, contacts, poses;
    int64_t steps = -1;
    int threads = hardware_threads();
    bool effects_given = false;
};

// An output file (stdout for an empty name) closed on destruction; failures are CannotWrite.
class Output {
public:
    explicit Output(const std::string& path) : path_(path) {
        if (path.empty()) return;
        f_ = std::fopen(path.c_str(), "w");
        if (!f_) throw Error(ErrorKind::CannotWrite, path + ": cannot open for writing: " + std::strerror(errno));
    }
    ~Output() {
        if (f_ && f_ != stdout) std::fclose(f_);
    }
    std::FILE* get() const { return f_; }
    void close() {
        if (f_ && f_ != stdout && std::fclose(f_) != 0) {
            f_ = nullptr;
            throw Error(ErrorKind::CannotWrite, path_ + ": write failed");
        }
        if (f_ == stdout && std::fflush(stdout) != 0) throw Error(ErrorKind::CannotWrite, "stdout: write failed");
        f_ = nullptr;
    }
    static Output standard() {
        Output o("");
        o.f_ = stdout;
        return o;
    }
    Output(Output&& o) noexcept : path_(std::move(o.path_)), f_(o.f_) { o.f_ = nullptr; }

private:
    std::string path_;
    std::FILE* f_ = nullptr;
};

void draw_progress(int64_t done, int64_t total) {
    const int width = 30;
    const int filled = total ? int(width * done / total) : width;
    std::cerr << "\r[" << std::string(size_t(filled), '#') << std::string(size_t(width - filled), '.') << "] " << done
              << "/" << total << " steps" << std::flush;
}

void write_contacts(std::FILE* f, const Scene& s, const StepResult& r) {
    for (const PairContact& c : r.contacts) {
        std::fprintf(f, "%d,%s,%s,", r.step, s.objects[c.a].name.c_str(), s.objects[c.b].name.c_str());
        if (c.has_depth)
            std::fprintf(f, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,", c.depth, c.point.x(), c.point.y(), c.point.z(),
                         c.normal.x(), c.normal.y(), c.normal.z());
        else
            std::fputs(",,,,,,,", f);
        if (c.has_toi) std::fprintf(f, "%.9g", c.toi);
        std::fputc('\n', f);
    }
}

// One row per object of the simulation's current state: pose and velocities, world frame.
void write_poses(std::FILE* f, const Simulation& sim) {
    const double time = sim.steps_done() * sim.scene().dt;
    for (size_t i = 0; i < sim.poses().size(); ++i) {
        const Pose& p = sim.poses()[i];
        const auto [v, w] = sim.object_velocity(i);
        const Eigen::Quaterniond& r = p.rotation;
        std::fprintf(f, "%d,%.17g,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                     sim.steps_done(), time, sim.scene().objects[i].name.c_str(), p.translation.x(), p.translation.y(),
                     p.translation.z(), r.w(), r.x(), r.y(), r.z(), v.x(), v.y(), v.z(), w.x(), w.y(), w.z());
    }
}

int run_simulate(const SimulateArgs& a) {
    Scene scene = load_scene(a.scene);
    const EffectSet effects = a.effects_given ? parse_effect_list(a.effects, "--effects") : scene.effects;
    const int64_t steps = a.steps >= 0 ? a.steps : scene.steps;
    for (const SceneObject& o : scene.objects)
        if (o.name.find_first_of(",\"\n") != std::string::npos && (!a.contacts.empty() || !a.poses.empty()))
            throw Error(ErrorKind::BadInput, a.scene + ": object name '" + o.name + "' cannot be written to CSV");
    Simulation sim(std::move(scene), effects, a.threads);
    Output out = a.output.empty() ? Output::standard() : Output(a.output);
    std::unique_ptr<Output> contacts;
    if (!a.contacts.empty()) contacts = std::make_unique<Output>(a.contacts);
    std::unique_ptr<Output> poses;
    if (!a.poses.empty()) poses = std::make_unique<Output>(a.poses);
    std::fprintf(out.get(), "step,time,candidate_pairs,colliding_pairs,node_pairs,sphere_tests,triangle_tests,"
                            "depth_queries,ccd_queries,responses,ns_broad,ns_narrow,ns_depth,ns_ccd,ns_response,"
                            "ns_deform,ns_dynamics,state_hash\n");
    if (contacts) std::fprintf(contacts->get(), "step,a,b,depth,px,py,pz,nx,ny,nz,toi\n");
    if (poses) {
        std::fprintf(poses->get(), "step,time,object,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n");
        write_poses(poses->get(), sim); // step 0: the initial state
    }
    const bool tty = ::isatty(2) && steps >= 100;
    const int64_t every = std::max<int64_t>(1, steps / 100);
    for (int64_t i = 0; i < steps; ++i) {
        const StepResult& r = sim.step();
        const StepCounters& c = r.counters;
        std::fprintf(out.get(), "%d,%.9g,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%lld,%lld,%lld,%lld,%lld,%lld,%lld,%016llx\n",
                     r.step, r.time, (unsigned long long)c.candidate_pairs, (unsigned long long)c.colliding_pairs,
                     (unsigned long long)c.node_pairs, (unsigned long long)c.sphere_tests,
                     (unsigned long long)c.triangle_tests, (unsigned long long)c.depth_queries,
                     (unsigned long long)c.ccd_queries, (unsigned long long)c.responses, (long long)c.ns_broad,
                     (long long)c.ns_narrow, (long long)c.ns_depth, (long long)c.ns_ccd, (long long)c.ns_response,
                     (long long)c.ns_deform, (long long)c.ns_dynamics, (unsigned long long)r.state_hash);
        if (contacts) write_contacts(contacts->get(), sim.scene(), r);
        if (poses) write_poses(poses->get(), sim);
        if (tty && ((i + 1) % every == 0 || i + 1 == steps)) draw_progress(i + 1, steps);
    }
    if (tty) std::cerr << "\n";
    out.close();
    if (contacts) contacts->close();
    if (poses) poses->close();
    return 0;
}

} // namespace

Action add_simulate_command(CLI::App& app) {
    auto a = std::make_shared<SimulateArgs>();
    CLI::App* c = app.add_subcommand("simulate", "Step a scene, computing only the effects asked for (CSV out)");
    c->add_option("scene", a->scene, "Scene file (JSON, docs/scenes.md)")->required();
    c->add_option("--steps", a->steps, "Steps to run (default: the scene's 'steps')")->check(CLI::Range(int64_t(0), int64_t(1000000000)));
    c->add_option("--effects", a->effects,
                  "Comma-separated effects replacing the scene's: motion,gravity,contacts,depth,pairs,response,ccd,exact,deform,dynamics")
        ->each([a](const std::string&) { a->effects_given = true; });
    c->add_option("-o,--output", a->output, "Per-step CSV (default: stdout)");
    c->add_option("--contacts", a->contacts, "CSV of every colliding object pair of every step");
    c->add_option("--poses-out", a->poses,
                  "CSV of every object's pose and velocities (world frame) at every step, step 0 the initial state");
    c->add_option("--threads", a->threads, "Threads for the pair queries and the response (default: the machine's; the results do not depend on it)")
        ->check(CLI::Range(1, 256));
    return [a] { return run_simulate(*a); };
}

} // namespace spt::cli
