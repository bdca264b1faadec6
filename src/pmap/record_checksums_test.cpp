#include "pmap/record_checksums.h"

#include <gtest/gtest.h>

#include <cstring>

#include "util/error.h"

namespace rp::pmap {
namespace {

// zlib's CRC-32 is the standard one: its check value for "123456789" is 0xCBF43926.
TEST(RecordChecksums, StandardCrc32) {
    const char* s = "123456789";
    EXPECT_EQ(recordsChecksum(reinterpret_cast<const unsigned char*>(s), std::strlen(s)),
              0xCBF43926u);
    EXPECT_EQ(checksumBlocks(0, 4096), 0u);
    EXPECT_EQ(checksumBlocks(4096, 4096), 1u);
    EXPECT_EQ(checksumBlocks(4097, 4096), 2u);
}

TEST(RecordChecksums, TrailerRoundTripAndMismatch) {
    RecordChecksums a;
    a.block = 10;
    a.crc = {0xCBF43926u, 1u, 0xffffffffu};
    const std::string bytes = a.encode();
    ASSERT_EQ(bytes.size(), 12u);
    EXPECT_EQ(static_cast<unsigned char>(bytes[0]), 0xCBu);  // most significant first
    RecordChecksums b;
    b.block = 10;
    b.decode(reinterpret_cast<const unsigned char*>(bytes.data()), 3);
    EXPECT_EQ(b.crc, a.crc);
    EXPECT_NO_THROW(b.check("m.pm", 1, 1u, 25));
    try {
        b.check("m.pm", 2, 7u, 25);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "m.pm: damaged photon map: photons 20 to 24 do not match their checksum");
    }
}

}  // namespace
}  // namespace rp::pmap
