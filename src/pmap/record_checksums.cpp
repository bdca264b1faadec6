// Per-block checksums of photon records (record_checksums.h), with zlib's CRC-32.
#include "pmap/record_checksums.h"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>

#include "util/error.h"

namespace rp::pmap {

uint32_t recordsChecksum(const unsigned char* bytes, size_t size) {
    return extendChecksum(static_cast<uint32_t>(crc32(0L, Z_NULL, 0)), bytes, size);
}

uint32_t extendChecksum(uint32_t crc, const unsigned char* bytes, size_t size) {
    uLong c = crc;
    // zlib takes uInt lengths: at most 4 GiB at a time.
    constexpr size_t kStep = size_t(1) << 30;
    for (size_t at = 0; at < size; at += kStep)
        c = crc32(c, bytes + at, static_cast<uInt>(std::min(kStep, size - at)));
    return static_cast<uint32_t>(c);
}

std::string RecordChecksums::encode() const {
    std::string b;
    b.reserve(crc.size() * 4);
    for (uint32_t c : crc)
        for (int s = 24; s >= 0; s -= 8) b += static_cast<char>((c >> s) & 0xff);
    return b;
}

void RecordChecksums::decode(const unsigned char* bytes, size_t blocks) {
    crc.resize(blocks);
    for (size_t i = 0; i < blocks; ++i) {
        const unsigned char* p = bytes + 4 * i;
        crc[i] = uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
    }
}

void RecordChecksums::check(const std::string& what, uint64_t b, uint32_t computed,
                            uint64_t numPhotons) const {
    RP_CHECK(b < crc.size());
    if (computed == crc[b]) return;
    throw InputError(SourceLoc{what, 0},
                     fmt::format("damaged photon map: photons {} to {} do not match their "
                                 "checksum",
                                 b * block, std::min<uint64_t>((b + 1) * block, numPhotons) - 1));
}

}  // namespace rp::pmap
