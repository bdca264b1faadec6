// A photon map file whose records are produced by heap node in any order (mkpmap's
// in-core and external kd-tree builds): the header and binary prologue first, each record
// then written at its heap position, and the file named only once complete (AtomicFile:
// a failed or killed run leaves nothing). PhotonMap::save is the same format for a map
// held in memory in heap order.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "pmap/kdtree_external.h"
#include "pmap/photon_map.h"
#include "util/file_write.h"

namespace rp::pmap {

class PhotonMapFileWriter final : public HeapSink {
public:
    // Starts the file for a map of info.stats.numPhotons photons. InputError if that is
    // 0, or `path` exists and !overwrite (mkpmap -fo), or the folder is not writable.
    PhotonMapFileWriter(const std::string& path, const PhotonMapFileInfo& info,
                        const std::string& commandLine, bool overwrite);
    // Encodes the photons of heap nodes first, first + 1, ... and writes them in place.
    // Thread-safe for disjoint nodes. InputError on a write error (disk full?).
    void write(uint64_t first, std::span<const Photon> photons) override;
    // Syncs the file and gives it its name (InputError if that fails).
    void commit();

private:
    std::string path_;
    bool overwrite_;
    AtomicFile file_;
    uint64_t recordsAt_ = 0;  // byte offset of heap node 1's record
    uint64_t numPhotons_ = 0;
};

}  // namespace rp::pmap
