#pragma once
// Little-endian writing and bounds-checked reading of the .spt byte stream.
#include "spt/error.hpp"
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace spt::detail {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the .spt codec assumes a little-endian host");

class Writer {
public:
    template <class T> void put(const T& v) { put_bytes(&v, sizeof(T)); }
    void put_string(const std::string& s) {
        put(uint32_t(s.size()));
        put_bytes(s.data(), s.size());
    }
    void put_bytes(const void* p, size_t n) {
        // A size of its own over storage grown in doubling steps: a 1M-sample file is 10M
        // puts, and a vector's range insert each was a tenth of saving it.
        if (buf_.size() - size_ < n) buf_.resize(std::max(2 * buf_.size(), size_ + n));
        if (n) std::memcpy(buf_.data() + size_, p, n);
        size_ += n;
    }
    /// Room for `n` bytes in all, so that writing that much copies nothing.
    void reserve(size_t n) {
        if (n > buf_.size()) buf_.resize(n);
    }
    /// The bytes written; the writer is empty afterwards.
    std::vector<uint8_t> take() {
        buf_.resize(size_);
        size_ = 0;
        return std::move(buf_);
    }

private:
    std::vector<uint8_t> buf_;
    size_t size_ = 0;
};

/// Reads from a byte buffer; every read is checked against what remains, and
/// failures name the byte offset where the problem is.
class Reader {
public:
    Reader(const std::vector<uint8_t>& bytes, std::string path) : bytes_(bytes), path_(std::move(path)) {}
    size_t offset() const { return pos_; }
    size_t remaining() const { return bytes_.size() - pos_; }
    [[noreturn]] void fail(size_t at, const std::string& what) const {
        throw_bad_input(path_, "byte " + std::to_string(at) + ": " + what);
    }
    void need(uint64_t n, const std::string& what) const {
        if (n > remaining())
            fail(pos_, "truncated: " + what + " needs " + std::to_string(n) + " bytes but " + std::to_string(remaining()) +
                           " remain");
    }
    template <class T> T get(const char* what) {
        need(sizeof(T), what);
        T v;
        std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return v;
    }
    std::string get_string(const char* what, uint32_t max_len) {
        const size_t at = pos_;
        const auto len = get<uint32_t>(what);
        if (len > max_len) fail(at, std::string(what) + " is " + std::to_string(len) + " bytes; at most " + std::to_string(max_len));
        need(len, what);
        std::string s(reinterpret_cast<const char*>(bytes_.data() + pos_), len);
        pos_ += len;
        return s;
    }

private:
    const std::vector<uint8_t>& bytes_;
    std::string path_;
    size_t pos_ = 0;
};

} // namespace spt::detail
