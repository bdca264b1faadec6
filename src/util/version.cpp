#include "util/version.h"

// Made at build time by cmake/version.cmake (the commit may change between builds).
#include "rp_version.h"

namespace rp {

std::string softwareName() { return std::string("radphoton ") + RP_VERSION; }

std::string versionLine() {
    return std::string("RADIANCE ") + kRadianceLevel + " " + RP_COMMIT_DATE + " " + softwareName() +
           " (" + RP_COMMIT + ")";
}

}  // namespace rp
