// A photon map: its type, photons in kd-tree order, the statistics RADIANCE keeps in the
// file header (photon count, average flux, bounding box, centre of gravity, mean squared
// distance to it), primaries for contribution maps, and RADIANCE "3.1k" file read/write.
// Density estimates and the adaptive search radius live in density.h.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "pmap/kdtree.h"
#include "pmap/photon.h"
#include "util/header.h"

namespace rp::pmap {

class OnDemandPhotons;

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
struct PhotonMapFileInfo {
    PhotonMapType type = PhotonMapType::Global;
    PhotonMapStats stats;
    std::span<const PhotonPrimary> primaries;
    std::span<const PrimaryRay> primaryRays;  // 3.1kPD maps only
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
    size_t size() const { return stats_.numPhotons; }
    bool empty() const { return size() == 0; }
    // Photons in kd-tree (= file) order. A map loaded on demand reads and checks the
    // photons no search has reached yet first (once; InputError if the file turns out to
    // be corrupt or truncated).
    std::span<const Photon> photons() const;

    // The kd-tree walk (kdtree.h findNearestPhotons), for maps loaded either way.
    size_t findNearest(const Vec3& pos, const Vec3* normal, float maxDist2,
                       std::span<PhotonHit> out) const;
    // Photon i, which findNearest must have returned (photons()[i] without reading the
    // rest of a map loaded on demand).
    const Photon& searchedPhoton(size_t i) const;
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
    // Unchecked is for callers that search the photons only through a PhotonIndex, which
    // does not depend on the file's order (the renderer): the order check is a walk over
    // every photon, a visible part of loading a map with one thread.
    enum class TreeOrder { Checked, Unchecked };
    static PhotonMap read(std::istream& in, const std::string& what,
                          TreeOrder order = TreeOrder::Checked);
    // With `causticOnDemand`, a caustic map's photons are read as searches reach them
    // (pmap/on_demand_photons.h), each checked then; the header, statistics and file size
    // are checked at once either way. For the renderer, which looks caustic maps up about
    // once per primary ray and may never need most of a million photons.
    static PhotonMap load(const std::string& path, TreeOrder order = TreeOrder::Checked,
                          bool causticOnDemand = false);
    // The kd-tree order check that read() skips with TreeOrder::Unchecked, for a map that
    // turns out to need it after all; throws the same InputError naming `what`.
    void checkTreeOrder(const std::string& what) const;

private:
    // The file's header and binary statistics, up to the photon records (the stream is
    // left at the first one); the photon count is checked against the bytes that follow.
    static PhotonMap readPrologue(std::istream& in, const std::string& what);
    // The photon records that follow, decoded and checked (read()'s second half).
    void readPhotons(std::istream& in, const std::string& what, TreeOrder order);

    PhotonMapType type_ = PhotonMapType::Global;
    BulkVector<Photon> photons_;
    std::shared_ptr<const OnDemandPhotons> onDemand_;  // set instead of photons_ on demand
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
