#pragma once
// A test's edit of .spt bytes made to look intact again: the length field and both CRC-32s
// written for the edited bytes (docs/spt-format.md), so that what refuses the edit is the
// structural checks behind them, not the checksums.
#include <zlib.h>
#include <cstdint>
#include <cstring>
#include <vector>

namespace spt::test {

/// Sets the header's length to b.size() and both checksums to those of `b`.
inline void reseal(std::vector<uint8_t>& b) {
    const uint64_t length = b.size();
    std::memcpy(b.data() + 16, &length, 8);
    const uint32_t body = uint32_t(crc32(0, b.data() + 32, uInt(b.size() - 32)));
    std::memcpy(b.data() + 24, &body, 4);
    const uint32_t head = uint32_t(crc32(0, b.data(), 28));
    std::memcpy(b.data() + 28, &head, 4);
}

} // namespace spt::test
