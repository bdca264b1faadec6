// The in-core store's index file (pmap/incore_store_index.cpp, kept beside photon maps):
// a valid index of a small store whose body the input damages (bytes XORed in at chosen
// places) and whose CRC-32 is then made to match again, so that the damage reaches the
// tree checks behind the CRC. Whatever readIndex accepts must be searched without a
// crash, a hang or a sanitizer report.
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "pmap/incore_store.h"

namespace {

using rp::pmap::InCoreStore;

constexpr size_t kPhotons = 3000;
const InCoreStore::IndexKey kKey{1, 2, 3};
const InCoreStore::Attributes kAttrs{true, true};  // every array: normals, flags, primaries

// Photons on two faces of a box and in a cluster, some stacked: leaves of every kind.
std::vector<rp::pmap::Photon> photons() {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<rp::pmap::Photon> v;
    for (size_t i = 0; i < kPhotons; ++i) {
        rp::Vec3 p, n;
        if (i % 3 == 0) {
            p = rp::Vec3(u(rng), u(rng), 0);
            n = rp::Vec3(0, 0, 1);
        } else if (i % 3 == 1) {
            p = rp::Vec3(u(rng), 0, u(rng));
            n = rp::Vec3(0, 1, 0);
        } else {
            p = rp::Vec3(0.5, 0.5, 0.5) + rp::Vec3(u(rng), u(rng), u(rng)) * (i % 7 ? 0.01 : 0);
            n = rp::normalize(rp::Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
        }
        v.push_back(rp::pmap::makePhoton(p, n, {1e-3, 2e-3, 3e-3}, i % 2 == 0, uint32_t(i)));
    }
    return v;
}

const std::string& validIndex() {
    static const std::string bytes = [] {
        const std::vector<rp::pmap::Photon> ph = photons();
        const InCoreStore store = InCoreStore::copyOf(ph, kAttrs, false);
        std::ostringstream out;
        store.writeIndex(out, kKey);
        return out.str();
    }();
    return bytes;
}

void search(const InCoreStore& store) {
    auto cursor = store.makeCursor();
    std::vector<rp::pmap::FoundPhoton> out;
    const rp::Vec3 up(0, 0, 1);
    for (int i = 0; i < 12; ++i) {
        const double t = i / 11.0;
        rp::pmap::PhotonQuery q{rp::Vec3(t, 0.5 * t, 0.5), i % 2 ? &up : nullptr, i % 4 == 3,
                                i < 6 ? 1e30f : 0.05f, size_t(1 + 17 * i)};
        q.causticExcluded = i % 5 == 1;
        if (i % 3 == 1 && q.normal) q.slab = 0.02f;
        store.findNearest(*cursor, q, out);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string b = validIndex();
    uint32_t headBytes;  // the head's size at byte 8, the body's CRC-32 in its last 4 bytes
    std::memcpy(&headBytes, b.data() + 8, 4);
    const size_t body = b.size() - headBytes;
    // Each three input bytes: a place in the body (16 bits, wrapped) and a byte XORed there.
    for (size_t i = 0; i + 3 <= size; i += 3) {
        const size_t at = (size_t(data[i]) | size_t(data[i + 1]) << 8) % body;
        b[headBytes + at] = char(b[headBytes + at] ^ char(data[i + 2]));
    }
    const uint32_t crc = static_cast<uint32_t>(
        crc32(crc32(0, nullptr, 0), reinterpret_cast<const Bytef*>(b.data() + headBytes),
              static_cast<uInt>(body)));
    std::memcpy(b.data() + headBytes - 4, &crc, 4);
    std::istringstream in(b);
    const std::optional<InCoreStore> store = InCoreStore::readIndex(in, kKey, kAttrs, kPhotons);
    if (store) search(*store);
    return 0;
}
