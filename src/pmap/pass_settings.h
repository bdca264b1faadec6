// The settings every photon pass of mkpmap shares (distribution, contribution photons,
// precomputation), parsed once into MkpmapOptions (mkpmap.h) and handed to each pass as
// this one struct. What differs per pass (targets, files, progress stream) stays in the
// pass's own settings.
#pragma once

#include <cstdint>

namespace rp::pmap {

struct PassSettings {
    double preDistrib = 0.25;  // -apD: prepass size as a fraction of the smallest target
                               // (contribution maps: of a source's share)
    int maxPrepass = 4;        // -apM: doublings of an empty prepass before giving up
    uint64_t seed = 0;         // -apr: every random stream derives from it (rng.h)
    int threads = 1;           // -n: the results do not depend on it
    int reportSeconds = 0;     // -t: seconds between progress reports (0 = none)
};

}  // namespace rp::pmap
