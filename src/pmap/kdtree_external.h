// The kd-tree build for maps larger than memory (mkpmap beyond its -aC budget): the top
// levels by external median selection over temporary files, every part that fits the
// budget with the in-core build (kdtree.h), each node written to its heap position as
// soon as it is known. The photons of each subtree, and so the file, are the same as the
// in-core build's (ties broken by the whole record, kdtree_select.h). Writing the nodes
// is a HeapSink's job (map_file_writer.h for files).
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "pmap/photon.h"
#include "util/temp_file.h"

namespace rp::pmap {

// Receives a tree's photons by heap node (1-based; children of i at 2i and 2i + 1).
// write() may be called from several threads at once, for disjoint nodes.
class HeapSink {
public:
    virtual ~HeapSink() = default;
    // The photons of heap nodes first, first + 1, ..., first + photons.size() - 1.
    virtual void write(uint64_t first, std::span<const Photon> photons) = 0;
};

// Writes a tree in the in-order layout of buildKdTreeInOrder as the subtree rooted at heap
// node `root` of a larger tree (root 1: the whole tree). The subtree's nodes at depth j
// below the root are heap nodes root * 2^j onward, contiguous, so each level goes out in
// a few large writes (in parallel when `parallel`).
void writeSubtreeHeap(std::span<const Photon> inOrder, uint64_t root, HeapSink& sink,
                      bool parallel);

struct ExternalBuildSettings {
    uint64_t inCorePhotons = 0;  // parts of at most this many photons are built in memory
    std::string folder;          // where the parts' temporary files go
    std::string what;            // the map file, named in errors
    bool parallel = true;        // the in-memory parts' builds
};

// Builds the kd-tree of the n photons in `photons` (24-byte records in any order) in
// the cell lo / hi (their bounding box) and writes every node to `sink`. A part too large
// for memory is split at its median found by histogram passes over the 16-bit digits of
// its photons' sort keys (photonKeyWord), then one pass writing the photons below and
// above it to two new temporary files; each file is closed as soon as it is split or
// read, so the disk holds about twice the photons at most. Memory: inCorePhotons photons
// and a few buffers. Throws InputError (naming settings.what) on read or write errors.
void buildKdTreeExternal(TempFile photons, uint64_t n, const float lo[3], const float hi[3],
                         HeapSink& sink, const ExternalBuildSettings& settings);

}  // namespace rp::pmap
