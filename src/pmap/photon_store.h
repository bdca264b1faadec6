// The one photon search of radphoton: k nearest photons to a point within a radius, with
// the surface normal filter (none for volume photons) and, for contribution maps, a
// caustic-only filter. Every store answers it: in memory (incore_store.h) or out of core
// from the map file through a bounded page cache (ooc_store.h). Density estimates,
// bias compensation, precomputation and contribution lookups read only what a search
// returns (FoundPhoton); which store a map gets is decided when it is opened
// (PhotonMap::open, StoreOptions), and nothing outside src/pmap knows.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pmap/photon.h"
#include "util/colr.h"
#include "util/vec.h"

namespace rp::pmap {

// One photon a search found: its squared distance to the query and what the estimates
// need of it (16 bytes, copied out so that no store has to keep anything alive).
struct FoundPhoton {
    float dist2 = 0;
    Colr flux = {0, 0, 0, 0};    // RGBE, as stored
    int8_t norm[3] = {0, 0, 0};  // surface normal (incident direction for volume photons) x 127
    uint8_t flags = 0;           // Photon::flags (caustic bit)
    uint32_t primary = 0;        // index into the map's primaries (contribution maps)

    std::array<float, 3> fluxRgb() const { return colrToRgb(flux); }
    bool caustic() const { return (flags & Photon::kCausticBit) != 0; }
};
static_assert(sizeof(FoundPhoton) == 16);

struct PhotonQuery {
    Vec3 pos;
    const Vec3* normal = nullptr;  // normal filter (kNormalTolerance); null: none
    bool causticOnly = false;      // only photons with the caustic flag
    float maxDist2 = 0;            // photons at squared distance < maxDist2
    size_t k = 1;                  // at most this many
    // Only photons without the caustic flag (a precomputed contribution map's gather
    // lookups: its flagged photons hold caustic light alone).
    bool causticExcluded = false;
    // > 0 (with `normal`): only photons within this distance of the plane through `pos`
    // normal to it (-ape's estimate over the query's own surface, density.h).
    float slab = 0;
};

class PhotonStore {
public:
    virtual ~PhotonStore() = default;

    // A thread's search state: scratch buffers and, out of core, its page cache. One per
    // thread; never shared.
    class Cursor {
    public:
        virtual ~Cursor() = default;
    };
    virtual std::unique_ptr<Cursor> makeCursor() const = 0;

    // The k nearest photons passing the query's filters (fewer if the radius holds fewer)
    // in out[0..n), the furthest at out[0] and the others in no particular order; returns
    // n. `out` grows as needed. Stores differ only among photons at exactly the k-th
    // distance. A damaged part of a map file met by the search is an InputError naming
    // the file.
    virtual size_t findNearest(Cursor& cursor, const PhotonQuery& q,
                               std::vector<FoundPhoton>& out) const = 0;

    virtual uint64_t size() const = 0;
    // Bytes the store holds now (index, photons, resident pages; not per-thread caches).
    virtual size_t memoryBytes() const = 0;
    // "in core" or "out of core (...)", for messages.
    virtual std::string describe() const = 0;
};

// How PhotonMap::open chooses and sizes a store (rtrace's -ac/-aC; RADIANCE's out-of-core
// options, manual 3.2). A map is searched out of core when its in-core store would not fit
// memoryBudget bytes, or when cachePhotons is set and the map holds more photons than that.
struct StoreOptions {
    uint64_t cachePhotons = 0;  // -aC: photons cached per thread (and resident); 0 = unset
    double pageSize = 4;        // -ac: page size as a multiple of the bandwidth
    int bandwidth = 50;         // the largest bandwidth the map is looked up with
    int threads = 1;            // threads that will search (one page cache each)
    uint64_t memoryBudget = 0;  // bytes; 0 = half the physical memory
};

// RADIANCE compat (pmapparm.c): -aC's default, 1M photons.
constexpr uint64_t kDefaultCachePhotons = 1000000;

}  // namespace rp::pmap
