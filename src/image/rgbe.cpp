// RGBE/XYZE pixel packing and the picture scanline codecs (see rgbe.h).
#include "image/rgbe.h"

#include <algorithm>
#include <cmath>

namespace rp {

namespace {

constexpr int kMinRun = 4;    // MINRUN in color.c: shorter runs stay literal
constexpr int kMaxRun = 127;  // a run count byte is 128 + length

// The next byte, or -1 at the end of the stream.
inline int nextByte(std::streambuf& in) {
    auto c = in.sbumpc();
    return c == std::streambuf::traits_type::eof() ? -1 : static_cast<int>(c);
}

// Old-style (pre-1991) scanline: flat 4-byte pixels, where a pixel 1,1,1,n repeats the
// previous pixel n times; consecutive run pixels extend the count by 8 more bits each
// (RADIANCE's oldreadcolrs). scan[0..start) is already filled.
std::string decodeOld(std::streambuf& in, Colr* scan, int start, int len) {
    int shift = 0;
    int i = start;
    while (i < len) {
        Colr c;
        for (int k = 0; k < 4; ++k) {
            int b = nextByte(in);
            if (b < 0) return "truncated scanline";
            c[k] = static_cast<uint8_t>(b);
        }
        if (c[0] == 1 && c[1] == 1 && c[2] == 1) {
            // A run with no previous pixel refers to memory before the buffer in
            // RADIANCE; here it is corrupt data.
            if (i == 0 || shift > 16) return "bad run length";
            long count = static_cast<long>(c[3]) << shift;
            if (count > len - i) return "bad run length";
            for (long n = 0; n < count; ++n, ++i) scan[i] = scan[i - 1];
            shift += 8;
        } else {
            scan[i++] = c;
            shift = 0;
        }
    }
    return {};
}

}  // namespace

void encodeScanline(const Colr* scan, int len, std::string& out) {
    if (len < kMinRleLength || len > kMaxRleLength) {
        for (int i = 0; i < len; ++i) out.append(reinterpret_cast<const char*>(scan[i].data()), 4);
        return;
    }
    out.push_back(2);
    out.push_back(2);
    out.push_back(static_cast<char>(len >> 8));
    out.push_back(static_cast<char>(len & 255));
    for (int k = 0; k < 4; ++k) {
        auto v = [scan, k](int i) { return scan[i][k]; };
        int j = 0;
        while (j < len) {
            // Find the next run long enough to be worth a run code.
            int beg = j, cnt = 0;
            bool haveRun = false;
            while (beg < len) {
                cnt = 1;
                while (cnt < kMaxRun && beg + cnt < len && v(beg + cnt) == v(beg)) ++cnt;
                if (cnt >= kMinRun) {
                    haveRun = true;
                    break;
                }
                beg += cnt;
            }
            // A short stretch of 2..3 equal bytes before the run: one run code is
            // smaller than a literal code (RADIANCE does the same).
            int gap = beg - j;
            if (gap > 1 && gap < kMinRun &&
                std::all_of(scan + j, scan + beg, [&](const Colr& c) { return c[k] == v(j); })) {
                out.push_back(static_cast<char>(128 + gap));
                out.push_back(static_cast<char>(v(j)));
                j = beg;
            }
            while (j < beg) {
                int n = std::min(128, beg - j);
                out.push_back(static_cast<char>(n));
                for (int i = 0; i < n; ++i) out.push_back(static_cast<char>(v(j + i)));
                j += n;
            }
            if (haveRun) {
                out.push_back(static_cast<char>(128 + cnt));
                out.push_back(static_cast<char>(v(beg)));
                j = beg + cnt;
            }
        }
    }
}

std::string decodeScanline(std::streambuf& in, Colr* scan, int len) {
    if (len <= 0) return {};
    if (len < kMinRleLength || len > kMaxRleLength) return decodeOld(in, scan, 0, len);
    Colr first;
    for (int k = 0; k < 4; ++k) {
        int b = nextByte(in);
        if (b < 0) return "truncated scanline";
        first[k] = static_cast<uint8_t>(b);
    }
    // New-style scanlines start 2,2,hi,lo with hi < 128; anything else is the first
    // pixel of an old-style or flat scanline. No pixel from toColr looks like the marker:
    // its largest mantissa is always >= 128.
    if (first[0] != 2 || first[1] != 2 || (first[2] & 128)) {
        scan[0] = first;
        return decodeOld(in, scan, 1, len);
    }
    if (((first[2] << 8) | first[3]) != len) return "scanline length mismatch";
    for (int k = 0; k < 4; ++k) {
        int j = 0;
        while (j < len) {
            int code = nextByte(in);
            if (code < 0) return "truncated scanline";
            if (code > 128) {
                code &= 127;
                int val = nextByte(in);
                if (val < 0) return "truncated scanline";
                if (code > len - j) return "bad run length";
                for (int n = 0; n < code; ++n) scan[j++][k] = static_cast<uint8_t>(val);
            } else {
                if (code > len - j) return "bad run length";
                for (int n = 0; n < code; ++n) {
                    int b = nextByte(in);
                    if (b < 0) return "truncated scanline";
                    scan[j++][k] = static_cast<uint8_t>(b);
                }
            }
        }
    }
    return {};
}

}  // namespace rp
