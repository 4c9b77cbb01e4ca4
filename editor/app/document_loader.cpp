// load_document: .spt with its mesh checked against the recorded identity, or mesh conversion.
#include "document_loader.hpp"
#include "edit_commands.hpp"
#include "spt/convert.hpp"
#include "spt/error.hpp"
#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace spt::editor {

bool is_spt_file(const QString& path) { return spt::is_spt_file(QFile::encodeName(path).toStdString()); }

namespace {

// A mesh file read, with its clips when it has some.
struct ReadMesh {
    TriangleMesh mesh;
    std::shared_ptr<const AnimatedMesh> animated; // null without clips
    QString warning;                              // the clips could not be read
};

ReadMesh read_mesh(const QString& path, const ImportOptions& reading) {
    ReadMesh r;
    // Formats without skins or clips are read once, as before the timeline (reading a file's
    // animation reads it a second time).
    if (may_hold_animation(path.toStdString())) {
        try {
            auto animated = std::make_shared<AnimatedMesh>(import_animated_mesh(path.toStdString(), reading));
            r.mesh = animated->imported.mesh;
            if (!animated->clips.empty()) r.animated = std::move(animated);
            return r;
        } catch (const Cancelled&) {
            throw;
        } catch (const Error& e) {
            // Refused weights or keys: the mesh alone opens as it did before (import_mesh below
            // throws again if the mesh itself is the problem).
            r.warning = QString("%1; the mesh opens without its animation").arg(QString::fromStdString(e.what()));
        }
    }
    r.mesh = import_mesh(path.toStdString(), reading).mesh;
    return r;
}

} // namespace

LoadResult load_document(const QString& path, const QString& mesh_path, const std::atomic<bool>* cancel,
                         const std::function<void(const std::string&)>& on_stage) {
    LoadResult r;
    r.path = path;
    bool converting = false; // the mesh is read: a cancel now stops the conversion
    try {
        if (!QFileInfo(path).isFile()) throw_bad_input(path.toStdString(), "no such file");
        if (!is_spt_file(path)) {
            ImportOptions reading;
            reading.cancel = cancel;
            ReadMesh read = read_mesh(path, reading);
            ConvertOptions options;
            options.cancel = cancel;
            options.on_stage = on_stage;
            converting = true;
            r.doc = make_document(read.mesh, options);
            // Authoring starts where the paper's tool does: the root holds every sample (B builds
            // the automatic tree under any node).
            const std::string name = r.doc->trees.front().name();
            r.doc->trees = {unsplit_tree(name, r.doc->samples)};
            r.mesh = std::move(read.mesh);
            r.animated = std::move(read.animated);
            r.warning = read.warning;
            r.mesh_path = path;
            r.converted = true;
            return r;
        }
        r.doc = load_spt(path.toStdString());
        const QString name = QString::fromStdString(r.doc->mesh.name);
        const QString candidate = mesh_path.isEmpty() ? QFileInfo(path).dir().filePath(name) : mesh_path;
        if (!QFileInfo(candidate).isFile()) {
            r.warning = QString("%1: its mesh %2 was not found%3; showing the sampling spheres only")
                            .arg(path, candidate, mesh_path.isEmpty() ? " beside it (give it with --mesh)" : "");
            return r;
        }
        try {
            ImportOptions reading;
            reading.cancel = cancel;
            ReadMesh read = read_mesh(candidate, reading);
            const std::string mismatch = check_mesh_matches(r.doc->mesh, read.mesh);
            if (!mismatch.empty()) {
                r.warning = QString("%1 is not the mesh %2 was made from (%3); showing the sampling spheres only")
                                .arg(candidate, path, QString::fromStdString(mismatch));
                return r;
            }
            r.mesh = std::move(read.mesh);
            r.animated = std::move(read.animated);
            r.warning = read.warning;
            r.mesh_path = candidate;
        } catch (const Cancelled&) {
            throw; // the whole opening stops, not only the mesh
        } catch (const std::exception& e) {
            r.warning = QString("%1; showing the sampling spheres only").arg(QString::fromStdString(e.what()));
        }
    } catch (const Cancelled&) {
        r.doc.reset();
        r.cancelled = true;
        r.stopped_importing = !converting;
        r.error = QString("%1: opening cancelled").arg(path);
    } catch (const Error& e) {
        r.doc.reset();
        r.error = QString::fromStdString(e.what());
    } catch (const std::exception& e) {
        r.doc.reset();
        r.error = QString("%1: %2").arg(path, QString::fromStdString(e.what()));
    }
    return r;
}

} // namespace spt::editor
