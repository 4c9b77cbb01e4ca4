#pragma once
// Recovery files: unsaved work written every few seconds beside a note of where it belongs,
// named by the writing process, so the next start can offer what a crashed or killed
// editor left behind.
#include <QDateTime>
#include <QString>
#include <cstdint>
#include <vector>

namespace spt::editor {

/// A recovery file left by an editor process that is no longer running.
struct RecoveryEntry {
    QString spt_path;   ///< the recovered document (.spt bytes)
    QString note_path;  ///< its note (JSON)
    QString save_path;  ///< where the document was to be saved (may be empty)
    QString mesh_path;  ///< the mesh it was shown with (may be empty)
    QString source;     ///< the file that was opened
    QDateTime written;  ///< when the recovery file was written
};

/// This process's recovery file in a directory.
class Recovery {
public:
    /// Recovery files go to `dir` (default: the application data location's "recovery").
    explicit Recovery(QString dir = {});
    /// The directory used.
    const QString& dir() const { return dir_; }
    /// Writes `bytes` and the note atomically; false with `error` set if it could not.
    bool write(const std::vector<uint8_t>& bytes, const QString& save_path, const QString& mesh_path,
               const QString& source, QString* error = nullptr);
    /// Removes this process's files (after a save, or on a clean exit).
    void clear();
    /// Recovery files whose process has ended, newest first.
    std::vector<RecoveryEntry> orphans() const;
    /// Removes an orphan's files (recovered or declined).
    static void discard(const RecoveryEntry& entry);

private:
    QString dir_;
    QString stem_; // this process's file stem
};

} // namespace spt::editor
