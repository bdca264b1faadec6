// A photon map: its type, photons in kd-tree order, the statistics RADIANCE keeps in the
// file header (photon count, average flux, bounding box, centre of gravity, mean squared
// distance to it), primaries for contribution maps, and RADIANCE "3.1k" file read/write.
// Density estimates and the adaptive search radius live in density.h.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pmap/kdtree.h"
#include "pmap/photon.h"
#include "pmap/photon_store.h"
#include "util/header.h"
#include "util/spectrum.h"

namespace rp::pmap {

// RADIANCE's file format version for in-core kd-tree maps with RGBE flux and plain
// primaries (pmapio.h PMAP_FILEVER); the only one we read and write so far.
constexpr const char* kPhotonMapFileVersion = "3.1k";
// RADIANCE's PMAP_CBDM build: primaries with position and direction.
constexpr const char* kPhotonMapFileVersionPD = "3.1kPD";

// "Radiance_<Type>_kdT_Photon_Map", the FORMAT= value RADIANCE writes for a kd-tree map.
std::string photonMapFormat(PhotonMapType type);

// Header statistics, with RADIANCE's precisions (PhotonMap in pmapdata.h): flux, bounding
// box and CoGdist are floats, the centre of gravity a double. We keep the CoG rounded to
// what the portable float encoding can hold, so that every field survives a file round trip
// bit for bit.
struct PhotonMapStats {
    uint64_t numPhotons = 0;
    std::array<float, 3> avgFlux = {0, 0, 0};  // mean photon flux [W], RGB
    std::array<float, 3> bboxMin = {0, 0, 0};
    std::array<float, 3> bboxMax = {0, 0, 0};
    std::array<double, 3> cog = {0, 0, 0};  // centre of gravity (mean photon position)
    // Mean SQUARED distance of photons to the CoG. RADIANCE calls it CoGdist and prints it
    // as "MaxDist^2" in the header; it sets the automatic maximum search radius.
    float cogDist2 = 0;

    bool operator==(const PhotonMapStats& o) const = default;
};

// What a map file holds besides its photon records (mkpmap writes files whose photons
// are not in a PhotonMap: pmap/map_file_writer.h).
// A spectral map set (mkpmap -cs above 3, issue 50): the scene rendered in passes of
// three bands (util/spectrum.h Pass), one 3.1k map file per pass, each holding its
// three bands as RGB flux; its header names the sampling (NCOMP=, WAVELENGTH_SPLITS=, as
// RADIANCE 6's spectral files) and the bands (BANDS= first last). The first pass's file
// is the one named; the others are "<name>.<first>-<last>" beside it (spectral::passFile).
struct MapBands {
    spectral::Sampling sampling;
    int first = 0;
    bool operator==(const MapBands&) const = default;
};
// The bands a pass's map holds; nullopt for RGB (a plain RADIANCE map).
std::optional<MapBands> mapBandsOf(const spectral::Pass& pass);
// InputError naming `file` unless a map's bands are the pass's: a spectral map rendered
// in RGB or another sampling, or an RGB map in spectral rendering.
void checkMapBands(const std::optional<MapBands>& bands, const spectral::Pass& pass,
                   const std::string& file);

struct PhotonMapFileInfo {
    PhotonMapType type = PhotonMapType::Global;
    PhotonMapStats stats;
    std::span<const PhotonPrimary> primaries;
    std::span<const PrimaryRay> primaryRays;  // 3.1kPD maps only
    // Records per checksum after the records (record_checksums.h); 0: none.
    uint32_t checksumBlock = 0;
    std::optional<MapBands> bands{};  // a pass of a spectral map set
    // "3.1k", or "3.1kPD" with primary rays.
    const char* fileVersion() const;
};

// The info header lines of a map file (PhotonMap::fileHeader).
Header photonMapFileHeader(const PhotonMapFileInfo& info, const std::string& commandLine);
// A map file's bytes before its photon records: the info header, the binary version,
// statistics and primaries. The records (photon_records.h) follow in heap order.
std::string photonMapFilePrologue(const PhotonMapFileInfo& info, const std::string& commandLine);

class PhotonMap {
public:
    PhotonMap() = default;

    // Builds a map from photons in any order: computes the statistics as RADIANCE's
    // buildPhotonMap (double sums) and reorders the photons into a kd-tree (in parallel when
    // `parallel`). Primaries are for contribution maps only; photon.primary indexes them.
    PhotonMap(PhotonMapType type, std::vector<Photon> photons,
              std::vector<PhotonPrimary> primaries = {}, bool parallel = true);

    PhotonMapType type() const { return type_; }
    // The bands of a spectral map set's file (nullopt: an RGB map).
    const std::optional<MapBands>& bands() const { return bands_; }
    size_t size() const { return stats_.numPhotons; }
    bool empty() const { return size() == 0; }
    // Photons in kd-tree (= file) order; empty for a map opened for searching (open()).
    std::span<const Photon> photons() const { return photons_; }

    // The search over the photons (photon_store.h): set by open(), or by makeSearchable()
    // for a map built or read in memory. RP_CHECKs that there is one.
    const PhotonStore& store() const;
    bool searchable() const { return store_ != nullptr; }
    // An in-core store over a copy of photons() (tests).
    void makeSearchable(bool parallel = true);
    // A map of `photons` (any order) for searching only: statistics and an in-core store
    // built from them, no kd-tree, photons() empty (mkpmap's precomputation).
    static PhotonMap searchableFrom(PhotonMapType type, std::vector<Photon> photons,
                                    bool parallel = true);
    const PhotonMapStats& stats() const { return stats_; }
    const std::vector<PhotonPrimary>& primaries() const { return primaries_; }
    // One per primary in maps of the 3.1kPD variant, else empty.
    const std::vector<PrimaryRay>& primaryRays() const { return primaryRays_; }
    void setPrimaryRays(std::vector<PrimaryRay> rays);

    // ---- Files (photon_map_io.cpp) ----

    // The info header lines RADIANCE 5.4 writes (after "#?RADIANCE", before the blank
    // line): the command line (skipped if empty), NumPhotons, AvgFlux, Bbox, CoG,
    // MaxDist^2, "<n> primary rays" (contrib maps with primaries), FORMAT, VERSION.
    Header fileHeader(const std::string& commandLine) const;
    // "3.1k", or "3.1kPD" for a map with primary rays.
    const char* fileVersion() const;
    // The map's file info (valid while the map lives).
    PhotonMapFileInfo fileInfo() const;

    // Writes the complete file (info header + portable binary part) to `out`.
    void write(std::ostream& out, const std::string& commandLine) const;

    // Saves to `path` via a temporary file in the same folder, renamed when complete.
    // Throws InputError if the map is empty, if `path` exists and !overwrite (mkpmap -fo),
    // or on any write error (the temporary file is removed).
    void save(const std::string& path, const std::string& commandLine, bool overwrite) const;

    // Reads a map from `in`, naming `what` (the file name) in errors. Validates header
    // FORMAT and VERSION, the binary version, that the photon count matches the number of
    // bytes that follow, split axes, finite positions, kd-tree order (unless
    // TreeOrder::Unchecked) and primary indices. Every problem is an InputError; no
    // allocation is made before the size has been checked.
    enum class TreeOrder { Checked, Unchecked };
    static PhotonMap read(std::istream& in, const std::string& what,
                          TreeOrder order = TreeOrder::Checked);
    static PhotonMap load(const std::string& path, TreeOrder order = TreeOrder::Checked);

    // Opens the map at `path` for searching (the renderer, rcontrib): header, statistics
    // and primaries as read() checks them, the photons into the store `options` choose
    // (photon_store.h StoreOptions; photon_map_open.cpp), with a message when a map is
    // searched out of core without -aC asking for it. With `trackedSources` (rcontrib), a
    // contribution map's photons from sources not marked there (by the primaries' source
    // index) are never found, as RADIANCE's lookups skip them; the statistics stay the
    // whole map's, as RADIANCE's do. photons() stays empty.
    static PhotonMap open(const std::string& path, const StoreOptions& options,
                          const std::vector<bool>* trackedSources = nullptr);
    // The kd-tree order check that read() skips with TreeOrder::Unchecked (a caller that
    // checks later); throws the same InputError naming `what`.
    void checkTreeOrder(const std::string& what) const;

private:
    // The file's header and binary statistics, up to the photon records (the stream is
    // left at the first one); the photon count is checked against the bytes that follow.
    static PhotonMap readPrologue(std::istream& in, const std::string& what);
    // The photon records that follow, decoded and checked (read()'s second half).
    void readPhotons(std::istream& in, const std::string& what, TreeOrder order);
    // Reads the checksums after the records and compares them with `computed`, the
    // records' own (InputError naming the first block that differs).
    void checkChecksums(std::istream& in, const std::string& what,
                        const std::vector<uint32_t>& computed) const;

    PhotonMapType type_ = PhotonMapType::Global;
    uint32_t checksumBlock_ = 0;  // the file's RP_CRC32 line (record_checksums.h)
    std::optional<MapBands> bands_;
    BulkVector<Photon> photons_;
    std::shared_ptr<const PhotonStore> store_;
    std::vector<PhotonPrimary> primaries_;
    std::vector<PrimaryRay> primaryRays_;
    PhotonMapStats stats_;
};

// Statistics of `photons` as RADIANCE's buildPhotonMap computes them: average of the
// decoded flux, bounding box, centre of gravity, mean squared distance to it.
PhotonMapStats computeStats(std::span<const Photon> photons);

// computeStats over photons that are not in memory at once (mkpmap's external build), in
// two passes: addFirst() every photon, then addSecond() the same photons in the same
// order (the mean squared distance needs the centre of gravity first), then stats().
// computeStats is this over one span: the same sums in the same order, the same numbers.
class StatsAccumulator {
public:
    StatsAccumulator();
    void addFirst(std::span<const Photon> photons);
    void addSecond(std::span<const Photon> photons);
    PhotonMapStats stats() const;

private:
    void finishFirst();

    PhotonMapStats s_;
    double flux_[3] = {0, 0, 0}, cog_[3] = {0, 0, 0};
    double dist2_ = 0;
    bool second_ = false;
};

}  // namespace rp::pmap
