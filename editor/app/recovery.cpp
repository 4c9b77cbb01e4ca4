// Recovery: per-process recovery files and notes, and finding the ones a dead process left.
#include "recovery.hpp"
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QStandardPaths>
#include <algorithm>
#include <csignal>
#include <cerrno>
#include <unistd.h>

namespace spt::editor {
namespace {

bool process_alive(qint64 pid) { return pid > 0 && (::kill(pid_t(pid), 0) == 0 || errno == EPERM); }

bool write_atomically(const QString& path, const QByteArray& bytes, QString* error) {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size() || !f.commit()) {
        if (error) *error = QString("%1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

} // namespace

Recovery::Recovery(QString dir) : dir_(std::move(dir)) {
    if (dir_.isEmpty()) dir_ = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/recovery";
    stem_ = QString("editor-%1").arg(QCoreApplication::applicationPid());
}

bool Recovery::write(const std::vector<uint8_t>& bytes, const QString& save_path, const QString& mesh_path,
                     const QString& source, QString* error) {
    if (!QDir().mkpath(dir_)) {
        if (error) *error = dir_ + ": cannot create the recovery folder";
        return false;
    }
    QJsonObject note;
    note["pid"] = QCoreApplication::applicationPid();
    note["save_path"] = save_path;
    note["mesh_path"] = mesh_path;
    note["source"] = source;
    note["written"] = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
    // The document first: a note always points at a complete document.
    return write_atomically(dir_ + "/" + stem_ + ".spt",
                            QByteArray(reinterpret_cast<const char*>(bytes.data()), qsizetype(bytes.size())), error) &&
           write_atomically(dir_ + "/" + stem_ + ".json", QJsonDocument(note).toJson(), error);
}

void Recovery::clear() {
    QFile::remove(dir_ + "/" + stem_ + ".json");
    QFile::remove(dir_ + "/" + stem_ + ".spt");
}

std::vector<RecoveryEntry> Recovery::orphans() const {
    std::vector<RecoveryEntry> out;
    const QDir dir(dir_);
    for (const QString& name : dir.entryList({"editor-*.json"}, QDir::Files)) {
        QFile f(dir.filePath(name));
        if (!f.open(QIODevice::ReadOnly)) continue;
        const QJsonObject note = QJsonDocument::fromJson(f.readAll()).object();
        const qint64 pid = note["pid"].toInteger();
        if (pid == QCoreApplication::applicationPid() || process_alive(pid)) continue;
        RecoveryEntry e;
        e.note_path = dir.filePath(name);
        e.spt_path = dir.filePath(name.chopped(5) + ".spt");
        e.save_path = note["save_path"].toString();
        e.mesh_path = note["mesh_path"].toString();
        e.source = note["source"].toString();
        e.written = QDateTime::fromString(note["written"].toString(), Qt::ISODate);
        if (QFile::exists(e.spt_path)) out.push_back(e);
    }
    std::sort(out.begin(), out.end(), [](const RecoveryEntry& a, const RecoveryEntry& b) { return a.written > b.written; });
    return out;
}

void Recovery::discard(const RecoveryEntry& entry) {
    QFile::remove(entry.note_path);
    QFile::remove(entry.spt_path);
}

} // namespace spt::editor
