// The 27-byte photon record of RADIANCE "3.1k" map files (pmapkdt.c kdT_SavePhotons) and
// the messages for records that fail their checks, shared by the eager reader
// (photon_map_io.cpp), the out-of-core store (ooc_store.cpp) and the writers
// (photon_map_io.cpp, map_file_writer.cpp).
#pragma once

#include <cstddef>
#include <string>

#include "pmap/photon.h"
#include "util/portable_io.h"

namespace rp::pmap {

// pos 3 flt | norm 3 x 1 B | RGBE 4 x 1 B | primary 4 B | flags 1 B.
constexpr size_t kPhotonRecordSize = 3 * portable::kPortableFloatSize + 3 + 4 + 4 + 1;  // 27

// Writes the kPhotonRecordSize bytes of p at out.
void encodePhoton(unsigned char* out, const Photon& p);
// The photon in the kPhotonRecordSize bytes at b (no checks: see checkPhotonRecords).
Photon decodePhoton(const unsigned char* b);
// The n records at src decoded into dst (storage for n photons), in parallel. Isolated:
// a caller holding a lock must not pick up, while it waits, a task that would wait for it.
void decodePhotons(const unsigned char* src, size_t n, Photon* dst);

// "photons are not a valid kd-tree (<problem>); corrupt file?"
std::string treeProblem(const std::string& problem);

}  // namespace rp::pmap
