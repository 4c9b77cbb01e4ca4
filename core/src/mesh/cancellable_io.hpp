#pragma once
// Files assimp reads through a stream that stops delivering bytes once a cancel flag is set:
// assimp has no way to abort a reading loader, but every loader must stop at the end of a
// truncated file, so a cancelled import ends within one buffered read. One file can be
// served from memory instead of the disk (a far-away mesh's positions made relative:
// mesh/recentre.hpp).
#include <assimp/DefaultIOSystem.h>
#include <atomic>
#include <filesystem>
#include <string>

namespace spt::detail {

/// The default file system whose streams read nothing more once `*cancel` is set.
class CancellableIOSystem : public Assimp::DefaultIOSystem {
public:
    /// `cancel` must outlive every stream opened through this system.
    explicit CancellableIOSystem(const std::atomic<bool>& cancel) : cancel_(&cancel) {}
    /// As above; a null `cancel` never stops.
    explicit CancellableIOSystem(const std::atomic<bool>* cancel) : cancel_(cancel) {}
    /// From now on, opening the file at `path` reads `bytes` instead of the file's own.
    void serve(const std::string& path, std::string bytes);
    /// Opens `file` as the default system does, wrapped so that reads stop once cancelled.
    Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;
    /// Closes a stream this system opened.
    void Close(Assimp::IOStream* stream) override;

private:
    const std::atomic<bool>* cancel_;
    std::filesystem::path served_path_;
    std::string served_;
};

} // namespace spt::detail
