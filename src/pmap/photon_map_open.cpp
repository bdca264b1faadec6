// PhotonMap::open: a map file opened for searching, and the choice of its store (in core
// or out of core, photon_store.h StoreOptions). The choice is made here only.
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <ext/stdio_filebuf.h>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "pmap/incore_store.h"
#include "pmap/ooc_store.h"
#include "pmap/photon_map.h"
#include "pmap/photon_records.h"
#include "pmap/record_checksums.h"
#include "util/error.h"
#include "util/file_write.h"
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

// The photons of `primaries` whose source is marked in `tracked`; none (every photon)
// when every primary's source is (the records' primary indices are checked on reading).
std::function<bool(const Photon&)> trackedFilter(const std::vector<PhotonPrimary>& primaries,
                                                 const std::vector<bool>& tracked) {
    auto keep = std::make_shared<std::vector<bool>>(primaries.size());
    bool all = !primaries.empty();
    for (size_t i = 0; i < primaries.size(); ++i) {
        const int s = primaries[i].srcIdx;
        (*keep)[i] = s >= 0 && size_t(s) < tracked.size() && tracked[size_t(s)];
        all = all && (*keep)[i];
    }
    if (all) return {};
    return [keep](const Photon& p) { return p.primary < keep->size() && (*keep)[p.primary]; };
}

// A map's in-core store is kept beside it, in "<map>.rpindex" (InCoreStore::writeIndex),
// by the first run that builds it, and read back by later runs instead of building it
// again: the build sorts and lays out every photon, reading the index back is a copy
// (bench/README_speed.md). Only radphoton's own maps get one: the key is the map file's
// size and modification time with the CRC-32s of its prologue (header, statistics,
// primaries) and of the record checksums after the records, so a map changed in any way
// is never searched through an index of another. A folder that cannot be written gets no
// index, and a damaged one is built again: the index only ever saves time.
std::string indexPath(const std::string& mapPath) { return mapPath + ".rpindex"; }

// `fd`: the map file the store is built from (not its path, which another mkpmap may
// point at a new file meanwhile).
std::optional<InCoreStore::IndexKey> indexKey(int fd, uint64_t recordsStart,
                                              uint64_t trailerStart) {
    struct stat st;
    if (::fstat(fd, &st) != 0 || uint64_t(st.st_size) < trailerStart) return std::nullopt;
    auto crcOfRange = [&](uint64_t from, uint64_t to) -> std::optional<uint32_t> {
        std::vector<unsigned char> bytes(to - from);
        if (!preadFully(fd, from, bytes.data(), bytes.size())) return std::nullopt;
        return recordsChecksum(bytes.data(), bytes.size());
    };
    const std::optional<uint32_t> prologue = crcOfRange(0, recordsStart);
    const std::optional<uint32_t> trailer = crcOfRange(trailerStart, uint64_t(st.st_size));
    if (!prologue || !trailer) return std::nullopt;
    const uint64_t mtime = uint64_t(st.st_mtim.tv_sec) * 1000000000u + uint64_t(st.st_mtim.tv_nsec);
    return InCoreStore::IndexKey{uint64_t(st.st_size), mtime, uint64_t{*prologue} << 32 | *trailer};
}

std::shared_ptr<const InCoreStore> readStoreIndex(const std::string& mapPath,
                                                  const InCoreStore::IndexKey& key,
                                                  InCoreStore::Attributes attrs, uint64_t n) {
    std::ifstream in(indexPath(mapPath), std::ios::binary);
    if (!in) return nullptr;
    std::optional<InCoreStore> s = InCoreStore::readIndex(in, key, attrs, n);
    return s ? std::make_shared<const InCoreStore>(std::move(*s)) : nullptr;
}

void writeStoreIndex(const std::string& mapPath, const InCoreStore::IndexKey& key,
                     const InCoreStore& store) {
    try {
        AtomicFile file(indexPath(mapPath));
        AtomicFileBuf buf(file);
        std::ostream out(&buf);
        store.writeIndex(out, key);
        out.flush();
        buf.flush();
        if (out) file.commit(/*replace=*/true, /*sync=*/false);
    } catch (const InputError&) {
        // Not writable (a read-only folder, a full disk): the next run builds the store.
    }
}

}  // namespace

PhotonMap PhotonMap::open(const std::string& path, const StoreOptions& options,
                          const std::vector<bool>* trackedSources) {
    const SourceLoc loc{path, 0};
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        throw InputError(loc, fmt::format("can't open photon map file: {}", std::strerror(errno)));
    // The stream owns fd; the store's index is keyed through the same descriptor.
    __gnu_cxx::stdio_filebuf<char> file(fd, std::ios::in | std::ios::binary);
    std::istream in(&file);
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
    const InCoreStore::Attributes attrs = InCoreStore::attributesFor(map.type_);
    // The store kept beside the map (indexPath), when it is this map's; else it is built
    // below and kept for the next run.
    std::optional<InCoreStore::IndexKey> key;
    if (!keep && map.checksumBlock_ && n > 0) {
        const std::streampos records = in.tellg();
        if (records >= 0) {
            key = indexKey(fd, uint64_t(records), uint64_t(records) + n * kPhotonRecordSize);
            if (key)
                if (auto store = readStoreIndex(path, *key, attrs, n)) {
                    map.store_ = std::move(store);
                    return map;
                }
        }
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
    auto store = std::make_shared<InCoreStore>(records, attrs, true, /*consume=*/true);
    if (key) writeStoreIndex(path, *key, *store);
    map.store_ = std::move(store);
    return map;
}

}  // namespace rp::pmap
