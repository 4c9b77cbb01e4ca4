#pragma once
// spt-viewer's main window: one SceneView of a recorded scene, playback (Space, Left, Right,
// a timeline, a speed), overlay toggles, the counters panel and energy plot, PNG export, and reload when
// the scene file changes on disk. Every state drawn is one core simulated (SceneHistory).
#include "counters_panel.hpp"
#include "energy_plot.hpp"
#include "scene_history.hpp"
#include "scene_view.hpp"
#include <QElapsedTimer>
#include <QFileSystemWatcher>
#include <QMainWindow>
#include <QTimer>
#include <array>
#include <map>
#include <memory>

class QAction;
class QComboBox;
class QLabel;
class QSlider;

namespace spt::editor {

/// How the viewer starts (the command line).
struct ViewerStart {
    QString file;                          ///< scene to open; empty: none
    int step = 0;                          ///< state shown first
    render::View view = render::View::Camera; ///< view kind
    ViewerOverlays overlays;               ///< what is drawn over the objects
    double speed = 1;                      ///< playback speed, 1 = real time (dt seconds a step)
    bool play = false;                     ///< start playing once loaded
};

/// The viewer window.
class ViewerWindow : public QMainWindow {
    Q_OBJECT
public:
    /// A window that opens `start.file` in the background.
    explicit ViewerWindow(const ViewerStart& start, QWidget* parent = nullptr);
    ~ViewerWindow() override;

    /// Opens a scene file in the background; on failure the open scene stays and the reason is shown.
    void open(const QString& path);
    /// Loads the open scene's file again (as when it changes on disk), keeping the step and camera.
    void reload();
    /// The history shown; null before the first scene has loaded.
    const SceneHistory* history() const { return history_.get(); }
    /// True while a scene is loading or re-recording before it replaces the shown one.
    bool busy() const { return pending_ != nullptr; }
    /// The state shown.
    int step() const { return view_->step(); }
    /// Shows state `step`, clamped to [0, what is recorded].
    void set_step(int step);
    /// Starts or stops playback.
    void set_playing(bool playing);
    /// True while playing.
    bool playing() const { return playing_; }
    /// Sets the playback speed (1 = real time).
    void set_speed(double speed);
    /// Sets the overlays; re-records if they need effects the recording lacks (or no longer needs).
    void set_overlays(const ViewerOverlays& overlays);
    /// The overlays drawn.
    const ViewerOverlays& overlays() const { return overlays_; }
    /// The view.
    SceneView* view() const { return view_; }
    /// The counters panel.
    CountersPanel* counters() const { return counters_; }
    /// The energy plot under the counters.
    EnergyPlot* energy() const { return energy_; }
    /// Writes states first..last as PNGs of the view (each `spt render` of that step, view and
    /// size), waiting for steps not recorded yet. `pattern` holds {frame} unless first == last.
    /// False with the reason (naming the file) in `error`.
    bool export_frames(int first, int last, const QString& pattern, QString* error);
    /// The last message shown in the status bar.
    const QString& last_message() const { return last_message_; }
    /// The last error shown.
    const QString& last_error() const { return last_error_; }

signals:
    /// The shown step changed.
    void stepShown(int step);
    /// A scene replaced the shown one (opened, reloaded or re-recorded).
    void historyChanged();

private:
    void build_actions();
    void build_toolbar();
    void start_pending(std::unique_ptr<SceneHistory> h, int want_step, bool refit);
    void adopt_pending();
    void pending_progress(int recorded);
    void show_state();
    void tick();
    void overlay_toggled();
    void export_frame_dialog();
    void export_range_dialog();
    void show_error(const QString& text);
    void show_message(const QString& text);
    void watch(const QString& path);
    // The file's inode, size and modification time (seconds, nanoseconds); -1s if it is missing.
    static std::array<int64_t, 4> file_stamp(const QString& path);

    SceneView* view_ = nullptr;
    CountersPanel* counters_ = nullptr;
    EnergyPlot* energy_ = nullptr;
    QSlider* timeline_ = nullptr;
    QLabel* step_label_ = nullptr;
    QComboBox* speed_box_ = nullptr;
    QComboBox* view_box_ = nullptr;
    QAction* play_action_ = nullptr;
    std::map<std::string, QAction*> overlay_actions_; // by the name `spt render --overlay` uses
    std::unique_ptr<SceneHistory> history_, pending_;
    // The step a pending history must reach before it replaces the shown one, or
    // kFollowShownStep: the step shown when it gets there (reload, re-recording while playing).
    static constexpr int kFollowShownStep = -1;
    int pending_step_ = 0;
    bool pending_refit_ = false;
    ViewerOverlays overlays_;
    bool playing_ = false;
    double speed_ = 1, carry_ = 0;
    QTimer play_timer_;
    QElapsedTimer clock_;
    QFileSystemWatcher watcher_;
    QTimer reload_timer_, poll_timer_;
    std::array<int64_t, 4> watched_stamp_{};
    QString last_message_, last_error_;
};

} // namespace spt::editor
