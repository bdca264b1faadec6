// Photon map files: the reader with every check (header, sizes, records, kd-tree order,
// primaries), then the same bytes opened for searching in core and out of core (a tiny
// page cache, so that searches read pages) and searched around the map's photons with
// and without the normal and caustic filters. Damage must be an InputError, never a
// crash, a hang or a sanitizer report.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "pmap/photon_map.h"
#include "util/error.h"

namespace {

void search(const rp::pmap::PhotonMap& map) {
    const rp::pmap::PhotonStore& store = map.store();
    auto cursor = store.makeCursor();
    std::vector<rp::pmap::FoundPhoton> out;
    const rp::pmap::PhotonMapStats& s = map.stats();
    const rp::Vec3 up(0, 0, 1);
    for (int i = 0; i < 8; ++i) {
        const double t = i / 7.0;
        const rp::Vec3 q(s.bboxMin[0] + t * (s.bboxMax[0] - s.bboxMin[0]),
                         s.bboxMin[1] + t * (s.bboxMax[1] - s.bboxMin[1]),
                         s.bboxMin[2] + t * (s.bboxMax[2] - s.bboxMin[2]));
        const rp::pmap::PhotonQuery query{q, i % 2 ? &up : nullptr, i % 4 == 3,
                                          i < 4 ? 1e30f : s.cogDist2, size_t(1 + 20 * i)};
        store.findNearest(*cursor, query, out);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        std::istringstream in(bytes);
        (void)rp::pmap::PhotonMap::read(in, "fuzz.pm");
    } catch (const rp::InputError&) {
    }
    // The stores read files: the input goes to one (per process, reused).
    static const std::string path = "/tmp/fuzz_photon_map_" + std::to_string(::getpid()) + ".pm";
    if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
        std::fwrite(bytes.data(), 1, bytes.size(), f);
        std::fclose(f);
    }
    for (uint64_t cache : {uint64_t{0}, uint64_t{7}}) {
        try {
            rp::pmap::StoreOptions o;
            o.cachePhotons = cache;
            o.bandwidth = 2;
            const rp::pmap::PhotonMap map = rp::pmap::PhotonMap::open(path, o);
            search(map);
        } catch (const rp::InputError&) {
        }
    }
    return 0;
}
