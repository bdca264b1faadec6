// mkpmap's last step for each map: header statistics, kd-tree and file, from photons in
// memory (built in place and written from the in-order layout: no second photon array) or
// spilled to a temporary file (statistics in two streaming passes, the external build).
// Both give the same file for the same photons. Collecting photons is distribute.h.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "pmap/photon_map.h"
#include "util/temp_file.h"

namespace rp::pmap {

// What is written besides the photons.
struct MapOutput {
    PhotonMapType type = PhotonMapType::Global;
    std::string file;
    std::string commandLine;                   // for the header
    bool overwrite = false;                    // -fo
    std::span<const PhotonPrimary> primaries;  // contribution maps
    std::span<const PrimaryRay> primaryRays;   // -apCPD
    bool parallel = true;
    std::optional<MapBands> bands;  // a pass of a spectral map set
};

// Statistics of `photons` (in collection order), then the kd-tree built in place (the
// photons are reordered) and the file. Returns the photon count. InputError for an empty
// map, an existing file without overwrite, a write error.
uint64_t saveMapInMemory(std::span<Photon> photons, const MapOutput& out);

// The same for n photons in `spilled` (24-byte records in collection order), building the
// tree externally with at most inCorePhotons photons in memory (kdtree_external.h).
uint64_t saveSpilledMap(TempFile spilled, uint64_t n, uint64_t inCorePhotons, const MapOutput& out);

}  // namespace rp::pmap
