// Optional integrity of radphoton's own photon map files: a CRC-32 (zlib's) of every
// block of kChecksumBlock photon records, so that a flipped bit in a record is found by
// whatever reads that block, in core or out of core. The header announces them with a
// line "RP_CRC32=<records per block>"; the checksums follow the last record, 4 bytes
// each, most significant first. RADIANCE's loader skips header lines it does not know
// and reads only the records, so it reads these maps as any other (checked with RADIANCE
// 5.4's rtrace: the same output with and without them). Maps without the line are read
// as before.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rp::pmap {

constexpr uint32_t kChecksumBlock = 4096;  // records per checksum
inline constexpr const char* kChecksumKey = "RP_CRC32";

// Blocks of `block` records in n records (the last may be short).
inline uint64_t checksumBlocks(uint64_t n, uint32_t block) {
    return block ? (n + block - 1) / block : 0;
}

// The CRC-32 of `bytes` raw record bytes.
uint32_t recordsChecksum(const unsigned char* bytes, size_t size);
// The CRC-32 of the bytes that gave `crc` followed by these (`crc` 0: none before), for
// data checked in several pieces (the in-core store's index).
uint32_t extendChecksum(uint32_t crc, const unsigned char* bytes, size_t size);

// The checksums of a map, as read from its file.
struct RecordChecksums {
    uint32_t block = 0;  // records per checksum; 0: the map has none
    std::vector<uint32_t> crc;

    // The trailer's bytes for these checksums, and the checksums from them.
    std::string encode() const;
    void decode(const unsigned char* bytes, size_t blocks);
    // Throws InputError naming `what` and the photons of block b (of a map of
    // `numPhotons`) when `computed`, its records' checksum, is not the stored one.
    void check(const std::string& what, uint64_t b, uint32_t computed, uint64_t numPhotons) const;
};

}  // namespace rp::pmap
