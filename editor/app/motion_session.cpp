// MotionSession: record_motion on a worker thread; the scene file's object list for the menu.
#include "motion_session.hpp"
#include "spt/error.hpp"
#include "spt/scene.hpp"
#include <QFile>
#include <QFileInfo>
#include <QPointer>
#include <QThread>
#include <QtConcurrent/QtConcurrentRun>

namespace spt::editor {

SceneObjects read_scene_objects(const QString& path) {
    // Core's parser (no models loaded): the same checks and messages as the run the motion makes.
    SceneObjects out;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return out.error = path + ": cannot open the scene: " + file.errorString(), out;
    const QByteArray text = file.read(64 << 20);
    try {
        const Scene scene = parse_scene(text.toStdString(), path.toStdString(),
                                        QFileInfo(path).absolutePath().toStdString());
        for (const SceneObject& o : scene.objects) {
            out.names.push_back(QString::fromStdString(o.name));
            out.models.push_back(QFileInfo(QString::fromStdString(o.model_path)).fileName() + " " +
                                 QFileInfo(QString::fromStdString(o.mesh_path)).fileName());
        }
    } catch (const Error& e) {
        return out.error = QString::fromStdString(e.what()), out;
    }
    if (out.names.isEmpty()) out.error = path + ": the scene has no objects";
    return out;
}

int matching_object(const SceneObjects& objects, const QString& mesh_name, const QString& document_file) {
    const QString mesh = QFileInfo(mesh_name).fileName(), file = QFileInfo(document_file).fileName();
    for (int i = 0; i < objects.models.size(); ++i) {
        const QStringList files = objects.models[i].split(' ', Qt::SkipEmptyParts);
        if ((!mesh.isEmpty() && files.contains(mesh)) || (!file.isEmpty() && files.contains(file))) return i;
    }
    return -1;
}

MotionSession::MotionSession(QObject* parent) : QObject(parent) {
    connect(&watcher_, &QFutureWatcher<Job>::finished, this, [this] {
        Job job = watcher_.result();
        const bool dropped = cancel_ && *cancel_;
        cancel_.reset();
        if (job.cancelled || dropped) return emit failed(pending_path_ + ": loading the motion was cancelled", true);
        if (!job.error.isEmpty()) return emit failed(job.error, false);
        recording_ = std::move(job.recording);
        scene_path_ = pending_path_;
        steps_ = pending_steps_;
        emit loaded();
    });
}

MotionSession::~MotionSession() {
    if (cancel_) *cancel_ = true;
    watcher_.waitForFinished();
}

bool MotionSession::load(const QString& scene_path, const QString& object, int steps, MotionModel model) {
    if (loading()) return false;
    pending_path_ = scene_path;
    pending_steps_ = steps;
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    emit started();
    QPointer<MotionSession> self(this);
    watcher_.setFuture(QtConcurrent::run([self, path = scene_path.toStdString(), object = object.toStdString(), steps,
                                          model = std::move(model), flag = cancel_]() {
        Job job;
        try {
            MotionOptions options;
            options.steps = steps;
            options.threads = std::max(1, QThread::idealThreadCount());
            options.cancel = flag.get();
            options.progress = [self](int done, int total) {
                QMetaObject::invokeMethod(self, [self, done, total] {
                    if (self) emit self->progress(done, total);
                });
            };
            const Scene scene = load_scene(path, flag.get());
            job.recording = std::make_shared<const MotionRecording>(record_motion(scene, object, model, options));
        } catch (const Cancelled&) {
            job.cancelled = true;
        } catch (const std::exception& e) {
            // Core's messages name the scene file where they can; the others get it in front.
            QString why = QString::fromStdString(e.what());
            const QString file = QString::fromStdString(path);
            job.error = why.contains(file) || why.contains(QFileInfo(file).fileName()) ? why : file + ": " + why;
        }
        return job;
    }));
    return true;
}

void MotionSession::cancel() {
    if (cancel_) *cancel_ = true;
}

void MotionSession::clear() {
    cancel();
    const bool had = recording_ != nullptr;
    recording_.reset();
    scene_path_.clear();
    steps_ = 0;
    if (had) emit cleared();
}

QString MotionSession::label() const {
    if (!recording_) return {};
    return QFileInfo(scene_path_).fileName() + " / " + QString::fromStdString(recording_->object);
}

} // namespace spt::editor
