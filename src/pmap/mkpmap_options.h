// mkpmap's command line (RADIANCE mkpmap.1 and photon-map manual 4.5): the map requests
// and regions its options name. The options struct (which holds the tracer's settings,
// so it lives beside runMkpmap) and its parser are in mkpmap.h. Checks that need the scene (sensor
// modifiers, ports, sources) and the run itself live in mkpmap.h; tracing in trace.h, distribution
// in distribute.h.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "light/light_sources.h"
#include "pmap/photon.h"
#include "util/color.h"
#include "util/vec.h"

namespace rp::pmap {

// One requested map: -apg/-apc/-apv/-apd/-app/-apC file nphotons [bwidth].
struct MapRequest {
    std::string file;
    uint64_t target = 0;     // nphotons
    int bandwidth = 0;       // -app; -apC's optional one (precomputed contributions)
    double compression = 0;  // -apC's optional comp, in [0, 1]
    // -apCPD: a contribution map that keeps where each primary left its source
    // (RADIANCE's 3.1kPD variant), so that rcontrib can bin photons by direction.
    bool primaryRays = false;
};

// -api box (xmin ymin zmin xmax ymax zmax).
struct RegionOfInterest {
    Vec3 min, max;
    bool contains(const Vec3& p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
               p.z <= max.z;
    }
};

// mkpmap -aC's default: half the physical memory, in 24-byte photons.
uint64_t defaultMemoryPhotons();

}  // namespace rp::pmap
