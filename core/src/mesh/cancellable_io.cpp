// CancellableIOSystem: a stream that delegates to assimp's default one until cancelled.
#include "mesh/cancellable_io.hpp"
#include <assimp/IOStream.hpp>
#include <memory>

namespace spt::detail {
namespace {

class CancellableStream : public Assimp::IOStream {
public:
    CancellableStream(Assimp::IOStream* inner, const std::atomic<bool>& cancel) : inner_(inner), cancel_(cancel) {}
    size_t Read(void* buffer, size_t size, size_t count) override {
        // Nothing more once cancelled: to the loader, the file ends here.
        if (cancel_.load(std::memory_order_relaxed)) return 0;
        return inner_->Read(buffer, size, count);
    }
    size_t Write(const void* buffer, size_t size, size_t count) override { return inner_->Write(buffer, size, count); }
    aiReturn Seek(size_t offset, aiOrigin origin) override { return inner_->Seek(offset, origin); }
    size_t Tell() const override { return inner_->Tell(); }
    size_t FileSize() const override { return inner_->FileSize(); }
    void Flush() override { inner_->Flush(); }

private:
    std::unique_ptr<Assimp::IOStream> inner_;
    const std::atomic<bool>& cancel_;
};

} // namespace

Assimp::IOStream* CancellableIOSystem::Open(const char* file, const char* mode) {
    Assimp::IOStream* inner = DefaultIOSystem::Open(file, mode);
    return inner ? new CancellableStream(inner, cancel_) : nullptr;
}

void CancellableIOSystem::Close(Assimp::IOStream* stream) { delete stream; }

} // namespace spt::detail
