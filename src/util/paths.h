// Where radphoton finds its own data: the library of .cal files (rayinit.cal,
// skybright.cal, perezlum.cal) that RAYPATH falls back on.
#pragma once

#include <string>

namespace rp {

// The first of: $RADPHOTON_LIB if set and not empty; the installed library
// <prefix>/lib/radphoton, found from the running executable's folder <prefix>/bin (so an
// installed or packaged copy works wherever it is put); the lib/ folder of the source
// tree the tools were built from (compiled in as RP_LIB_DIR), for tools run from their
// build folder.
std::string projectLibDir();

}  // namespace rp
