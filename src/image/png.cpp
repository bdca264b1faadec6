// PNG encoding with stored deflate blocks (see png.h; PNG spec, ISO/IEC 15948, and
// RFC 1950/1951 for the zlib and deflate framing).
#include "image/png.h"

#include <array>
#include <cmath>

#include "util/error.h"

namespace rp {

namespace {

constexpr std::array<uint32_t, 256> makeCrcTable() {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
        uint32_t c = n;
        for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
        t[n] = c;
    }
    return t;
}
constexpr std::array<uint32_t, 256> kCrcTable = makeCrcTable();

void put32(std::string& s, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) s.push_back(static_cast<char>((v >> shift) & 255));
}

void chunk(std::string& png, const char* type, const std::string& data) {
    put32(png, static_cast<uint32_t>(data.size()));
    std::string body = std::string(type, 4) + data;
    png += body;
    put32(png, pngCrc32(reinterpret_cast<const uint8_t*>(body.data()), body.size()));
}

// zlib stream (RFC 1950) holding deflate stored blocks (RFC 1951 section 3.2.4) of at
// most 65535 bytes each.
std::string deflateStored(const std::string& raw) {
    std::string z;
    z.push_back(0x78);  // CM=8 (deflate), 32K window
    z.push_back(0x01);  // no dictionary, fastest; (0x78 * 256 + 0x01) % 31 == 0
    size_t pos = 0;
    do {
        size_t n = std::min<size_t>(65535, raw.size() - pos);
        bool last = pos + n == raw.size();
        z.push_back(last ? 1 : 0);  // BFINAL, BTYPE=00
        z.push_back(static_cast<char>(n & 255));
        z.push_back(static_cast<char>(n >> 8));
        z.push_back(static_cast<char>(~n & 255));
        z.push_back(static_cast<char>((~n >> 8) & 255));
        z.append(raw, pos, n);
        pos += n;
    } while (pos < raw.size());
    put32(z, adler32(reinterpret_cast<const uint8_t*>(raw.data()), raw.size()));
    return z;
}

}  // namespace

uint32_t pngCrc32(const uint8_t* data, size_t len, uint32_t crc) {
    uint32_t c = crc ^ 0xffffffffu;
    for (size_t i = 0; i < len; ++i) c = kCrcTable[(c ^ data[i]) & 255] ^ (c >> 8);
    return c ^ 0xffffffffu;
}

uint32_t adler32(const uint8_t* data, size_t len) {
    uint32_t a = 1, b = 0;
    for (size_t i = 0; i < len; ++i) {
        a = (a + data[i]) % 65521;
        b = (b + a) % 65521;
    }
    return (b << 16) | a;
}

std::string encodePng(int width, int height, const std::vector<uint8_t>& rgb,
                      std::optional<double> gamma) {
    RP_CHECK(width > 0 && height > 0);
    RP_CHECK(rgb.size() == static_cast<size_t>(width) * height * 3);
    std::string png("\x89PNG\r\n\x1a\n", 8);
    std::string ihdr;
    put32(ihdr, static_cast<uint32_t>(width));
    put32(ihdr, static_cast<uint32_t>(height));
    ihdr += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bit, truecolour, deflate, no interlace
    chunk(png, "IHDR", ihdr);
    if (gamma) {
        std::string g;
        put32(g, static_cast<uint32_t>(std::lround(100000.0 / *gamma)));
        chunk(png, "gAMA", g);
    } else {
        chunk(png, "sRGB", std::string(1, '\0'));  // perceptual rendering intent
    }
    // Each row starts with filter type 0 (none): filters only help a real compressor.
    std::string raw;
    raw.reserve(static_cast<size_t>(height) * (1 + 3 * static_cast<size_t>(width)));
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);
        raw.append(reinterpret_cast<const char*>(rgb.data()) + static_cast<size_t>(y) * width * 3,
                   static_cast<size_t>(width) * 3);
    }
    // The zlib stream may be split over any number of IDAT chunks; 1 MiB chunks keep
    // every chunk far below the 2^31 length limit.
    std::string z = deflateStored(raw);
    for (size_t pos = 0; pos < z.size(); pos += 1 << 20) chunk(png, "IDAT", z.substr(pos, 1 << 20));
    chunk(png, "IEND", std::string());
    return png;
}

}  // namespace rp
