#pragma once
// Opening a file for the editor, run off the UI thread: a .spt file with its mesh (found
// beside it by the recorded name, or given), or a mesh converted with default options
// whose one tree is the unsplit root, where manual authoring starts. A mesh whose file has
// animation clips comes with them (the timeline).
#include "spt/animation.hpp"
#include "spt/spt_file.hpp"
#include <QString>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace spt::editor {

/// What opening a file gave: a document, maybe its mesh, and what went wrong.
struct LoadResult {
    QString path;                       ///< the file asked for
    std::optional<SptDocument> doc;     ///< empty when the file could not be opened
    std::optional<TriangleMesh> mesh;   ///< the document's mesh, when found and matching
    std::shared_ptr<const AnimatedMesh> animated; ///< that mesh with its clips, when its file has some
    QString mesh_path;                  ///< where the mesh was read from (empty if not used)
    bool converted = false;             ///< the file was a mesh, converted to a new document
    bool cancelled = false;             ///< the opening was stopped by the cancel flag
    bool stopped_importing = false;     ///< it stopped while the mesh was being read (else converted)
    QString error;                      ///< why the file could not be opened (names the file)
    QString warning;                    ///< a problem that still leaves a document (mesh missing or mismatched)
};

/// True if `path` starts with the .spt magic.
bool is_spt_file(const QString& path);

/// Opens `path`; `mesh_path` (may be empty) overrides where a .spt file's mesh is looked for.
/// Reading a mesh (a .spt file's too) and converting it stop when `cancel` (may be null) is
/// set (`cancelled`, and `error` says so); the conversion names its stages to `on_stage` (may
/// be empty). Never throws: problems come back in `error` and `warning`.
LoadResult load_document(const QString& path, const QString& mesh_path, const std::atomic<bool>* cancel = nullptr,
                         const std::function<void(const std::string&)>& on_stage = {});

} // namespace spt::editor
