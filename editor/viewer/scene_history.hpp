#pragma once
// The viewer's recorded history: a scene file loaded and simulated step by step on a worker
// thread, every state kept so that playback can step back and scrub. The simulation is
// core's (spt/simulation.hpp); this only runs it and keeps what it returns.
#include "spt/render/scene_drawing.hpp"
#include "spt/simulation.hpp"
#include <QObject>
#include <QString>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace spt::editor {

/// The state after step k (k = 0: the initial state), as the simulation left it.
struct RecordedState {
    std::vector<Pose> poses;          ///< world frame, object order
    std::vector<Pose> ghost;          ///< poses before the step's response
    std::optional<StepResult> step;   ///< what step k did; none for k = 0
    std::vector<BroadSphere> broad;   ///< broad-phase spheres of step k (empty for k = 0)
    double energy = 0;                ///< Simulation::mechanical_energy() of this state
};

/// A scene and its simulation, recorded in the background.
class SceneHistory : public QObject {
    Q_OBJECT
public:
    /// Loads `path` and records its simulation with the scene's effects plus what `overlays`
    /// need (render::effects_for_overlays), up to the scene's step count, on a worker thread.
    SceneHistory(const QString& path, const render::SceneOverlays& overlays, QObject* parent = nullptr);
    /// Records `scene` (already loaded) the same way.
    SceneHistory(std::shared_ptr<const Scene> scene, const render::SceneOverlays& overlays,
                 QObject* parent = nullptr);
    /// Stops the worker and waits for it.
    ~SceneHistory() override;

    /// The scene file.
    const QString& path() const { return path_; }
    /// True once the scene has loaded (scene() and effects() are valid).
    bool loaded() const { return loaded_; }
    /// The scene; valid once loaded().
    const Scene& scene() const { return *scene_; }
    /// The scene, to share with a history that records it with other effects; valid once loaded().
    std::shared_ptr<const Scene> shared_scene() const { return scene_; }
    /// The effects simulated; valid once loaded().
    EffectSet effects() const { return effects_; }
    /// The last step recorded so far (0: only the initial state); -1 before loading.
    int recorded() const;
    /// The step recording stops at (the scene's `steps`).
    int target() const { return target_; }
    /// True when the worker has stopped: done, failed or out of memory budget.
    bool finished() const { return finished_; }
    /// Why loading or recording stopped early; empty if it did not.
    QString error() const;
    /// State k, 0 <= k <= recorded().
    std::shared_ptr<const RecordedState> state(int k) const;
    /// Each object's origin at steps 0..k, for the trails overlay (world frame).
    std::vector<std::vector<Eigen::Vector3f>> trails(int k) const;
    /// The mechanical energy of states 0..k (those recorded), for the energy plot.
    std::vector<double> energies(int k) const;
    /// Memory the recorded states may take before recording stops, bytes.
    static constexpr size_t kMemoryBudget = size_t(4) << 30;

signals:
    /// The scene has loaded (queued to the object's thread).
    void sceneLoaded();
    /// More steps are recorded; `recorded` is the last one (queued, at most every ~30 ms).
    void progressed(int recorded);
    /// Loading or a step failed; `message` names the file and the problem (queued).
    void failed(const QString& message);
    /// Recording stopped: the target was reached or something failed (queued).
    void stopped();

private:
    void run(render::SceneOverlays overlays, bool load);
    void record(const Simulation& sim, const StepResult* step);
    QString path_;
    std::shared_ptr<const Scene> scene_;
    EffectSet effects_;
    int target_ = 0;
    std::atomic<bool> loaded_{false}, finished_{false}, stop_{false};
    mutable std::mutex mutex_;
    std::vector<std::shared_ptr<const RecordedState>> states_;
    QString error_;
    size_t bytes_ = 0;
    std::thread worker_;
};

} // namespace spt::editor
