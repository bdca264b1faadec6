// PhotonMap::open: a map file opened for searching, and the choice of its store (in core
// or out of core, photon_store.h StoreOptions). The choice is made here only.
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>

#include "pmap/incore_store.h"
#include "pmap/ooc_store.h"
#include "pmap/photon_map.h"
#include "util/error.h"
#include "util/warnings.h"

namespace rp::pmap {

namespace {

// Bytes per photon while an in-core store is built: the map's 24-byte records, given back
// as the leaves are filled (incore_store.h).
constexpr uint64_t kInCoreBytesPerPhoton = sizeof(Photon);

uint64_t physicalMemory() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), size = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && size > 0 ? uint64_t(pages) * uint64_t(size) : uint64_t{1} << 32;
}

struct Placement {
    bool outOfCore = false;
    uint64_t cachePhotons = 0;  // resident, and per thread
    uint32_t pagePhotons = 1;
};

// Out of core when -aC was given and the map holds more photons than it, or when the
// in-core store would take more than the budget (then the cache uses the budget: the
// resident top of the tree and one cache per thread, each of this many photons).
Placement placeStore(const std::string& path, uint64_t n, const StoreOptions& o) {
    Placement p;
    const double page = std::max(1.0, std::round(o.pageSize * std::max(o.bandwidth, 1)));
    p.pagePhotons = static_cast<uint32_t>(std::min(page, 1e6));
    const uint64_t budget = o.memoryBudget ? o.memoryBudget : physicalMemory() / 2;
    if (o.cachePhotons) {
        p.outOfCore = n > o.cachePhotons;
        p.cachePhotons = o.cachePhotons;
        return p;
    }
    if (n * kInCoreBytesPerPhoton <= budget) return p;
    p.outOfCore = true;
    const uint64_t shares = uint64_t(std::max(o.threads, 1)) + 1;
    p.cachePhotons = std::max(kDefaultCachePhotons, budget / (sizeof(Photon) * shares));
    warn(fmt::format(
        "{}: {} photons need {:.1f} GB in memory, more than the budget of "
        "{:.1f} GB; searching the map out of core (-aC {})",
        path, n, double(n * kInCoreBytesPerPhoton) / 1e9, double(budget) / 1e9, p.cachePhotons));
    return p;
}

// The photons of `primaries` whose source is marked in `tracked`.
std::function<bool(const Photon&)> trackedFilter(const std::vector<PhotonPrimary>& primaries,
                                                 const std::vector<bool>& tracked) {
    auto keep = std::make_shared<std::vector<bool>>(primaries.size());
    for (size_t i = 0; i < primaries.size(); ++i) {
        const int s = primaries[i].srcIdx;
        (*keep)[i] = s >= 0 && size_t(s) < tracked.size() && tracked[size_t(s)];
    }
    return [keep](const Photon& p) { return p.primary < keep->size() && (*keep)[p.primary]; };
}

}  // namespace

PhotonMap PhotonMap::open(const std::string& path, const StoreOptions& options,
                          const std::vector<bool>* trackedSources) {
    const SourceLoc loc{path, 0};
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(loc, fmt::format("can't open photon map file: {}", std::strerror(errno)));
    PhotonMap map = readPrologue(in, path);
    const uint64_t n = map.stats_.numPhotons;
    std::function<bool(const Photon&)> keep;
    if (trackedSources && map.type_ == PhotonMapType::Contrib)
        keep = trackedFilter(map.primaries_, *trackedSources);
    const Placement place = placeStore(path, n, options);
    if (place.outOfCore) {
        const std::streampos records = in.tellg();
        if (records < 0 || !in) throw InputError(loc, "can't determine file size");
        OutOfCoreStore::Options o;
        o.residentPhotons = place.cachePhotons;
        o.cachePhotons = place.cachePhotons;
        o.pagePhotons = place.pagePhotons;
        o.keep = keep;
        o.numPrimaries = map.primaries_.size();
        o.checksumBlock = map.checksumBlock_;
        map.store_ = std::make_shared<OutOfCoreStore>(path, uint64_t(records), n, std::move(o));
        return map;
    }
    // The store searches by its own tree, not the file's, but a file whose order is broken
    // is damaged, and what else is wrong in it cannot be known: refused, as out of core
    // (and by pmapdump). Every record is checked too.
    map.readPhotons(in, path, TreeOrder::Checked);
    BulkVector<Photon> records = std::move(map.photons_);
    map.photons_ = {};
    if (keep) {
        size_t kept = 0;
        for (const Photon& p : records)
            if (keep(p)) records[kept++] = p;
        records.resize(kept);
    }
    map.store_ = std::make_shared<InCoreStore>(records, InCoreStore::attributesFor(map.type_), true,
                                               /*consume=*/true);
    return map;
}

}  // namespace rp::pmap
