#pragma once
// Helpers shared by the test binaries: temporary directories and real meshes.
#include "spt/convert.hpp"
#include "sampling/surface_samples.hpp"
#include <atomic>
#include <filesystem>
#include <unistd.h>
#include <random>
#include <string>
#include <thread>

namespace spt::test {

/// A fresh directory under the build tree, removed on destruction.
class TempDir {
public:
    explicit TempDir(const std::string& tag) {
        static int counter = 0;
        path_ = std::filesystem::path(SPT_BINARY_DIR) / "test-tmp" /
                (tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() { std::filesystem::remove_all(path_); }
    /// Path of `name` inside the directory.
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

/// Sets a cancel flag from another thread as soon as start() is called, as an editor's Cancel
/// button would while the calling thread runs long work (the flag is set within microseconds).
class CancelFromAnotherThread {
public:
    explicit CancelFromAnotherThread(std::atomic<bool>& flag)
        : thread_([this, &flag] {
              while (!started_.load()) std::this_thread::yield();
              flag = true;
          }) {}
    ~CancelFromAnotherThread() {
        start();
        thread_.join();
    }
    CancelFromAnotherThread(const CancelFromAnotherThread&) = delete;
    CancelFromAnotherThread& operator=(const CancelFromAnotherThread&) = delete;
    /// The work starts now: the flag is set at once.
    void start() { started_ = true; }

private:
    std::atomic<bool> started_{false};
    std::thread thread_;
};

/// Directory of Debian's assimp-testmodels.
inline std::string assimp_models() { return "/usr/share/assimp/models"; }

/// Directory of the project's bundled meshes.
inline std::string project_meshes() { return std::string(SPT_SOURCE_DIR) + "/resources/meshes"; }

/// Vertex samples with the default protrusion allowance, as make_document takes them.
inline SampleSet vertex_samples(const TriangleMesh& mesh) {
    const RadiusLimiter limiter(mesh, kDefaultProtrusion * mesh.diagonal());
    return sample_vertices(mesh, limiter);
}

} // namespace spt::test
