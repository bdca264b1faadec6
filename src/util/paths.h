// Where radphoton finds its own data: the library of .cal files (rayinit.cal,
// skybright.cal, perezlum.cal) that RAYPATH falls back on.
#pragma once

#include <string>

namespace rp {

// $RADPHOTON_LIB if set and not empty, else the lib/ folder of the source tree the
// tools were built from (compiled in as RP_LIB_DIR).
std::string projectLibDir();

}  // namespace rp
