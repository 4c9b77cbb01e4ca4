#pragma once
// Files assimp reads through a stream that stops delivering bytes once a cancel flag is set:
// assimp has no way to abort a reading loader, but every loader must stop at the end of a
// truncated file, so a cancelled import ends within one buffered read.
#include <assimp/DefaultIOSystem.h>
#include <atomic>

namespace spt::detail {

/// The default file system whose streams read nothing more once `*cancel` is set.
class CancellableIOSystem : public Assimp::DefaultIOSystem {
public:
    /// `cancel` must outlive every stream opened through this system.
    explicit CancellableIOSystem(const std::atomic<bool>& cancel) : cancel_(cancel) {}
    /// Opens `file` as the default system does, wrapped so that reads stop once cancelled.
    Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;
    /// Closes a stream this system opened.
    void Close(Assimp::IOStream* stream) override;

private:
    const std::atomic<bool>& cancel_;
};

} // namespace spt::detail
