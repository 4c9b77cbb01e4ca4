#pragma once
// The editor's main window: the four views left of a dock with the tree panel and the
// undo history; File and Edit menus, a toolbar, a status bar with progress; atomic
// saves, a modified mark in the title, recovery files.
#include "document_loader.hpp"
#include "editor_document.hpp"
#include "motion_session.hpp"
#include "preferences.hpp"
#include "recovery.hpp"
#include "spt/tree_builder.hpp"
#include "scene.hpp"
#include "view_grid.hpp"
#include <QFutureWatcher>
#include <QMap>
#include <QMainWindow>
#include <QTimer>
#include <QUndoStack>
#include <atomic>
#include <memory>
#include <optional>

class QLabel;
class QProgressBar;
class QUndoView;
class QPushButton;

namespace spt::editor {

class CostPanel;
class TimelineBar;
class TreePanel;

/// How the editor was started (spt-editor [FILE] [-o OUT.spt] [--mesh MESH] [--autosave SECONDS]).
struct StartOptions {
    QString file;          ///< mesh or .spt to open
    QString output;        ///< where Save writes (no dialog)
    QString mesh;          ///< the .spt file's mesh, if not beside it
    int autosave_seconds = -1; ///< recovery file period, seconds; 0 turns it off; -1: the preference
    QString recovery_dir;  ///< empty: the application data location's "recovery"
    QString scene;         ///< a scene whose motion is loaded once FILE is open (--scene)
    QString object;        ///< its object (--object); empty: the one whose model is FILE's mesh
    int motion_steps = 0;  ///< steps of that motion (--motion-steps); 0: the scene's own
};

/// The editor window.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    /// A window started with `options`; opening FILE starts in the background.
    explicit MainWindow(const StartOptions& options, QWidget* parent = nullptr);
    ~MainWindow() override;

    /// The open document.
    EditorDocument& document() { return doc_; }
    /// The undo stack of the document's edits.
    QUndoStack& undo_stack() { return stack_; }
    /// The views.
    ViewGrid& grid() { return *grid_; }
    /// What the views draw.
    const Scene& scene() const { return scene_; }
    /// The dock's tree panel.
    TreePanel& tree_panel() { return *panel_; }
    /// The dock's cost panel.
    CostPanel& cost_panel() { return *cost_; }
    /// The timeline under the views (shown while the mesh has animation clips).
    TimelineBar& timeline() { return *timeline_; }
    /// Shared view settings (visible-only selection, modifier swap).
    ViewOptions& view_options() { return options_; }
    /// True while a file is being opened in the background.
    bool loading() const { return opening_; }
    /// The last error shown (file and problem), for tests.
    const QString& last_error() const { return last_error_; }
    /// The last status-bar message.
    const QString& last_message() const { return last_message_; }
    /// True when the document has changes not saved.
    bool modified() const;
    /// Where Save writes (empty: Save asks).
    const QString& save_path() const { return save_path_; }

    /// Starts opening `path` in the background (the document stays until it succeeds).
    void open_file(const QString& path, const QString& mesh_path = {});
    /// The files of Open Recent, newest first.
    QStringList recent_files() const;
    /// Offers the recovery files dead editors left; true if one was opened.
    bool offer_recovery();
    /// Saves to `path` atomically; false (message shown) if it could not.
    bool save_to(const QString& path);
    /// Writes the recovery file now if there is unsaved work.
    void autosave();
    /// Reopens the document's file, dropping unsaved changes after asking (File > Revert);
    /// false if there is no file or the changes are kept.
    bool revert();
    /// Applies preferences at once (recovery period, selection keys and mode, colours) and,
    /// with `save`, keeps them for the next sessions.
    void apply_preferences(const Preferences& preferences, bool save = true);
    /// The preferences in effect.
    const Preferences& preferences() const { return preferences_; }
    /// Opens the preferences dialog (Edit > Preferences); accepting it applies them.
    void show_preferences();

    /// Chooses what a left drag draws (R rectangle, L lasso, C brush).
    void set_select_tool(SelectTool tool);
    /// Sets the brush radius, logical pixels (held within 2 to 500; [ and ] scale it by 1.25).
    void set_brush_radius(double radius);
    /// Select linked under the cursor in the view it was last over (Ctrl+L adds, Ctrl+Shift+L subtracts).
    void select_linked(SelectionMode mode);
    /// Inverts the selection within the current node (Ctrl+I).
    void invert_selection();
    /// Grows the selection by one ring of mesh neighbours (Ctrl+NumPad+).
    void grow_selection();
    /// Shrinks the selection by one ring (Ctrl+NumPad-).
    void shrink_selection();
    /// Hides the current node's spheres in every view (H), a view state, not an edit.
    void hide_current();
    /// Shows only the current node's spheres (Shift+H).
    void isolate_current();
    /// Shows every node (Alt+H).
    void show_all_nodes();

    /// Splits the current node by the selection (key S).
    bool split();
    /// Merges the current node's children.
    bool merge();
    /// Sets the current node's sampling-sphere radius.
    bool set_radius(float radius);
    /// Builds a subtree under the current node with the panel's options: at once for a node
    /// of fewer than background_build_samples() samples, else in the background (progress,
    /// Cancel); false if refused.
    bool build_subtree();
    /// True while a subtree is being built in the background.
    bool building() const { return build_pending_; }
    /// Nodes with at least this many samples are built in the background (tests lower it).
    void set_background_build_samples(size_t samples) { background_build_samples_ = samples; }
    /// The motion loaded for the document (File > Load motion), if any.
    MotionSession& motion() { return motion_; }
    /// Starts loading the motion of `object` in `scene_path` (`steps` steps; 0: the scene's) in the
    /// background with the edited tree (what File > Load motion does once the object is chosen);
    /// false if refused (no document, a load running).
    bool load_motion(const QString& scene_path, const QString& object, int steps = 0);
    /// Asks for a scene file, then for its object, and loads the motion (File > Load motion).
    void choose_motion();
    /// Builds under the current node for the loaded motion (Shift+B), in the background; applied
    /// as one undo command recording the build in the tree. False if refused.
    bool build_from_motion();
    /// The action of Build from motion (enabled with a motion and an active current node).
    QAction* build_motion_action() const { return build_motion_action_; }
    /// Adds a tree named `name` (a free name if empty).
    bool add_tree(const QString& name = {});
    /// Renames the edited tree.
    bool rename_tree(const QString& name);
    /// Duplicates the edited tree under `name` (a free name if empty).
    bool duplicate_tree(const QString& name = {});
    /// Deletes the edited tree.
    bool delete_tree();

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void build_menus();
    void build_select_menu();
    void apply_operation(StrokeKind kind, const QString& what);
    ViewWidget* hover_view_ = nullptr; // the view the mouse was last over
    class QActionGroup* tool_group_ = nullptr;
    void build_docks();
    void loaded(const LoadResult& result);
    void show_error(const QString& text);
    void show_message(const QString& text);
    bool push(struct EditOutcome outcome);
    bool maybe_save();
    bool save();
    bool save_as();
    void update_title();
    void add_recent(const QString& path);
    void refresh_recent();

    StartOptions start_;
    EditorDocument doc_;
    QUndoStack stack_;
    Scene scene_;
    ViewOptions options_;
    ViewGrid* grid_ = nullptr;
    TimelineBar* timeline_ = nullptr;
    TreePanel* panel_ = nullptr;
    CostPanel* cost_ = nullptr;
    QUndoView* history_ = nullptr;
    QString save_path_, source_path_, mesh_path_, pending_save_path_;
    bool unsaved_new_ = false, recovering_ = false, discard_on_open_ = false;
    bool opening_ = false; // from open_file until its result has been taken in
    QTimer autosave_timer_;
    Recovery recovery_;
    QFutureWatcher<LoadResult> watcher_;
    struct BuildJob {
        std::optional<SamplingTree> tree; // the edited tree with the subtree built
        QString refusal;     // why core refused, if it did
        bool stopped = false; // core's builder saw the cancel flag and stopped
    };
    QFutureWatcher<BuildJob> build_watcher_;
    size_t background_build_samples_ = 20000;
    int build_stack_index_ = -1, build_tree_index_ = -1;
    NodeId build_node_ = 0;
    BuildOptions build_options_;
    bool build_pending_ = false; // started, result not yet taken in
    std::shared_ptr<std::atomic<bool>> build_cancel_flag_; // the running build's; set: Cancel build was clicked
    QProgressBar* build_progress_ = nullptr;
    QPushButton* build_cancel_ = nullptr;
    void build_finished();
    bool start_build(NodeId node, size_t samples, bool from_motion);
    void update_motion_actions();
    void motion_loaded();
    QString motion_scene_for_file() const;
    MotionSession motion_;
    bool build_motion_ = false; // the build running is from motion
    MotionBuildStep build_motion_step_;
    QString build_motion_label_;
    bool start_motion_pending_ = false; // --scene: load it once the document is in
    QMap<QString, QString> measured_;   // tree name: the motion it was last measured on
    class QAction* build_motion_action_ = nullptr;
    QProgressBar* motion_progress_ = nullptr;
    QPushButton* motion_cancel_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
    bool cancelled_ = false;
    // The opening's cancel flag, shared with the worker (which may outlive a cancelled opening).
    std::shared_ptr<std::atomic<bool>> open_cancel_;
    QString last_error_, last_message_;
    class QMenu* recent_menu_ = nullptr;
    Preferences preferences_;
    class QAction *visible_action_ = nullptr, *swap_action_ = nullptr;
};

} // namespace spt::editor
