// CancellableIOSystem: a stream that delegates to assimp's default one until cancelled.
#include "mesh/cancellable_io.hpp"
#include <assimp/IOStream.hpp>
#include <algorithm>
#include <cstring>
#include <memory>

namespace spt::detail {
namespace {

bool cancelled(const std::atomic<bool>* flag) { return flag && flag->load(std::memory_order_relaxed); }

class CancellableStream : public Assimp::IOStream {
public:
    CancellableStream(Assimp::IOStream* inner, const std::atomic<bool>* cancel) : inner_(inner), cancel_(cancel) {}
    size_t Read(void* buffer, size_t size, size_t count) override {
        // Nothing more once cancelled: to the loader, the file ends here.
        if (cancelled(cancel_)) return 0;
        return inner_->Read(buffer, size, count);
    }
    size_t Write(const void* buffer, size_t size, size_t count) override { return inner_->Write(buffer, size, count); }
    aiReturn Seek(size_t offset, aiOrigin origin) override { return inner_->Seek(offset, origin); }
    size_t Tell() const override { return inner_->Tell(); }
    size_t FileSize() const override { return inner_->FileSize(); }
    void Flush() override { inner_->Flush(); }

private:
    std::unique_ptr<Assimp::IOStream> inner_;
    const std::atomic<bool>* cancel_;
};

// Bytes held by the system, read as a file is (fread's contract: whole items only).
class MemoryStream : public Assimp::IOStream {
public:
    MemoryStream(const std::string& bytes, const std::atomic<bool>* cancel) : bytes_(bytes), cancel_(cancel) {}
    size_t Read(void* buffer, size_t size, size_t count) override {
        if (cancelled(cancel_) || size == 0) return 0;
        const size_t items = std::min(count, (bytes_.size() - pos_) / size);
        std::memcpy(buffer, bytes_.data() + pos_, items * size);
        pos_ += items * size;
        return items;
    }
    size_t Write(const void*, size_t, size_t) override { return 0; }
    aiReturn Seek(size_t offset, aiOrigin origin) override {
        size_t to = 0;
        switch (origin) {
        case aiOrigin_SET: to = offset; break;
        case aiOrigin_CUR: to = pos_ + offset; break;
        case aiOrigin_END: to = bytes_.size() - std::min(offset, bytes_.size()); break;
        default: return aiReturn_FAILURE;
        }
        if (to > bytes_.size()) return aiReturn_FAILURE;
        pos_ = to;
        return aiReturn_SUCCESS;
    }
    size_t Tell() const override { return pos_; }
    size_t FileSize() const override { return bytes_.size(); }
    void Flush() override {}

private:
    const std::string& bytes_;
    size_t pos_ = 0;
    const std::atomic<bool>* cancel_;
};

} // namespace

void CancellableIOSystem::serve(const std::string& path, std::string bytes) {
    served_path_ = path;
    served_ = std::move(bytes);
}

Assimp::IOStream* CancellableIOSystem::Open(const char* file, const char* mode) {
    std::error_code ec;
    if (!served_path_.empty() && file && std::strchr(mode ? mode : "r", 'w') == nullptr &&
        std::filesystem::equivalent(served_path_, file, ec))
        return new MemoryStream(served_, cancel_);
    Assimp::IOStream* inner = DefaultIOSystem::Open(file, mode);
    return inner ? new CancellableStream(inner, cancel_) : nullptr;
}

void CancellableIOSystem::Close(Assimp::IOStream* stream) { delete stream; }

} // namespace spt::detail
