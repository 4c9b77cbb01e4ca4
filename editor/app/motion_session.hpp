#pragma once
// Authoring from motion (issue 40): a scene run with the edited tree in place of one object's
// model, in the background (core's record_motion), and the recording kept for this session: the
// heat map, builds from motion and the cost panel read it. It is view data, not an edit: nothing
// goes on the undo stack.
#include "spt/motion.hpp"
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QStringList>
#include <atomic>
#include <memory>

namespace spt::editor {

/// The objects of a scene file as its JSON lists them (names and the files of their models).
struct SceneObjects {
    QStringList names;  ///< in file order
    QStringList models; ///< each object's "model" and "mesh" file names (basenames), space-separated
    QString error;      ///< non-empty: the file could not be read (names the file)
};
/// Reads the object list of scene file `path` with core's parse_scene (models not loaded: load_scene
/// loads them when the motion runs); a bad scene gives core's message.
SceneObjects read_scene_objects(const QString& path);
/// The object of `objects` whose model or mesh file is the document's (`mesh_name`, the file the
/// samples were taken from, or `document_file`, the opened .spt); -1 if none.
int matching_object(const SceneObjects& objects, const QString& mesh_name, const QString& document_file);

/// A motion loaded, or being loaded, for the open document.
class MotionSession : public QObject {
    Q_OBJECT
public:
    explicit MotionSession(QObject* parent = nullptr);
    ~MotionSession() override;

    /// Starts recording `object` of `scene_path` for `steps` steps (0: the scene's own) with
    /// `model` (the document, its edited tree and mesh) on a worker thread; the loaded motion stays
    /// until the new one is in. False if a load is running already.
    bool load(const QString& scene_path, const QString& object, int steps, MotionModel model);
    /// Stops the running load (its result is dropped).
    void cancel();
    /// Forgets the motion (another document opened).
    void clear();
    /// True while a load runs.
    bool loading() const { return watcher_.isRunning(); }
    /// The loaded motion, or null.
    std::shared_ptr<const MotionRecording> recording() const { return recording_; }
    /// The scene file the motion was loaded from (as given).
    const QString& scene_path() const { return scene_path_; }
    /// Steps asked for (0: the scene's own).
    int steps() const { return steps_; }
    /// "walking.json / walker": what the tree box and the messages call the motion.
    QString label() const;

signals:
    /// A load started.
    void started();
    /// Steps recorded so far of all (from the worker, queued to this thread).
    void progress(int done, int total);
    /// A motion is in (recording() is it).
    void loaded();
    /// A load failed (`why` names the file) or was cancelled (`cancelled`); the old motion stays.
    void failed(const QString& why, bool cancelled);
    /// The motion was forgotten.
    void cleared();

private:
    struct Job {
        std::shared_ptr<const MotionRecording> recording;
        QString error;
        bool cancelled = false;
    };
    QFutureWatcher<Job> watcher_;
    std::shared_ptr<std::atomic<bool>> cancel_;
    std::shared_ptr<const MotionRecording> recording_;
    QString scene_path_, pending_path_;
    int steps_ = 0, pending_steps_ = 0;
};

} // namespace spt::editor
