// SceneHistory: load a scene and record its simulation on a worker thread.
#include "scene_history.hpp"
#include "spt/error.hpp"
#include <QMetaObject>
#include <algorithm>
#include <chrono>

namespace spt::editor {

SceneHistory::SceneHistory(const QString& path, const render::SceneOverlays& overlays, QObject* parent)
    : QObject(parent), path_(path) {
    worker_ = std::thread([this, overlays] { run(overlays, true); });
}

SceneHistory::SceneHistory(std::shared_ptr<const Scene> scene, const render::SceneOverlays& overlays,
                           QObject* parent)
    : QObject(parent), path_(QString::fromStdString(scene->file)), scene_(std::move(scene)) {
    worker_ = std::thread([this, overlays] { run(overlays, false); });
}

SceneHistory::~SceneHistory() {
    stop_ = true;
    if (worker_.joinable()) worker_.join();
}

int SceneHistory::recorded() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return int(states_.size()) - 1;
}

QString SceneHistory::error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return error_;
}

std::shared_ptr<const RecordedState> SceneHistory::state(int k) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (k < 0 || size_t(k) >= states_.size()) return nullptr;
    return states_[size_t(k)];
}

std::vector<std::vector<Eigen::Vector3f>> SceneHistory::trails(int k) const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::vector<Eigen::Vector3f>> out(scene_ ? scene_->objects.size() : 0);
    const size_t steps = std::min(size_t(std::max(k, 0)) + 1, states_.size());
    for (auto& trail : out) trail.reserve(steps);
    for (size_t s = 0; s < steps; ++s)
        for (size_t i = 0; i < out.size(); ++i) out[i].push_back(states_[s]->poses[i].translation.cast<float>());
    return out;
}

std::vector<double> SceneHistory::energies(int k) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const size_t steps = std::min(size_t(std::max(k, 0)) + 1, states_.size());
    std::vector<double> out(steps);
    for (size_t s = 0; s < steps; ++s) out[s] = states_[s]->energy;
    return out;
}

void SceneHistory::record(const Simulation& sim, const StepResult* step) {
    auto s = std::make_shared<RecordedState>();
    s->poses = sim.poses();
    s->ghost = sim.ghost_poses();
    s->energy = sim.mechanical_energy();
    if (step) s->step = *step, s->broad = sim.broad_spheres();
    size_t bytes = sizeof(RecordedState) + (s->poses.size() + s->ghost.size()) * sizeof(Pose) +
                   s->broad.size() * sizeof(BroadSphere);
    if (step)
        for (const PairContact& c : step->contacts)
            bytes += sizeof(c) + c.pairs.size() * sizeof(SpherePair) + c.manifold.size() * sizeof(ContactPoint);
    std::lock_guard<std::mutex> lock(mutex_);
    states_.push_back(std::move(s));
    bytes_ += bytes;
}

void SceneHistory::run(render::SceneOverlays overlays, bool load) {
    auto fail = [this](const QString& message) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            error_ = message;
        }
        finished_ = true;
        QMetaObject::invokeMethod(this, [this, message] { emit failed(message), emit stopped(); }, Qt::QueuedConnection);
    };
    try {
        // A history dropped while its meshes convert (the window closed, the file reloaded)
        // stops them.
        if (load) scene_ = std::make_shared<const Scene>(load_scene(path_.toStdString(), &stop_));
        effects_ = render::effects_for_overlays(scene_->effects, overlays);
        target_ = scene_->steps;
        Simulation sim(*scene_, effects_, hardware_threads());
        record(sim, nullptr);
        loaded_ = true;
        QMetaObject::invokeMethod(this, [this] { emit sceneLoaded(), emit progressed(0); }, Qt::QueuedConnection);
        auto last_signal = std::chrono::steady_clock::now();
        while (!stop_ && sim.steps_done() < target_) {
            const StepResult& r = sim.step();
            record(sim, &r);
            const auto now = std::chrono::steady_clock::now();
            const bool last = sim.steps_done() == target_;
            if (last || now - last_signal > std::chrono::milliseconds(30)) {
                last_signal = now;
                const int n = sim.steps_done();
                QMetaObject::invokeMethod(this, [this, n] { emit progressed(n); }, Qt::QueuedConnection);
            }
            if (bytes_ > kMemoryBudget && !last)
                return fail(QString("%1: recording stopped at step %2: the history reached %3 GiB")
                                .arg(path_)
                                .arg(sim.steps_done())
                                .arg(double(kMemoryBudget) / double(1 << 30)));
        }
        finished_ = true;
        QMetaObject::invokeMethod(this, [this] { emit stopped(); }, Qt::QueuedConnection);
    } catch (const Cancelled&) {
        finished_ = true; // only the destructor stops a history: nobody is told
    } catch (const std::exception& e) {
        // load_scene's messages name the file and the JSON path already.
        fail(QString::fromStdString(e.what()));
    }
}

} // namespace spt::editor
