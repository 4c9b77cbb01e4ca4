#pragma once
// Shared by the fuzz targets: reading typed values from the fuzzer's bytes, and the one
// rule every target checks (bad input is Error(BadInput); nothing else escapes).
#include "spt/error.hpp"
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <cstdio>

namespace spt::fuzz {

/// Consumes the fuzzer's bytes front to back; past the end every read gives zero bytes.
struct Bytes {
    const uint8_t* data;
    size_t size;
    size_t at = 0;
    /// The next sizeof(T) bytes as a T (zero-padded past the end).
    template <class T> T take() {
        T v{};
        uint8_t raw[sizeof(T)] = {};
        for (size_t k = 0; k < sizeof(T) && at < size; ++k) raw[k] = data[at++];
        std::memcpy(&v, raw, sizeof(T));
        return v;
    }
    bool empty() const { return at >= size; }
    size_t left() const { return size - at; }
};

/// Stops the run as a crash (the fuzzer and the replay test both report it) with a reason.
[[noreturn]] inline void fail(const char* why) {
    std::fprintf(stderr, "fuzz target invariant broken: %s\n", why);
    std::abort();
}

/// Runs f; Error(BadInput) is the documented refusal, anything else is a finding.
template <class F> void expect_bad_input_only(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        if (e.kind() != ErrorKind::BadInput) fail(e.what());
    }
}

} // namespace spt::fuzz
